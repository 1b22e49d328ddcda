#include "game/gltf_mesh.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <span>
#include <vector>

#include <tiny_gltf.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "game/level_loader.hpp"
#include "game/texture_file.hpp"

namespace game {

namespace {

namespace fs = std::filesystem;

// Guards against memory exhaustion from a hostile or broken asset.
constexpr std::uintmax_t kMaxModelFileBytes = 256u << 20;
constexpr std::size_t kMaxNodeVisits = 1u << 20;
// Error messages list at most this many node or mesh names.
constexpr std::size_t kMaxListedNames = 20;

[[noreturn]] void fail(const fs::path& file, const std::string& problem) {
  throw LevelError(file.string() + ": " + problem);
}

// Confines tinygltf's file access to one directory tree. tinygltf only reads through these
// callbacks, so a path that escapes (via "..", an absolute URI or a symlink) is never opened.
struct FileAccessGuard {
  fs::path root;                     // weakly canonical
  std::vector<std::string> refused;  // paths outside `root` that tinygltf wanted
  std::vector<fs::path> read;        // every file read, in order, for reload watching

  bool allows(const std::string& path) const {
    std::error_code error;
    const fs::path resolved = fs::weakly_canonical(fs::path(path), error);
    if (error) return false;
    const fs::path relative = resolved.lexically_relative(root);
    return !relative.empty() && *relative.begin() != "..";
  }

  void refuse(const std::string& path) {
    if (std::find(refused.begin(), refused.end(), path) == refused.end()) refused.push_back(path);
  }
};

bool guardedFileExists(const std::string& path, void* userData) {
  auto& guard = *static_cast<FileAccessGuard*>(userData);
  std::error_code error;
  const bool exists = fs::is_regular_file(path, error);
  if (!guard.allows(path)) {
    // tinygltf also probes the working directory for missing files; only a file that really
    // exists out there means the model tried to reach outside.
    if (exists) guard.refuse(path);
    return false;
  }
  return exists;
}

// tinygltf's default would run wordexp on paths taken from the model; keep them literal.
std::string literalPath(const std::string& path, void*) {
  return path;
}

bool guardedReadFile(std::vector<unsigned char>* contents, std::string* error,
                     const std::string& path, void* userData) {
  auto& guard = *static_cast<FileAccessGuard*>(userData);
  if (!guard.allows(path)) {
    guard.refuse(path);
    if (error) *error = "outside the allowed directory";
    return false;
  }
  std::error_code sizeError;
  const std::uintmax_t size = fs::file_size(path, sizeError);
  if (sizeError || size > kMaxModelFileBytes) {
    if (error) *error = sizeError ? sizeError.message() : "file is larger than 256 MiB";
    return false;
  }
  std::ifstream stream(path, std::ios::binary);
  contents->resize(static_cast<std::size_t>(size));
  if (!stream ||
      !stream.read(reinterpret_cast<char*>(contents->data()), static_cast<std::streamsize>(size))) {
    if (error) *error = "cannot read file";
    return false;
  }
  const fs::path readPath = fs::path(path).lexically_normal();
  if (std::find(guard.read.begin(), guard.read.end(), readPath) == guard.read.end()) {
    guard.read.push_back(readPath);
  }
  return true;
}

bool refuseWrite(std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
  if (error) *error = "writing files is disabled";
  return false;
}

// Keeps each image's encoded bytes so that only the images the material uses get decoded, and
// by decodeTexture with its size limits. Images in buffer views are left for later: tinygltf
// hands them over without checking that the view lies inside its buffer.
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  if (image->bufferView >= 0) return true;
  image->image.assign(bytes, bytes + std::max(size, 0));
  image->as_is = true;
  return true;
}

std::string toLower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// tinygltf's messages end in newlines and may hold several lines; messages here are one line.
std::string oneLine(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  std::string joined;
  for (const char c : text) {
    if (c == '\n') {
      joined += "; ";
    } else if (c != '\r') {
      joined.push_back(c);
    }
  }
  return joined.empty() ? "unknown error" : joined;
}

template <typename Named>
std::string namesOf(const std::vector<Named>& items) {
  std::string names;
  const std::size_t listed = std::min(items.size(), kMaxListedNames);
  for (std::size_t i = 0; i < listed; ++i) {
    if (!names.empty()) names += ", ";
    names += items[i].name.empty() ? "(unnamed #" + std::to_string(i) + ")"
                                   : "\"" + items[i].name + "\"";
  }
  if (items.size() > listed) names += " and " + std::to_string(items.size() - listed) + " more";
  return names.empty() ? "none" : names;
}

std::size_t componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

std::size_t componentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    case TINYGLTF_TYPE_MAT2:
      return 4;
    case TINYGLTF_TYPE_MAT3:
      return 9;
    case TINYGLTF_TYPE_MAT4:
      return 16;
    default:
      return 0;
  }
}

