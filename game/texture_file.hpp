#pragma once
// Decodes PNG/JPEG textures for levels, with size limits.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "scene/scene_desc.hpp"

namespace game {

constexpr uint32_t kMaxTextureDimension = 4096;

// Decodes an image file (PNG or JPEG) into RGBA8. Throws game::LevelError naming the file when
// it cannot be read or decoded, or is larger than kMaxTextureDimension on a side.
scene::TextureDesc loadTextureFile(const std::filesystem::path& file, bool srgb);

// Same, from bytes already in memory (e.g. an image embedded in a .glb); `name` names it.
scene::TextureDesc decodeTexture(std::span<const uint8_t> bytes, const std::string& name,
                                 bool srgb);

}  // namespace game
