// A glTF model of several materials renders each primitive in its own (docs/LEVELS.md, "glTF
// models"), unless the entity names one material for all of it.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "game/level_loader.hpp"
#include "vulkan_fixture.hpp"

namespace {

namespace fs = std::filesystem;

std::string base64(const std::string& bytes) {
  static const char* const kDigits =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t count = std::min<std::size_t>(3, bytes.size() - i);
    uint32_t group = uint32_t(uint8_t(bytes[i])) << 16;
    if (count > 1) group |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    if (count > 2) group |= uint32_t(uint8_t(bytes[i + 2]));
    text += kDigits[(group >> 18) & 63];
    text += kDigits[(group >> 12) & 63];
    text += count > 1 ? kDigits[(group >> 6) & 63] : '=';
    text += count > 2 ? kDigits[group & 63] : '=';
  }
  return text;
}

template <typename T>
std::string bytesOf(const std::vector<T>& values) {
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// Two unit quads facing +Z side by side, x in [-1, 0] and [0, 1]: primitive 0 with material
// "red", primitive 1 with "green", both in one mesh.
std::string twoMaterialModel() {
  const std::vector<float> left = {-1, -0.5f, 0, 0, -0.5f, 0, 0, 0.5f, 0, -1, 0.5f, 0};
  const std::vector<float> right = {0, -0.5f, 0, 1, -0.5f, 0, 1, 0.5f, 0, 0, 0.5f, 0};
  const std::vector<uint16_t> indices = {0, 1, 2, 0, 2, 3};
  const std::string buffer = bytesOf(left) + bytesOf(right) + bytesOf(indices);
  const std::string views = R"([
    {"buffer": 0, "byteOffset": 0, "byteLength": 48},
    {"buffer": 0, "byteOffset": 48, "byteLength": 48},
    {"buffer": 0, "byteOffset": 96, "byteLength": 12}])";
  const std::string accessors = R"([
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -0.5, 0], "max": [0, 0.5, 0]},
    {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, -0.5, 0], "max": [1, 0.5, 0]},
    {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}])";
  return R"({"asset": {"version": "2.0"},
    "buffers": [{"byteLength": )" +
         std::to_string(buffer.size()) + R"(, "uri": "data:application/octet-stream;base64,)" +
         base64(buffer) + R"("}],
    "bufferViews": )" +
         views + R"(, "accessors": )" + accessors + R"(,
    "materials": [
      {"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1], "metallicFactor": 0}},
      {"name": "green", "pbrMetallicRoughness": {"baseColorFactor": [0, 1, 0, 1], "metallicFactor": 0}}],
    "meshes": [{"name": "pair", "primitives": [
      {"attributes": {"POSITION": 0}, "indices": 2, "material": 0},
      {"attributes": {"POSITION": 1}, "indices": 2, "material": 1}]}]})";
}

class ModelMaterialsTest : public test::VulkanTest {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("sightline-model-materials-" + std::to_string(std::random_device{}()));
    fs::create_directories(root_);
    std::ofstream(root_ / "pair.gltf") << twoMaterialModel();
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(root_, ignored);
    test::VulkanTest::TearDown();
  }

  // The pair seen straight on under a sun behind the camera; `material` names one for all.
  render::Rgba8Image render(const std::string& material) {
    std::ofstream(root_ / "level.json") << R"({
      "format": 1, "name": "Pair",
      "camera": { "position": [0, 0, 2.5] },
      "materials": { "paint": { "color": [0.5, 0.5, 0.5] } },
      "meshes": { "pair": { "gltf": "pair.gltf" } },
      "entities": { "pair": { "mesh": "pair")" +
                                               material + R"( } },
      "lights": { "sun": { "type": "directional", "direction": [0, 0, -1], "intensity": 1 } }
    })";
    const game::Level level = game::loadLevel(root_ / "level.json");
    return renderLevel(level, 32, 16, scene::Tonemap::Identity);
  }

  fs::path root_;
};

TEST_F(ModelMaterialsTest, each_primitive_renders_in_its_own_material) {
  const render::Rgba8Image image = render("");
  const game::Level level = game::loadLevel(root_ / "level.json");
  EXPECT_EQ(level.meshMaterialNames[0], (std::vector<std::string>{"red", "green"}));
  EXPECT_EQ(level.materialIds.back(), "pair#gltf:1");
  auto at = [&](uint32_t x, uint32_t y, int channel) {
    return int(image.pixels[(size_t(y) * image.width + x) * 4 + size_t(channel)]);
  };
  // Left of centre the red quad, right of it the green one (each 1 m wide at 2.5 m).
  EXPECT_GT(at(12, 8, 0), 120);
  EXPECT_LT(at(12, 8, 1), 40);
  EXPECT_GT(at(19, 8, 1), 120);
  EXPECT_LT(at(19, 8, 0), 40);

  // The entity's own material covers every primitive.
  const render::Rgba8Image grey = render(R"(, "material": "paint")");
  const size_t left = (8 * 32 + 12) * 4, right = (8 * 32 + 19) * 4;
  EXPECT_EQ(grey.pixels[left], grey.pixels[right]);
  EXPECT_EQ(grey.pixels[left], grey.pixels[left + 1]);
}

}  // namespace