std::string modeName(int mode) {
  static const char* const names[] = {"POINTS",    "LINES",          "LINE_LOOP",   "LINE_STRIP",
                                      "TRIANGLES", "TRIANGLE_STRIP", "TRIANGLE_FAN"};
  return mode >= 0 && mode <= 6 ? names[mode] : "unknown";
}

template <typename T>
bool validIndex(int index, const std::vector<T>& items) {
  return index >= 0 && static_cast<std::size_t>(index) < items.size();
}

// The bytes of one accessor, checked to lie inside its buffer view and buffer.
struct AccessorBytes {
  const unsigned char* first = nullptr;
  std::size_t stride = 0;
  std::size_t count = 0;
  int componentType = 0;

  const unsigned char* element(std::size_t i) const { return first + i * stride; }
};

glm::dmat4 localTransform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());
  glm::dmat4 transform(1.0);
  if (node.translation.size() == 3) {
    transform = glm::translate(transform, glm::make_vec3(node.translation.data()));
  }
  if (node.rotation.size() == 4) {
    const auto& r = node.rotation;  // glTF stores x, y, z, w
    transform *= glm::mat4_cast(glm::dquat(r[3], r[0], r[1], r[2]));
  }
  if (node.scale.size() == 3) transform = glm::scale(transform, glm::make_vec3(node.scale.data()));
  return transform;
}

glm::vec3 normalizedOrUp(const glm::vec3& v) {
  const float length = glm::length(v);
  return length > 0.0f && std::isfinite(length) ? v / length : glm::vec3(0, 1, 0);
}

// Zero area, judged in double precision relative to the edge lengths, so triangles whose
// corners coincide or lie on one line (up to float rounding) count while slim ones do not.
bool isDegenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::dvec3 edge1 = glm::dvec3(b) - glm::dvec3(a);
  const glm::dvec3 edge2 = glm::dvec3(c) - glm::dvec3(a);
  constexpr double kRelativeTolerance = 1e-7;  // about float's precision
  return glm::length(glm::cross(edge1, edge2)) <=
         kRelativeTolerance * glm::length(edge1) * glm::length(edge2);
}

class MeshAssembler {
 public:
  MeshAssembler(const tinygltf::Model& model, const fs::path& file) : model_(model), file_(file) {}

