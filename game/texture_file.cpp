#include "game/texture_file.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <fstream>
#include <memory>
#include <vector>

#include <stb/stb_image.h>

#include "game/level_loader.hpp"

namespace game {

namespace {

namespace fs = std::filesystem;

// Both limits guard against memory exhaustion: a 4096x4096 RGBA8 texture is 64 MiB decoded,
// and no sensible PNG or JPEG of that size is larger than that encoded.
constexpr std::size_t kMaxTextureFileBytes = std::size_t{64} << 20;

[[noreturn]] void fail(const std::string& name, const std::string& problem) {
  throw LevelError(name + ": " + problem);
}

constexpr std::array<uint8_t, 8> kPngSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr std::array<uint8_t, 3> kJpegSignature = {0xff, 0xd8, 0xff};

template <std::size_t N>
bool startsWith(std::span<const uint8_t> bytes, const std::array<uint8_t, N>& signature) {
  return bytes.size() >= N && std::equal(signature.begin(), signature.end(), bytes.begin());
}

std::string stbReason() {
  const char* reason = stbi_failure_reason();
  return reason ? reason : "unknown error";
}

struct StbFree {
  void operator()(stbi_uc* pixels) const { stbi_image_free(pixels); }
};

}  // namespace

scene::TextureDesc decodeTexture(std::span<const uint8_t> bytes, const std::string& name,
                                 bool srgb) {
  if (bytes.empty()) fail(name, "image file is empty");
  if (bytes.size() > kMaxTextureFileBytes) {
    fail(name, "image file is larger than the 64 MiB limit");
  }
  // stb_image also reads BMP, GIF, TGA, ...; the level format promises PNG and JPEG only.
  const bool isPng = startsWith(bytes, kPngSignature);
  if (!isPng && !startsWith(bytes, kJpegSignature)) fail(name, "not a PNG or JPEG image");
  const char* const format = isPng ? "PNG" : "JPEG";

  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int length = static_cast<int>(bytes.size());  // fits: at most 64 MiB
  // Read the header alone first, so an oversized image is refused before anything is allocated
  // for its pixels.
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(data, length, &width, &height, &channels)) {
    fail(name, std::string("cannot read the ") + format + " header (" + stbReason() + ")");
  }
  if (width <= 0 || height <= 0) fail(name, "image has no pixels");
  if (static_cast<uint32_t>(width) > kMaxTextureDimension ||
      static_cast<uint32_t>(height) > kMaxTextureDimension) {
    fail(name, "image is " + std::to_string(width) + "x" + std::to_string(height) +
                   "; textures are limited to " + std::to_string(kMaxTextureDimension) + "x" +
                   std::to_string(kMaxTextureDimension));
  }

  constexpr int kRgba = 4;
  int decodedWidth = 0, decodedHeight = 0;
  const std::unique_ptr<stbi_uc, StbFree> pixels(
      stbi_load_from_memory(data, length, &decodedWidth, &decodedHeight, &channels, kRgba));
  if (!pixels) {
    fail(name, std::string("cannot decode the ") + format +
                   " image: the file is truncated or corrupt (" + stbReason() + ")");
  }
  if (decodedWidth != width || decodedHeight != height) {
    fail(name, "image decoded to a different size than its header states");
  }

  scene::TextureDesc texture;
  texture.name = name;
  texture.width = static_cast<uint32_t>(width);
  texture.height = static_cast<uint32_t>(height);
  texture.srgb = srgb;
  const std::size_t byteCount = std::size_t{texture.width} * texture.height * kRgba;
  texture.rgba.assign(pixels.get(), pixels.get() + byteCount);
  return texture;
}

scene::TextureDesc loadTextureFile(const fs::path& file, bool srgb) {
  const std::string name = file.string();
  std::error_code error;
  if (!fs::is_regular_file(file, error)) fail(name, "cannot open texture file");
  const std::uintmax_t size = fs::file_size(file, error);
  if (error) fail(name, "cannot read texture file: " + error.message());
  // Checked before reading, so a huge file is never loaded into memory.
  if (size > kMaxTextureFileBytes) fail(name, "image file is larger than the 64 MiB limit");

  std::vector<uint8_t> bytes(static_cast<std::size_t>(size));
  std::ifstream stream(file, std::ios::binary);
  if (!stream ||
      !stream.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size))) {
    fail(name, "cannot read texture file");
  }
  return decodeTexture(bytes, name, srgb);
}

}  // namespace game
