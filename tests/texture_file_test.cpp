// Tests for decoding PNG/JPEG texture files and their limits.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <stb/stb_image_write.h>

#include "game/level_loader.hpp"
#include "game/texture_file.hpp"
#include "temp_dir_fixture.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path kAssets = fs::path(SIGHTLINE_SOURCE_DIR) / "assets";

std::vector<uint8_t> readBytes(const fs::path& path) {
  std::ifstream stream(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

std::vector<uint8_t> asBytes(const std::string& text) {
  return {text.begin(), text.end()};
}

// The message decodeTexture throws for `bytes`, or a note that it threw nothing.
std::string decodeError(const std::vector<uint8_t>& bytes, const std::string& name = "t.png") {
  try {
    game::decodeTexture(bytes, name, true);
  } catch (const game::LevelError& error) {
    return error.what();
  }
  return "(no error)";
}

using test::texel;

void appendBigEndian(std::vector<uint8_t>& bytes, uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8)
    bytes.push_back(static_cast<uint8_t>(value >> shift));
}

uint32_t crc32(const uint8_t* data, std::size_t size) {
  uint32_t crc = 0xffffffffu;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

// A well-formed PNG signature and IHDR claiming `width` x `height` RGBA pixels, then IEND: no
// pixel data at all, so decoding it could only fail.
std::vector<uint8_t> pngHeaderOnly(uint32_t width, uint32_t height) {
  std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  auto appendChunk = [&png](const std::string& type, const std::vector<uint8_t>& data) {
    appendBigEndian(png, static_cast<uint32_t>(data.size()));
    const std::size_t typeAt = png.size();
    png.insert(png.end(), type.begin(), type.end());
    png.insert(png.end(), data.begin(), data.end());
    appendBigEndian(png, crc32(png.data() + typeAt, png.size() - typeAt));
  };
  std::vector<uint8_t> header;
  appendBigEndian(header, width);
  appendBigEndian(header, height);
  header.insert(header.end(), {8, 6, 0, 0, 0});  // 8-bit RGBA, no interlacing
  appendChunk("IHDR", header);
  appendChunk("IEND", {});
  return png;
}

class TextureFileTest : public test::TempDirTest {};

TEST(TextureFile, crate_colour_png_decodes_to_exact_rgba8) {
  const fs::path file = kAssets / "crate_color.png";
  const scene::TextureDesc texture = game::loadTextureFile(file, true);
  EXPECT_EQ(texture.name, file.string());
  EXPECT_EQ(texture.width, 64u);
  EXPECT_EQ(texture.height, 64u);
  EXPECT_TRUE(texture.srgb);
  ASSERT_EQ(texture.rgba.size(), 64u * 64u * 4u);
  // The RGB file gains an opaque alpha channel. Values from scripts/make_textured_crate.py.
  EXPECT_EQ(texel(texture, 0, 0), (std::array<uint8_t, 4>{92, 62, 34, 255}));      // frame
  EXPECT_EQ(texel(texture, 32, 8), (std::array<uint8_t, 4>{167, 117, 65, 255}));   // plank 0
  EXPECT_EQ(texel(texture, 10, 20), (std::array<uint8_t, 4>{159, 113, 64, 255}));  // plank 1
  EXPECT_EQ(texel(texture, 40, 15), (std::array<uint8_t, 4>{60, 40, 22, 255}));    // seam
  EXPECT_EQ(texel(texture, 63, 63), (std::array<uint8_t, 4>{92, 62, 34, 255}));    // frame
}

TEST(TextureFile, normal_map_keeps_its_linear_flag_and_values) {
  const scene::TextureDesc texture = game::loadTextureFile(kAssets / "crate_normal.png", false);
  EXPECT_FALSE(texture.srgb);
  EXPECT_EQ(texture.width, 32u);
  EXPECT_EQ(texture.height, 32u);
  EXPECT_EQ(texel(texture, 16, 20), (std::array<uint8_t, 4>{128, 128, 255, 255}));  // flat
  EXPECT_EQ(texel(texture, 0, 16), (std::array<uint8_t, 4>{70, 128, 242, 255}));    // left bevel
  EXPECT_EQ(texel(texture, 31, 31), (std::array<uint8_t, 4>{180, 75, 232, 255}));   // corner
}

TEST_F(TextureFileTest, grey_and_rgba_pngs_are_expanded_to_rgba) {
  const std::array<uint8_t, 6> grey = {0, 50, 100, 150, 200, 255};  // 3x2
  ASSERT_TRUE(stbi_write_png((root_ / "grey.png").c_str(), 3, 2, 1, grey.data(), 3));
  const scene::TextureDesc greyTexture = game::loadTextureFile(root_ / "grey.png", true);
  EXPECT_EQ(greyTexture.width, 3u);
  EXPECT_EQ(greyTexture.height, 2u);
  EXPECT_EQ(texel(greyTexture, 0, 0), (std::array<uint8_t, 4>{0, 0, 0, 255}));
  EXPECT_EQ(texel(greyTexture, 1, 1), (std::array<uint8_t, 4>{200, 200, 200, 255}));

  const std::array<uint8_t, 8> rgba = {1, 2, 3, 4, 250, 251, 252, 0};  // 1x2, rows top first
  ASSERT_TRUE(stbi_write_png((root_ / "rgba.png").c_str(), 1, 2, 4, rgba.data(), 4));
  const scene::TextureDesc rgbaTexture = game::loadTextureFile(root_ / "rgba.png", false);
  EXPECT_EQ(rgbaTexture.rgba, std::vector<uint8_t>(rgba.begin(), rgba.end()));
}

TEST_F(TextureFileTest, jpeg_decodes) {
  std::vector<uint8_t> pixels(16 * 8 * 3);
  for (std::size_t i = 0; i < pixels.size(); i += 3) {
    pixels[i] = 200, pixels[i + 1] = 100, pixels[i + 2] = 50;
  }
  ASSERT_TRUE(stbi_write_jpg((root_ / "flat.jpg").c_str(), 16, 8, 3, pixels.data(), 100));
  const scene::TextureDesc texture = game::loadTextureFile(root_ / "flat.jpg", true);
  EXPECT_EQ(texture.width, 16u);
  EXPECT_EQ(texture.height, 8u);
  const auto corner = texel(texture, 15, 7);
  EXPECT_NEAR(corner[0], 200, 3);  // lossy, but a flat colour survives almost exactly
  EXPECT_NEAR(corner[1], 100, 3);
  EXPECT_NEAR(corner[2], 50, 3);
  EXPECT_EQ(corner[3], 255);
}

TEST(TextureFile, oversized_image_is_refused_from_its_header_before_decoding) {
  // The file holds no pixel data: were it decoded, the message would be a decode failure.
  EXPECT_EQ(decodeError(pngHeaderOnly(5000, 5000)),
            "t.png: image is 5000x5000; textures are limited to 4096x4096");
  EXPECT_EQ(decodeError(pngHeaderOnly(4097, 1)),
            "t.png: image is 4097x1; textures are limited to 4096x4096");
  EXPECT_EQ(decodeError(pngHeaderOnly(1, 4097)),
            "t.png: image is 1x4097; textures are limited to 4096x4096");
  // At the limit the header passes and decoding is what fails.
  EXPECT_EQ(decodeError(pngHeaderOnly(4096, 4096)).rfind("t.png: cannot decode the PNG image", 0),
            0u);
}

TEST(TextureFile, truncated_png_gives_a_clear_error) {
  std::vector<uint8_t> bytes = readBytes(kAssets / "crate_color.png");
  ASSERT_GT(bytes.size(), 200u);
  bytes.resize(bytes.size() / 2);
  const std::string error = decodeError(bytes, "half.png");
  EXPECT_EQ(
      error.rfind("half.png: cannot decode the PNG image: the file is truncated or corrupt (", 0),
      0u)
      << error;

  // Cut inside the header: not even the size can be read.
  bytes.resize(12);
  EXPECT_EQ(decodeError(bytes, "stub.png").rfind("stub.png: cannot read the PNG header (", 0), 0u);
}

TEST(TextureFile, other_formats_and_empty_input_are_refused) {
  EXPECT_EQ(decodeError(asBytes("hello, world")), "t.png: not a PNG or JPEG image");
  EXPECT_EQ(decodeError(asBytes(std::string("BM\x3e\0\0\0", 6))),
            "t.png: not a PNG or JPEG image");  // BMP
  EXPECT_EQ(decodeError({}), "t.png: image file is empty");
}

TEST_F(TextureFileTest, missing_and_oversized_files_are_reported_with_their_name) {
  try {
    game::loadTextureFile(root_ / "missing.png", true);
    FAIL() << "expected an error";
  } catch (const game::LevelError& error) {
    EXPECT_EQ(std::string(error.what()),
              (root_ / "missing.png").string() + ": cannot open texture file");
  }
  // Sparse, so the test neither writes nor reads 64 MiB: the size alone refuses it.
  const fs::path huge = root_ / "huge.png";
  std::ofstream(huge, std::ios::binary) << "\x89PNG";
  fs::resize_file(huge, (std::uintmax_t{64} << 20) + 1);
  try {
    game::loadTextureFile(huge, true);
    FAIL() << "expected an error";
  } catch (const game::LevelError& error) {
    EXPECT_EQ(std::string(error.what()),
              huge.string() + ": image file is larger than the 64 MiB limit");
  }
}

}  // namespace