  void appendMesh(int meshIndex, const glm::dmat4& transform) {
    if (!validIndex(meshIndex, model_.meshes)) {
      fail(file_, "a node refers to mesh " + std::to_string(meshIndex) + ", which does not exist");
    }
    const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(meshIndex)];
    const std::string meshLabel =
        mesh.name.empty() ? "mesh " + std::to_string(meshIndex) : "mesh \"" + mesh.name + "\"";
    for (std::size_t i = 0; i < mesh.primitives.size(); ++i) {
      appendPrimitive(mesh.primitives[i], transform, meshLabel + " primitive " + std::to_string(i));
    }
  }

  // The material of the first primitive appended, -1 when it has none.
  int firstMaterial() const { return firstMaterial_.value_or(-1); }
  std::size_t droppedTriangles() const { return dropped_; }

  scene::MeshData finish(std::string name) {
    if (result_.indices.empty()) {
      if (dropped_ > 0) {
        fail(file_, "all " + std::to_string(dropped_) + " triangles are degenerate (zero area)");
      }
      fail(file_, "contains no triangles");
    }
    result_.name = std::move(name);
    return std::move(result_);
  }

 private:
  void appendPrimitive(const tinygltf::Primitive& primitive, const glm::dmat4& transform,
                       const std::string& label) {
    if (!firstMaterial_) firstMaterial_ = primitive.material;
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES) {
      fail(file_, label + " has mode " + std::to_string(mode) + " (" + modeName(mode) +
                      "); only TRIANGLES (4) is supported");
    }
    const auto positionAttribute = primitive.attributes.find("POSITION");
    if (positionAttribute == primitive.attributes.end()) {
      fail(file_, label + " has no POSITION attribute");
    }
    const std::vector<glm::vec3> positions =
        readVec3s(positionAttribute->second, label + " POSITION");

    std::vector<glm::vec3> normals;
    if (const auto normalAttribute = primitive.attributes.find("NORMAL");
        normalAttribute != primitive.attributes.end()) {
      normals = readVec3s(normalAttribute->second, label + " NORMAL");
      expectOnePerPosition(normals.size(), positions.size(), label, "normals");
    }

    std::vector<glm::vec2> uvs;
    if (const auto uvAttribute = primitive.attributes.find("TEXCOORD_0");
        uvAttribute != primitive.attributes.end()) {
      uvs = readUvs(uvAttribute->second, label + " TEXCOORD_0");
      expectOnePerPosition(uvs.size(), positions.size(), label, "UVs");
    }

    std::vector<uint32_t> indices = primitive.indices >= 0
                                        ? readIndices(primitive.indices, label + " indices")
                                        : sequentialIndices(positions.size(), label);
    if (indices.size() % 3 != 0) {
      fail(file_, label + " has " + std::to_string(indices.size()) +
                      " indices, which is not a multiple of 3");
    }
    for (std::size_t i = 0; i < indices.size(); ++i) {
      if (indices[i] >= positions.size()) {
        fail(file_, label + " index " + std::to_string(indices[i]) + " (at " + std::to_string(i) +
                        ") is out of range: the primitive has " + std::to_string(positions.size()) +
                        " vertices");
      }
    }

    // A mirroring transform turns counter-clockwise faces clockwise; swap two corners back.
    if (glm::determinant(glm::dmat3(transform)) < 0.0) {
      for (std::size_t i = 0; i < indices.size(); i += 3) std::swap(indices[i + 1], indices[i + 2]);
    }

    const glm::dmat3 normalTransform = glm::transpose(glm::inverse(glm::dmat3(transform)));
    std::vector<scene::Vertex> vertices(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
      vertices[i].position = glm::vec3(transform * glm::dvec4(glm::dvec3(positions[i]), 1.0));
      if (!normals.empty()) {
        vertices[i].normal = normalizedOrUp(glm::vec3(normalTransform * glm::dvec3(normals[i])));
      }
      if (!uvs.empty()) vertices[i].uv = uvs[i];
    }

    // Zero-area triangles have no normal and can never be hit; they only cost time.
    std::vector<uint32_t> kept;
    kept.reserve(indices.size());
    for (std::size_t i = 0; i < indices.size(); i += 3) {
      if (isDegenerate(vertices[indices[i]].position, vertices[indices[i + 1]].position,
                       vertices[indices[i + 2]].position)) {
        ++dropped_;
      } else {
        kept.insert(kept.end(), {indices[i], indices[i + 1], indices[i + 2]});
      }
    }
    if (normals.empty()) computeAreaWeightedNormals(vertices, kept);

    const std::size_t base = result_.vertices.size();
    if (base + vertices.size() > std::numeric_limits<uint32_t>::max()) {
      fail(file_, "has more vertices than 32-bit indices can address");
    }
    result_.vertices.insert(result_.vertices.end(), vertices.begin(), vertices.end());
    for (const uint32_t index : kept) {
      result_.indices.push_back(static_cast<uint32_t>(base + index));
    }
  }

  void expectOnePerPosition(std::size_t count, std::size_t positionCount, const std::string& label,
                            const std::string& what) const {
    if (count != positionCount) {
      fail(file_, label + " has " + std::to_string(count) + " " + what + " for " +
                      std::to_string(positionCount) + " positions");
    }
  }

  // Summing unnormalised face normals weights each face by its area; a mesh without shared
  // vertices ends up flat shaded.
  static void computeAreaWeightedNormals(std::vector<scene::Vertex>& vertices,
                                         const std::vector<uint32_t>& indices) {
    std::vector<glm::vec3> sums(vertices.size(), glm::vec3(0.0f));
    for (std::size_t i = 0; i < indices.size(); i += 3) {
      const glm::vec3& a = vertices[indices[i]].position;
      const glm::vec3& b = vertices[indices[i + 1]].position;
      const glm::vec3& c = vertices[indices[i + 2]].position;
      const glm::vec3 faceNormal = glm::cross(b - a, c - a);
      for (std::size_t corner = 0; corner < 3; ++corner) sums[indices[i + corner]] += faceNormal;
    }
    for (std::size_t i = 0; i < vertices.size(); ++i) vertices[i].normal = normalizedOrUp(sums[i]);
  }

  std::vector<uint32_t> sequentialIndices(std::size_t count, const std::string& label) const {
    if (count > std::numeric_limits<uint32_t>::max()) fail(file_, label + " has too many vertices");
    std::vector<uint32_t> indices(count);
    for (std::size_t i = 0; i < count; ++i) indices[i] = static_cast<uint32_t>(i);
    return indices;
  }

  AccessorBytes locate(int accessorIndex, const std::string& label) const {
    if (!validIndex(accessorIndex, model_.accessors)) {
      fail(file_, label + " refers to accessor " + std::to_string(accessorIndex) +
                      ", which does not exist");
    }
    const tinygltf::Accessor& accessor = model_.accessors[static_cast<std::size_t>(accessorIndex)];
    const std::string accessorLabel = label + " (accessor " + std::to_string(accessorIndex) + ")";
    if (accessor.sparse.isSparse) fail(file_, accessorLabel + " is sparse, which is not supported");
    if (!validIndex(accessor.bufferView, model_.bufferViews)) {
      fail(file_, accessorLabel + " has no valid buffer view");
    }
    const tinygltf::BufferView& view =
        model_.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
    if (!validIndex(view.buffer, model_.buffers)) {
      fail(file_, accessorLabel + " uses a buffer view without a valid buffer");
    }
    const std::vector<unsigned char>& buffer =
        model_.buffers[static_cast<std::size_t>(view.buffer)].data;
    const std::size_t elementSize =
        componentSize(accessor.componentType) * componentCount(accessor.type);
    const std::size_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
    if (elementSize == 0 || stride < elementSize) {
      fail(file_, accessorLabel + " has an invalid component type, type or byte stride");
    }

    // Checked in an order that cannot overflow: the view lies in the buffer, then the accessor's
    // elements lie in the view.
    const bool viewFits =
        view.byteOffset <= buffer.size() && view.byteLength <= buffer.size() - view.byteOffset;
    const bool accessorFits =
        accessor.count == 0 ||
        (accessor.byteOffset <= view.byteLength &&
         accessor.count - 1 <= (view.byteLength - accessor.byteOffset) / stride &&
         (accessor.count - 1) * stride + elementSize <= view.byteLength - accessor.byteOffset);
    if (!viewFits || !accessorFits) {
      fail(file_, accessorLabel + " reads past the end of its buffer");
    }
    return {buffer.data() + view.byteOffset + accessor.byteOffset, stride, accessor.count,
            accessor.componentType};
  }

  const tinygltf::Accessor* accessorAt(int accessorIndex) const {
    return validIndex(accessorIndex, model_.accessors)
               ? &model_.accessors[static_cast<std::size_t>(accessorIndex)]
               : nullptr;
  }

  std::vector<glm::vec3> readVec3s(int accessorIndex, const std::string& label) const {
    const tinygltf::Accessor* accessor = accessorAt(accessorIndex);
    if (accessor && (accessor->type != TINYGLTF_TYPE_VEC3 ||
                     accessor->componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)) {
      fail(file_,
           label + " (accessor " + std::to_string(accessorIndex) + ") must hold VEC3 floats");
    }
    const AccessorBytes bytes = locate(accessorIndex, label);
    std::vector<glm::vec3> values(bytes.count);
    for (std::size_t i = 0; i < bytes.count; ++i) {
      std::memcpy(&values[i], bytes.element(i), sizeof(glm::vec3));  // glTF is little-endian
      if (!std::isfinite(values[i].x) || !std::isfinite(values[i].y) ||
          !std::isfinite(values[i].z)) {
        fail(file_, label + " holds a value that is not a finite number");
      }
    }
    return values;
  }

  // glTF allows UVs as floats or as unsigned integers normalised to [0, 1].
  std::vector<glm::vec2> readUvs(int accessorIndex, const std::string& label) const {
    const tinygltf::Accessor* accessor = accessorAt(accessorIndex);
    if (accessor) {
      const int type = accessor->componentType;
      const bool normalizedInteger =
          accessor->normalized && (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                   type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
      if (accessor->type != TINYGLTF_TYPE_VEC2 ||
          (type != TINYGLTF_COMPONENT_TYPE_FLOAT && !normalizedInteger)) {
        fail(file_, label + " (accessor " + std::to_string(accessorIndex) +
                        ") must hold VEC2 floats or normalized unsigned bytes or shorts");
      }
    }
    const AccessorBytes bytes = locate(accessorIndex, label);
    std::vector<glm::vec2> values(bytes.count);
    for (std::size_t i = 0; i < bytes.count; ++i) {
      const unsigned char* element = bytes.element(i);
      switch (bytes.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
          std::memcpy(&values[i], element, sizeof(glm::vec2));
          if (!std::isfinite(values[i].x) || !std::isfinite(values[i].y)) {
            fail(file_, label + " holds a value that is not a finite number");
          }
          break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
          values[i] = glm::vec2(element[0], element[1]) / 255.0f;
          break;
        default: {
          uint16_t pair[2];
          std::memcpy(pair, element, sizeof pair);
          values[i] = glm::vec2(pair[0], pair[1]) / 65535.0f;
          break;
        }
      }
    }
    return values;
  }

  std::vector<uint32_t> readIndices(int accessorIndex, const std::string& label) const {
    const AccessorBytes bytes = locate(accessorIndex, label);
    const tinygltf::Accessor& accessor = model_.accessors[static_cast<std::size_t>(accessorIndex)];
    if (accessor.type != TINYGLTF_TYPE_SCALAR) fail(file_, label + " must be scalars");
    std::vector<uint32_t> indices(bytes.count);
    for (std::size_t i = 0; i < bytes.count; ++i) {
      const unsigned char* element = bytes.element(i);
      switch (bytes.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
          indices[i] = element[0];
          break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
          uint16_t value;
          std::memcpy(&value, element, sizeof value);
          indices[i] = value;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
          std::memcpy(&indices[i], element, sizeof(uint32_t));
          break;
        default:
          fail(file_, label + " must be unsigned bytes, shorts or ints (component type " +
                          std::to_string(bytes.componentType) + ")");
      }
    }
    return indices;
  }

  const tinygltf::Model& model_;
  const fs::path& file_;
  scene::MeshData result_;
  std::optional<int> firstMaterial_;
  std::size_t dropped_ = 0;
};

