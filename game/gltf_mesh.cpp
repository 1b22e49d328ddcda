#include "game/gltf_mesh.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

#include <tiny_gltf.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "game/level_loader.hpp"

namespace game {

namespace {

namespace fs = std::filesystem;

// Guards against memory exhaustion from a hostile or broken asset.
constexpr std::uintmax_t kMaxModelFileBytes = 256u << 20;
constexpr std::size_t kMaxNodeVisits = 1u << 20;

[[noreturn]] void fail(const fs::path& file, const std::string& problem) {
  throw LevelError(file.string() + ": " + problem);
}

// Confines tinygltf's file access to one directory tree. tinygltf only reads through these
// callbacks, so a path that escapes (via "..", an absolute URI or a symlink) is never opened.
struct FileAccessGuard {
  fs::path root;                     // weakly canonical
  std::vector<std::string> refused;  // paths outside `root` that tinygltf wanted

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
  return true;
}

bool refuseWrite(std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
  if (error) *error = "writing files is disabled";
  return false;
}

// Only geometry is used, so images are accepted without being decoded.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
               const unsigned char*, int, void*) {
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

class MeshAssembler {
 public:
  MeshAssembler(const tinygltf::Model& model, const fs::path& file) : model_(model), file_(file) {}

  void appendMesh(int meshIndex, const glm::dmat4& transform) {
    if (meshIndex < 0 || static_cast<std::size_t>(meshIndex) >= model_.meshes.size()) {
      fail(file_, "a node refers to mesh " + std::to_string(meshIndex) + ", which does not exist");
    }
    const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(meshIndex)];
    const std::string meshLabel =
        mesh.name.empty() ? "mesh " + std::to_string(meshIndex) : "mesh \"" + mesh.name + "\"";
    for (std::size_t i = 0; i < mesh.primitives.size(); ++i) {
      appendPrimitive(mesh.primitives[i], transform, meshLabel + " primitive " + std::to_string(i));
    }
  }

  render::MeshData finish(std::string name) {
    if (result_.indices.empty()) fail(file_, "contains no triangles");
    result_.name = std::move(name);
    return std::move(result_);
  }

 private:
  void appendPrimitive(const tinygltf::Primitive& primitive, const glm::dmat4& transform,
                       const std::string& label) {
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
      if (normals.size() != positions.size()) {
        fail(file_, label + " has " + std::to_string(normals.size()) + " normals for " +
                        std::to_string(positions.size()) + " positions");
      }
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
    std::vector<render::Vertex> vertices(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
      vertices[i].position = glm::vec3(transform * glm::dvec4(glm::dvec3(positions[i]), 1.0));
      if (!normals.empty()) {
        vertices[i].normal = normalizedOrUp(glm::vec3(normalTransform * glm::dvec3(normals[i])));
      }
    }
    if (normals.empty()) computeAreaWeightedNormals(vertices, indices);

    const std::size_t base = result_.vertices.size();
    if (base + vertices.size() > std::numeric_limits<uint32_t>::max()) {
      fail(file_, "has more vertices than 32-bit indices can address");
    }
    result_.vertices.insert(result_.vertices.end(), vertices.begin(), vertices.end());
    for (const uint32_t index : indices) {
      result_.indices.push_back(static_cast<uint32_t>(base + index));
    }
  }

  static glm::vec3 normalizedOrUp(const glm::vec3& v) {
    const float length = glm::length(v);
    return length > 0.0f && std::isfinite(length) ? v / length : glm::vec3(0, 1, 0);
  }

  // Summing unnormalised face normals weights each face by its area; a mesh without shared
  // vertices ends up flat shaded.
  static void computeAreaWeightedNormals(std::vector<render::Vertex>& vertices,
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
    if (accessorIndex < 0 || static_cast<std::size_t>(accessorIndex) >= model_.accessors.size()) {
      fail(file_, label + " refers to accessor " + std::to_string(accessorIndex) +
                      ", which does not exist");
    }
    const tinygltf::Accessor& accessor = model_.accessors[static_cast<std::size_t>(accessorIndex)];
    const std::string accessorLabel = label + " (accessor " + std::to_string(accessorIndex) + ")";
    if (accessor.sparse.isSparse) fail(file_, accessorLabel + " is sparse, which is not supported");
    if (accessor.bufferView < 0 ||
        static_cast<std::size_t>(accessor.bufferView) >= model_.bufferViews.size()) {
      fail(file_, accessorLabel + " has no valid buffer view");
    }
    const tinygltf::BufferView& view =
        model_.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size()) {
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

  std::vector<glm::vec3> readVec3s(int accessorIndex, const std::string& label) const {
    const tinygltf::Accessor* accessor =
        accessorIndex >= 0 && static_cast<std::size_t>(accessorIndex) < model_.accessors.size()
            ? &model_.accessors[static_cast<std::size_t>(accessorIndex)]
            : nullptr;
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
  render::MeshData result_;
};

std::string meshNamesOf(const tinygltf::Model& model) {
  std::string names;
  for (std::size_t i = 0; i < model.meshes.size(); ++i) {
    if (!names.empty()) names += ", ";
    names += model.meshes[i].name.empty() ? "(unnamed #" + std::to_string(i) + ")"
                                          : "\"" + model.meshes[i].name + "\"";
  }
  return names.empty() ? "none" : names;
}

void appendScene(const tinygltf::Model& model, const fs::path& file, MeshAssembler& assembler) {
  const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (static_cast<std::size_t>(sceneIndex) >= model.scenes.size()) {
    fail(file, "the default scene " + std::to_string(sceneIndex) + " does not exist");
  }
  struct PendingNode {
    int index;
    glm::dmat4 parentTransform;
    std::size_t depth;
  };
  std::vector<PendingNode> pending;
  for (const int root : model.scenes[static_cast<std::size_t>(sceneIndex)].nodes) {
    pending.push_back({root, glm::dmat4(1.0), 0});
  }
  std::size_t visits = 0;
  while (!pending.empty()) {
    const PendingNode current = pending.back();
    pending.pop_back();
    if (current.index < 0 || static_cast<std::size_t>(current.index) >= model.nodes.size()) {
      fail(file, "refers to node " + std::to_string(current.index) + ", which does not exist");
    }
    // A tree cannot be deeper than its node count; deeper means the children form a cycle.
    if (current.depth > model.nodes.size() || ++visits > kMaxNodeVisits) {
      fail(file, "the node hierarchy contains a cycle or is too large");
    }
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(current.index)];
    const glm::dmat4 transform = current.parentTransform * localTransform(node);
    if (node.mesh >= 0) assembler.appendMesh(node.mesh, transform);
    for (const int child : node.children) pending.push_back({child, transform, current.depth + 1});
  }
}

}  // namespace

render::MeshData loadGltfMesh(const fs::path& file, const fs::path& allowedRoot,
                              const std::string& meshName) {
  const std::string extension = toLower(file.extension().string());
  if (extension != ".gltf" && extension != ".glb") {
    fail(file, "expected a .gltf or .glb file");
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
  loader.SetImageLoader(&skipImage, nullptr);
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

  MeshAssembler assembler(model, file);
  if (!meshName.empty()) {
    const auto found =
        std::find_if(model.meshes.begin(), model.meshes.end(),
                     [&](const tinygltf::Mesh& mesh) { return mesh.name == meshName; });
    if (found == model.meshes.end()) {
      fail(file, "has no mesh named \"" + meshName + "\"; its meshes are: " + meshNamesOf(model));
    }
    assembler.appendMesh(static_cast<int>(found - model.meshes.begin()), glm::dmat4(1.0));
    return assembler.finish(meshName);
  }
  if (model.scenes.empty()) {
    for (std::size_t i = 0; i < model.meshes.size(); ++i) {
      assembler.appendMesh(static_cast<int>(i), glm::dmat4(1.0));
    }
  } else {
    appendScene(model, file, assembler);
  }
  return assembler.finish(file.stem().string());
}

}  // namespace game
