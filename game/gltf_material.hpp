#pragma once
// Maps a glTF model's metallic-roughness material onto ours and decodes its textures.
#include <filesystem>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "game/gltf_mesh.hpp"

namespace game::gltf {

// `materialIndex` must be valid. Textures are decoded by decodeTexture, with its limits; a
// texture that asks for a UV set past TEXCOORD_1 adds a line to `warnings` (and reads
// TEXCOORD_0). KHR_texture_transform moves a texture and may pick its UV set.
GltfMaterial mapMaterial(const tinygltf::Model& model, const std::filesystem::path& file,
                         int materialIndex, std::vector<std::string>& warnings);

}  // namespace game::gltf