// Appends the meshes of `rootNode` and its descendants, depth first in document order.
void appendSubtree(const tinygltf::Model& model, const fs::path& file, int rootNode,
                   const glm::dmat4& parentTransform, MeshAssembler& assembler,
                   std::size_t& visits) {
  struct PendingNode {
    int index;
    glm::dmat4 parentTransform;
    std::size_t depth;
  };
  std::vector<PendingNode> pending{{rootNode, parentTransform, 0}};
  while (!pending.empty()) {
    const PendingNode current = pending.back();
    pending.pop_back();
    if (!validIndex(current.index, model.nodes)) {
      fail(file, "refers to node " + std::to_string(current.index) + ", which does not exist");
    }
    // A tree cannot be deeper than its node count; deeper means the children form a cycle.
    if (current.depth > model.nodes.size() || ++visits > kMaxNodeVisits) {
      fail(file, "the node hierarchy contains a cycle or is too large");
    }
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(current.index)];
    const glm::dmat4 transform = current.parentTransform * localTransform(node);
    if (node.mesh >= 0) assembler.appendMesh(node.mesh, transform);
    // Pushed in reverse so the first child is taken next.
    for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
      pending.push_back({*child, transform, current.depth + 1});
    }
  }
}

void appendScene(const tinygltf::Model& model, const fs::path& file, MeshAssembler& assembler) {
  const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (!validIndex(sceneIndex, model.scenes)) {
    fail(file, "the default scene " + std::to_string(sceneIndex) + " does not exist");
  }
  std::size_t visits = 0;
  for (const int root : model.scenes[static_cast<std::size_t>(sceneIndex)].nodes) {
    appendSubtree(model, file, root, glm::dmat4(1.0), assembler, visits);
  }
}

