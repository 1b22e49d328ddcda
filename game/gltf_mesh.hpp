#pragma once
// Loads a glTF 2.0 model (.gltf or .glb) for use as a level mesh.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene_desc.hpp"

namespace game {

// One of the model's own materials, mapped to ours; see docs/LEVELS.md.
struct GltfMaterial {
  std::string name;           // the glTF material's name, or "material N", or "default"
  glm::vec3 baseColor{1.0f};  // linear (glTF factors are linear)
  float metallic = 1.0f;      // glTF's default metallicFactor
  float alpha = 1.0f;         // baseColorFactor's alpha
  float alphaCutoff = 0.0f;   // alphaMode MASK: its alphaCutoff; 0: opaque
  bool alphaBlend = false;    // alphaMode BLEND
  float roughness = 1.0f;
  glm::vec3 emissive{0.0f};  // linear, times KHR_materials_emissive_strength
  float normalScale = 1.0f;
  float occlusionStrength = 1.0f;
  std::optional<scene::TextureDesc> colorTexture;              // srgb = true
  std::optional<scene::TextureDesc> normalTexture;             // srgb = false
  std::optional<scene::TextureDesc> metallicRoughnessTexture;  // srgb = false
  std::optional<scene::TextureDesc> occlusionTexture;          // srgb = false
  std::optional<scene::TextureDesc> emissiveTexture;           // srgb = true
  // Each texture's UV set and KHR_texture_transform, by scene::TextureRole.
  std::array<scene::TextureMapping, scene::kTextureRoles> textureMappings{};
};

// Which part of the model to load; at most one of the two may be set. Neither: every node of
// the default scene with its transforms (every mesh untransformed when there is no scene).
struct GltfSelection {
  std::string node;  // non-empty: that node (by name) and its children, placed where the scene
                     // puts them (its ancestors' transforms apply too)
  std::string mesh;  // non-empty: that mesh (by name), in its own coordinates
};

struct GltfModel {
  // Positions, normals, UVs; degenerate triangles dropped; with several materials, which one
  // each triangle has (mesh.triangleMaterials indexes `materials`).
  scene::MeshData mesh;
  // The primitives' materials in order of first use (a primitive without one gets glTF's
  // default material); empty when no primitive names one.
  std::vector<GltfMaterial> materials;
  std::vector<std::filesystem::path> filesRead;  // the model and every buffer/image it named
  std::vector<std::string> warnings;             // "<file>: dropped N degenerate triangles"
};

// Reads `file`; every file tinygltf opens must resolve inside `allowedRoot`. Meshes are
// appended depth first in document order; every primitive keeps its material, and only the
// images those materials use are decoded (through decodeTexture, so with its limits).
// Throws game::LevelError("<file>: <problem>"); the problem names the mesh, primitive, material
// or image at fault.
GltfModel loadGltfModel(const std::filesystem::path& file, const std::filesystem::path& allowedRoot,
                        const GltfSelection& selection = {});

// Transitional: the mesh alone (meshName selects a mesh, as GltfSelection::mesh).
scene::MeshData loadGltfMesh(const std::filesystem::path& file,
                             const std::filesystem::path& allowedRoot,
                             const std::string& meshName = {});

}  // namespace game
