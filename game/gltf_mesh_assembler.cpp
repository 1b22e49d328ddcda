#include "game/gltf_mesh_assembler.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "game/gltf_checks.hpp"

namespace game::gltf {

namespace fs = std::filesystem;

// The bytes of one accessor, checked to lie inside its buffer view and buffer.
struct AccessorBytes {
  const unsigned char* first = nullptr;
  std::size_t stride = 0;
  std::size_t count = 0;
  int componentType = 0;

  const unsigned char* element(std::size_t i) const { return first + i * stride; }
};

namespace {

// Guards against memory exhaustion from a hostile or broken asset.
constexpr std::size_t kMaxNodeVisits = 1u << 20;

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

}  // namespace

void MeshAssembler::appendMesh(int meshIndex, const glm::dmat4& transform) {
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

scene::MeshData MeshAssembler::finish(std::string name) {
  if (result_.indices.empty()) {
    if (dropped_ > 0) {
      fail(file_, "all " + std::to_string(dropped_) + " triangles are degenerate (zero area)");
    }
    fail(file_, "contains no triangles");
  }
  result_.name = std::move(name);
  if (materials_.size() <= 1) result_.triangleMaterials.clear();  // one material: none needed
  return std::move(result_);
}

void MeshAssembler::appendPrimitive(const tinygltf::Primitive& primitive,
                                    const glm::dmat4& transform, const std::string& label) {
  const auto known = std::find(materials_.begin(), materials_.end(), primitive.material);
  const auto localMaterial = static_cast<uint32_t>(known - materials_.begin());
  if (known == materials_.end()) materials_.push_back(primitive.material);
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

  // A second set for textures that ask for it; without one they read the first.
  std::vector<glm::vec2> secondUvs;
  if (const auto uvAttribute = primitive.attributes.find("TEXCOORD_1");
      uvAttribute != primitive.attributes.end()) {
    secondUvs = readUvs(uvAttribute->second, label + " TEXCOORD_1");
    expectOnePerPosition(secondUvs.size(), positions.size(), label, "second UVs");
  }

  std::vector<glm::vec4> colors;
  if (const auto colorAttribute = primitive.attributes.find("COLOR_0");
      colorAttribute != primitive.attributes.end()) {
    colors = readColors(colorAttribute->second, label + " COLOR_0");
    expectOnePerPosition(colors.size(), positions.size(), label, "colours");
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
    vertices[i].uv1 = secondUvs.empty() ? vertices[i].uv : secondUvs[i];
    if (!colors.empty()) vertices[i].color = colors[i];
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
  result_.triangleMaterials.insert(result_.triangleMaterials.end(), kept.size() / 3, localMaterial);
}

void MeshAssembler::expectOnePerPosition(std::size_t count, std::size_t positionCount,
                                         const std::string& label, const std::string& what) const {
  if (count != positionCount) {
    fail(file_, label + " has " + std::to_string(count) + " " + what + " for " +
                    std::to_string(positionCount) + " positions");
  }
}

// Summing unnormalised face normals weights each face by its area; a mesh without shared
// vertices ends up flat shaded.
void MeshAssembler::computeAreaWeightedNormals(std::vector<scene::Vertex>& vertices,
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

std::vector<uint32_t> MeshAssembler::sequentialIndices(std::size_t count,
                                                       const std::string& label) const {
  if (count > std::numeric_limits<uint32_t>::max()) fail(file_, label + " has too many vertices");
  std::vector<uint32_t> indices(count);
  for (std::size_t i = 0; i < count; ++i) indices[i] = static_cast<uint32_t>(i);
  return indices;
}

AccessorBytes MeshAssembler::locate(int accessorIndex, const std::string& label) const {
  if (!validIndex(accessorIndex, model_.accessors)) {
    fail(file_,
         label + " refers to accessor " + std::to_string(accessorIndex) + ", which does not exist");
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

const tinygltf::Accessor* MeshAssembler::accessorAt(int accessorIndex) const {
  return validIndex(accessorIndex, model_.accessors)
             ? &model_.accessors[static_cast<std::size_t>(accessorIndex)]
             : nullptr;
}

std::vector<glm::vec3> MeshAssembler::readVec3s(int accessorIndex, const std::string& label) const {
  const tinygltf::Accessor* accessor = accessorAt(accessorIndex);
  if (accessor && (accessor->type != TINYGLTF_TYPE_VEC3 ||
                   accessor->componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)) {
    fail(file_, label + " (accessor " + std::to_string(accessorIndex) + ") must hold VEC3 floats");
  }
  const AccessorBytes bytes = locate(accessorIndex, label);
  std::vector<glm::vec3> values(bytes.count);
  for (std::size_t i = 0; i < bytes.count; ++i) {
    std::memcpy(&values[i], bytes.element(i), sizeof(glm::vec3));  // glTF is little-endian
    if (!std::isfinite(values[i].x) || !std::isfinite(values[i].y) || !std::isfinite(values[i].z)) {
      fail(file_, label + " holds a value that is not a finite number");
    }
  }
  return values;
}

// glTF allows UVs as floats or as unsigned integers normalised to [0, 1].
std::vector<glm::vec2> MeshAssembler::readUvs(int accessorIndex, const std::string& label) const {
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

// COLOR_0: RGB or RGBA, floats or normalized unsigned bytes or shorts; linear, alpha 1 when
// absent.
std::vector<glm::vec4> MeshAssembler::readColors(int accessorIndex,
                                                 const std::string& label) const {
  const tinygltf::Accessor* accessor = accessorAt(accessorIndex);
  int components = 4;
  if (accessor) {
    const int type = accessor->componentType;
    const bool normalizedInteger =
        accessor->normalized && (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                 type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    if ((accessor->type != TINYGLTF_TYPE_VEC3 && accessor->type != TINYGLTF_TYPE_VEC4) ||
        (type != TINYGLTF_COMPONENT_TYPE_FLOAT && !normalizedInteger)) {
      fail(file_, label + " (accessor " + std::to_string(accessorIndex) +
                      ") must hold VEC3 or VEC4 floats or normalized unsigned bytes or shorts");
    }
    components = accessor->type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
  }
  const AccessorBytes bytes = locate(accessorIndex, label);
  std::vector<glm::vec4> values(bytes.count, glm::vec4(1.0f));
  for (std::size_t i = 0; i < bytes.count; ++i) {
    const unsigned char* element = bytes.element(i);
    for (int c = 0; c < components; ++c) {
      float value = 0.0f;
      if (bytes.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        std::memcpy(&value, element + 4 * c, sizeof value);
        if (!std::isfinite(value))
          fail(file_, label + " holds a value that is not a finite number");
      } else if (bytes.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
        value = float(element[c]) / 255.0f;
      } else {
        uint16_t component = 0;
        std::memcpy(&component, element + 2 * c, sizeof component);
        value = float(component) / 65535.0f;
      }
      values[i][c] = std::clamp(value, 0.0f, 1.0f);
    }
  }
  return values;
}

std::vector<uint32_t> MeshAssembler::readIndices(int accessorIndex,
                                                 const std::string& label) const {
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

}  // namespace game::gltf