// The product of the transforms of `nodeIndex`'s ancestors: where the scene puts the node.
glm::dmat4 ancestorTransform(const tinygltf::Model& model, const fs::path& file, int nodeIndex) {
  std::vector<int> parentOf(model.nodes.size(), -1);
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    for (const int child : model.nodes[i].children) {
      if (validIndex(child, model.nodes) && parentOf[static_cast<std::size_t>(child)] < 0) {
        parentOf[static_cast<std::size_t>(child)] = static_cast<int>(i);
      }
    }
  }
  glm::dmat4 transform(1.0);
  std::size_t steps = 0;
  for (int parent = parentOf[static_cast<std::size_t>(nodeIndex)]; parent >= 0;
       parent = parentOf[static_cast<std::size_t>(parent)]) {
    if (++steps > model.nodes.size()) fail(file, "the node hierarchy contains a cycle");
    transform = localTransform(model.nodes[static_cast<std::size_t>(parent)]) * transform;
  }
  return transform;
}

// Maps glTF's metallic-roughness material onto ours and decodes the textures it uses.
class MaterialMapper {
 public:
  MaterialMapper(const tinygltf::Model& model, const fs::path& file,
                 std::vector<std::string>& warnings)
      : model_(model), file_(file), warnings_(warnings) {}

