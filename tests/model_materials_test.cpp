// A glTF model of several materials renders each primitive in its own (docs/LEVELS.md, "glTF
// models"), unless the entity names one material for all of it.
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "game/level_loader.hpp"
#include "gltf_builder.hpp"
#include "vulkan_fixture.hpp"

namespace {

namespace fs = std::filesystem;

// Two unit quads facing +Z side by side, x in [-1, 0] and [0, 1]: primitive 0 with material
// "red", primitive 1 with "green", both in one mesh.
void writeTwoMaterialModel(const fs::path& path) {
  test::GltfBuilder gltf;
  const std::vector<uint16_t> quad = {0, 1, 2, 0, 2, 3};
  nlohmann::json left =
      gltf.primitive({{-1, -0.5f, 0}, {0, -0.5f, 0}, {0, 0.5f, 0}, {-1, 0.5f, 0}}, quad);
  left["material"] = 0;
  nlohmann::json right =
      gltf.primitive({{0, -0.5f, 0}, {1, -0.5f, 0}, {1, 0.5f, 0}, {0, 0.5f, 0}}, quad);
  right["material"] = 1;
  gltf.addMesh("pair", {left, right});
  gltf.document["materials"] = {
      {{"name", "red"},
       {"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0, 1}}, {"metallicFactor", 0}}}},
      {{"name", "green"},
       {"pbrMetallicRoughness", {{"baseColorFactor", {0, 1, 0, 1}}, {"metallicFactor", 0}}}}};
  gltf.write(path);
}

// One quad across the view, white, with vertex colours (normalized bytes) of orange.
void writeOrangeVertexColourModel(const fs::path& path) {
  test::GltfBuilder gltf;
  nlohmann::json quad = gltf.primitive({{-1, -0.5f, 0}, {1, -0.5f, 0}, {1, 0.5f, 0}, {-1, 0.5f, 0}},
                                       {0, 1, 2, 0, 2, 3});
  const std::vector<uint8_t> orange = {255, 128, 0, 255, 128, 0, 255, 128, 0, 255, 128, 0};
  quad["attributes"]["COLOR_0"] =
      gltf.addAccessor(test::packed(orange), test::kUnsignedByte, 4, "VEC3", true);
  quad["material"] = 0;
  gltf.addMesh("pair", {quad});
  gltf.document["materials"] = {
      {{"name", "white"},
       {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 1}}, {"metallicFactor", 0}}}}};
  gltf.write(path);
}

// A 2x1 RGBA PNG: an opaque red texel, then a transparent one.
std::string halfTransparentPng() {
  const std::array<uint8_t, 8> pixels = {255, 0, 0, 255, 255, 0, 0, 0};
  return test::pngBytes(2, 1, 4, pixels.data());
}

// One quad across the view whose texture is opaque on its left half and a hole on its right,
// alphaMode MASK.
void writeMaskedQuadModel(const fs::path& path) {
  test::GltfBuilder gltf;
  nlohmann::json quad = gltf.primitive({{-1, -0.5f, 0}, {1, -0.5f, 0}, {1, 0.5f, 0}, {-1, 0.5f, 0}},
                                       {0, 1, 2, 0, 2, 3});
  quad["attributes"]["TEXCOORD_0"] = gltf.addAccessor(
      test::packed(std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0}), test::kFloat, 4, "VEC2");
  quad["material"] = 0;
  gltf.addMesh("pair", {quad});
  gltf.document["materials"] = {
      {{"name", "leaf"},
       {"alphaMode", "MASK"},
       {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0}}}}};
  gltf.document["textures"] = {{{"source", 0}}};
  gltf.document["images"] = {
      {{"uri", "data:image/png;base64," + test::base64(halfTransparentPng())}}};
  gltf.write(path);
}

class ModelMaterialsTest : public test::VulkanTest {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("sightline-model-materials-" + std::to_string(std::random_device{}()));
    fs::create_directories(root_);
    writeTwoMaterialModel(root_ / "pair.gltf");
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(root_, ignored);
    test::VulkanTest::TearDown();
  }

  // The pair seen straight on under a sun behind the camera, a green wall 1 m behind it;
  // `material` names one for all.
  render::Rgba8Image render(const std::string& material) {
    std::ofstream(root_ / "level.json") << R"({
      "format": 1, "name": "Pair",
      "camera": { "position": [0, 0, 2.5] },
      "materials": { "paint": { "color": [0.5, 0.5, 0.5] }, "green": { "color": [0, 1, 0] } },
      "meshes": { "pair": { "gltf": "pair.gltf" }, "wall": { "box": { "size": [6, 6, 0.1] } } },
      "entities": { "pair": { "mesh": "pair")" +
                                               material + R"( },
                    "wall": { "mesh": "wall", "material": "green", "position": [0, 0, -1] } },
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

namespace {

TEST_F(ModelMaterialsTest, vertex_colours_multiply_the_base_colour) {
  writeOrangeVertexColourModel(root_ / "pair.gltf");
  const render::Rgba8Image image = render("");
  const size_t centre = (8 * 32 + 16) * 4;
  // White times linear (1, 0.502, 0): red brightest, green about half in linear light, blue
  // only from the 4 % white highlight of glTF's dielectric specular.
  EXPECT_GT(image.pixels[centre], 120);
  EXPECT_GT(image.pixels[centre], image.pixels[centre + 1] + 20);
  EXPECT_GT(image.pixels[centre + 1], 40);
  EXPECT_LT(image.pixels[centre + 2], 40);
}

}  // namespace

namespace {

// Camera rays see the wall through the hole; the sun's shadow rays pass it too, so the wall
// there is lit (shadowed by the quad it would be dark).
TEST_F(ModelMaterialsTest, an_alpha_masked_quad_has_holes_for_camera_and_shadow_rays) {
  writeMaskedQuadModel(root_ / "pair.gltf");
  const render::Rgba8Image image = render("");
  const size_t opaque = (8 * 32 + 12) * 4, hole = (8 * 32 + 19) * 4;
  EXPECT_GT(image.pixels[opaque], 120);  // the red texel
  EXPECT_LT(image.pixels[opaque + 1], 40);
  EXPECT_LT(image.pixels[hole], 40);  // the lit green wall behind the hole
  EXPECT_GT(image.pixels[hole + 1], 120);
}

}  // namespace
