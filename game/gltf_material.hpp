#pragma once
// Maps a glTF model's metallic-roughness material onto ours and decodes its textures.
#include <filesystem>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "game/gltf_mesh.hpp"

namespace game::gltf {

// `materialIndex` must be valid. Textures are decoded by decodeTexture, with its limits; a
// texture that asks for another UV set than TEXCOORD_0 adds a line to `warnings`.
GltfMaterial mapMaterial(const tinygltf::Model& model, const std::filesystem::path& file,
                         int materialIndex, std::vector<std::string>& warnings);

}  // namespace game::gltf