  GltfMaterial map(int materialIndex) {
    const tinygltf::Material& material = model_.materials[static_cast<std::size_t>(materialIndex)];
    label_ = material.name.empty() ? "material " + std::to_string(materialIndex)
                                   : "material \"" + material.name + "\"";
    const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
    GltfMaterial result;
    result.baseColor = factors<3>(pbr.baseColorFactor, "baseColorFactor", result.baseColor);
    result.roughness = factor(pbr.roughnessFactor, "roughnessFactor");
    result.specular = 0.04f + 0.96f * factor(pbr.metallicFactor, "metallicFactor");
    result.emissive = factors<3>(material.emissiveFactor, "emissiveFactor", result.emissive);
    if (pbr.baseColorTexture.index >= 0) {
      result.colorTexture =
          texture(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, "baseColorTexture",
                  /*srgb=*/true);
    }
    if (material.normalTexture.index >= 0) {
      result.normalTexture = texture(material.normalTexture.index, material.normalTexture.texCoord,
                                     "normalTexture", /*srgb=*/false);
    }
    return result;
  }

 private:
  // glTF factors lie in [0, 1]; values outside are clamped rather than refused, as viewers do.
  float factor(double value, const std::string& name) const {
    if (!std::isfinite(value)) fail(file_, label_ + " " + name + " is not a finite number");
    return static_cast<float>(std::clamp(value, 0.0, 1.0));
  }

