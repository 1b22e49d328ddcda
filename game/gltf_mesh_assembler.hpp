#pragma once
// Reads a glTF model's meshes into one scene::MeshData: accessors, node transforms, the
// scene and subtree walks.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <tiny_gltf.h>
#include <glm/glm.hpp>

#include "scene/scene_desc.hpp"

namespace game::gltf {

struct AccessorBytes;

// Appends meshes, transformed, to one mesh; degenerate triangles are dropped and counted.
class MeshAssembler {
 public:
  MeshAssembler(const tinygltf::Model& model, const std::filesystem::path& file)
      : model_(model), file_(file) {}

  void appendMesh(int meshIndex, const glm::dmat4& transform);

  // The glTF materials of the primitives appended, in order of first use (-1: a primitive
  // without one); the mesh's triangleMaterials index this list.
  const std::vector<int>& materials() const { return materials_; }
  std::size_t droppedTriangles() const { return dropped_; }

  scene::MeshData finish(std::string name);

 private:
  void appendPrimitive(const tinygltf::Primitive& primitive, const glm::dmat4& transform,
                       const std::string& label);
  void expectOnePerPosition(std::size_t count, std::size_t positionCount, const std::string& label,
                            const std::string& what) const;
  static void computeAreaWeightedNormals(std::vector<scene::Vertex>& vertices,
                                         const std::vector<uint32_t>& indices);
  std::vector<uint32_t> sequentialIndices(std::size_t count, const std::string& label) const;
  AccessorBytes locate(int accessorIndex, const std::string& label) const;
  const tinygltf::Accessor* accessorAt(int accessorIndex) const;
  std::vector<glm::vec3> readVec3s(int accessorIndex, const std::string& label) const;
  std::vector<glm::vec2> readUvs(int accessorIndex, const std::string& label) const;
  std::vector<glm::vec4> readColors(int accessorIndex, const std::string& label) const;
  std::vector<uint32_t> readIndices(int accessorIndex, const std::string& label) const;

  const tinygltf::Model& model_;
  const std::filesystem::path& file_;
  scene::MeshData result_;
  std::vector<int> materials_;
  std::size_t dropped_ = 0;
};

// Appends the meshes of `rootNode` and its descendants, depth first in document order.
void appendSubtree(const tinygltf::Model& model, const std::filesystem::path& file, int rootNode,
                   const glm::dmat4& parentTransform, MeshAssembler& assembler,
                   std::size_t& visits);

// Appends every node of the default scene with its transforms.
void appendScene(const tinygltf::Model& model, const std::filesystem::path& file,
                 MeshAssembler& assembler);

// The product of the transforms of `nodeIndex`'s ancestors: where the scene puts the node.
glm::dmat4 ancestorTransform(const tinygltf::Model& model, const std::filesystem::path& file,
                             int nodeIndex);

}  // namespace game::gltf