  template <int N>
  glm::vec<N, float> factors(const std::vector<double>& values, const std::string& name,
                             const glm::vec<N, float>& fallback) const {
    if (values.empty()) return fallback;
    if (values.size() < N) fail(file_, label_ + " " + name + " has too few components");
    glm::vec<N, float> result;
    for (int i = 0; i < N; ++i) result[i] = factor(values[static_cast<std::size_t>(i)], name);
    return result;
  }

  scene::TextureDesc texture(int textureIndex, int texCoord, const std::string& role, bool srgb) {
    const std::string where = label_ + " " + role;
    if (!validIndex(textureIndex, model_.textures)) {
      fail(file_,
           where + " refers to texture " + std::to_string(textureIndex) + ", which does not exist");
    }
    const int imageIndex = model_.textures[static_cast<std::size_t>(textureIndex)].source;
    if (!validIndex(imageIndex, model_.images)) {
      fail(file_, where + " uses texture " + std::to_string(textureIndex) +
                      ", which has no PNG or JPEG image");
    }
    if (texCoord != 0) {
      warnings_.push_back(file_.string() + ": " + where + " uses TEXCOORD_" +
                          std::to_string(texCoord) + "; only TEXCOORD_0 is read, so it is used");
    }
    const tinygltf::Image& image = model_.images[static_cast<std::size_t>(imageIndex)];
    const std::string imageLabel =
        "image " + std::to_string(imageIndex) + (image.uri.empty() ? "" : " \"" + image.uri + "\"");
    // An external image is named by its path; an embedded one by the model and its index.
    const std::string name = image.uri.empty()
                                 ? file_.string() + " image " + std::to_string(imageIndex)
                                 : (file_.parent_path() / image.uri).lexically_normal().string();
    const std::span<const uint8_t> bytes = encodedBytes(image, where + " " + imageLabel);
    try {
      return decodeTexture(bytes, name, srgb);
    } catch (const LevelError& error) {
      fail(file_, where + ": " + error.what());
    }
  }

  std::span<const uint8_t> encodedBytes(const tinygltf::Image& image,
                                        const std::string& label) const {
    if (image.bufferView < 0) {
      if (image.image.empty()) fail(file_, label + " was not found or could not be read");
      return image.image;
    }
    if (!validIndex(image.bufferView, model_.bufferViews)) {
      fail(file_, label + " has no valid buffer view");
    }
    const tinygltf::BufferView& view =
        model_.bufferViews[static_cast<std::size_t>(image.bufferView)];
    if (!validIndex(view.buffer, model_.buffers)) {
      fail(file_, label + " uses a buffer view without a valid buffer");
    }
    const std::vector<unsigned char>& buffer =
        model_.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset) {
      fail(file_, label + " reads past the end of its buffer");
    }
    return {buffer.data() + view.byteOffset, view.byteLength};
  }

  const tinygltf::Model& model_;
  const fs::path& file_;
  std::vector<std::string>& warnings_;
  std::string label_;  // names the material in messages
};

}  // namespace

GltfModel loadGltfModel(const fs::path& file, const fs::path& allowedRoot,
                        const GltfSelection& selection) {
  const std::string extension = toLower(file.extension().string());
  if (extension != ".gltf" && extension != ".glb") {
    fail(file, "expected a .gltf or .glb file");
  }
  if (!selection.node.empty() && !selection.mesh.empty()) {
    fail(file, "select a node or a mesh, not both");
  }
  FileAccessGuard guard;
  std::error_code error;
  guard.root = fs::weakly_canonical(allowedRoot, error);
  if (error) fail(file, "cannot resolve the directory " + allowedRoot.string());
  if (!fs::is_regular_file(file, error)) fail(file, "cannot open glTF file");
  if (!guard.allows(file.string())) {
    fail(file, "is outside the directory " + allowedRoot.string());
  }

  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&keepEncodedImage, nullptr);
  loader.SetFsCallbacks({&guardedFileExists, &literalPath, &guardedReadFile, &refuseWrite, &guard});

  tinygltf::Model model;
  std::string loadError, loadWarning;
  bool loaded = false;
  try {
    loaded = extension == ".glb"
                 ? loader.LoadBinaryFromFile(&model, &loadError, &loadWarning, file.string())
                 : loader.LoadASCIIFromFile(&model, &loadError, &loadWarning, file.string());
  } catch (const std::exception& exception) {
    fail(file, std::string("cannot load glTF: ") + exception.what());
  }
  if (!guard.refused.empty()) {
    fail(file, "refers to \"" + guard.refused.front() +
                   "\", which is outside the directory the model was found in (" +
                   guard.root.string() + ")");
  }
  if (!loaded) fail(file, "cannot load glTF: " + oneLine(loadError));

  GltfModel result;
  MeshAssembler assembler(model, file);
  std::string meshName = file.stem().string();
  if (!selection.mesh.empty()) {
    const auto found =
        std::find_if(model.meshes.begin(), model.meshes.end(),
                     [&](const tinygltf::Mesh& mesh) { return mesh.name == selection.mesh; });
    if (found == model.meshes.end()) {
      fail(file, "has no mesh named \"" + selection.mesh +
                     "\"; its meshes are: " + namesOf(model.meshes));
    }
    assembler.appendMesh(static_cast<int>(found - model.meshes.begin()), glm::dmat4(1.0));
    meshName = selection.mesh;
  } else if (!selection.node.empty()) {
    const auto found =
        std::find_if(model.nodes.begin(), model.nodes.end(),
                     [&](const tinygltf::Node& node) { return node.name == selection.node; });
    if (found == model.nodes.end()) {
      fail(file,
           "has no node named \"" + selection.node + "\"; its nodes are: " + namesOf(model.nodes));
    }
    const int nodeIndex = static_cast<int>(found - model.nodes.begin());
    std::size_t visits = 0;
    appendSubtree(model, file, nodeIndex, ancestorTransform(model, file, nodeIndex), assembler,
                  visits);
    meshName = selection.node;
  } else if (model.scenes.empty()) {
    for (std::size_t i = 0; i < model.meshes.size(); ++i) {
      assembler.appendMesh(static_cast<int>(i), glm::dmat4(1.0));
    }
  } else {
    appendScene(model, file, assembler);
  }
  result.mesh = assembler.finish(meshName);
  if (assembler.droppedTriangles() > 0) {
    result.warnings.push_back(file.string() + ": dropped " +
                              std::to_string(assembler.droppedTriangles()) +
                              " degenerate triangles");
  }

  if (const int materialIndex = assembler.firstMaterial(); materialIndex >= 0) {
    if (!validIndex(materialIndex, model.materials)) {
      fail(file, "refers to material " + std::to_string(materialIndex) + ", which does not exist");
    }
    result.material = MaterialMapper(model, file, result.warnings).map(materialIndex);
  }

  // The model first, as given, then each buffer and image file in the order tinygltf read them.
  result.filesRead.push_back(file);
  const fs::path normalizedModel = file.lexically_normal();
  for (const fs::path& read : guard.read) {
    if (read != normalizedModel) result.filesRead.push_back(read);
  }
  return result;
}

scene::MeshData loadGltfMesh(const fs::path& file, const fs::path& allowedRoot,
                             const std::string& meshName) {
  GltfSelection selection;
  selection.mesh = meshName;
  return loadGltfModel(file, allowedRoot, selection).mesh;
}

}  // namespace game
