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
#include "scene/color.hpp"
#include "vulkan_fixture.hpp"

namespace {

namespace fs = std::filesystem;

// Two unit quads facing +Z side by side, x in [-1, 0] and [0, 1]: primitive 0 with material
// `left`, primitive 1 with `right`, both in one mesh.
void writePairModel(const fs::path& path, const nlohmann::json& left, const nlohmann::json& right) {
  test::GltfBuilder gltf;
  const std::vector<uint16_t> quad = {0, 1, 2, 0, 2, 3};
  nlohmann::json leftQuad =
      gltf.primitive({{-1, -0.5f, 0}, {0, -0.5f, 0}, {0, 0.5f, 0}, {-1, 0.5f, 0}}, quad);
  leftQuad["material"] = 0;
  nlohmann::json rightQuad =
      gltf.primitive({{0, -0.5f, 0}, {1, -0.5f, 0}, {1, 0.5f, 0}, {0, 0.5f, 0}}, quad);
  rightQuad["material"] = 1;
  gltf.addMesh("pair", {leftQuad, rightQuad});
  gltf.document["materials"] = {left, right};
  gltf.write(path);
}

// A dielectric glTF material of one colour.
nlohmann::json plainMaterial(const std::string& name, const std::vector<double>& color) {
  return {{"name", name},
          {"pbrMetallicRoughness", {{"baseColorFactor", color}, {"metallicFactor", 0}}}};
}

void writeTwoMaterialModel(const fs::path& path) {
  writePairModel(path, plainMaterial("red", {1, 0, 0, 1}), plainMaterial("green", {0, 1, 0, 1}));
}

// One quad across the view, x in [-1, 1] and y in [-0.5, 0.5], with UVs u = (x + 1) / 2,
// v = 0.5 - y and a second set (TEXCOORD_1) whose u runs the other way; texture i shows
// image i (PNG bytes).
void writeTexturedQuadModel(const fs::path& path, const nlohmann::json& material,
                            const std::vector<std::string>& images) {
  test::GltfBuilder gltf;
  nlohmann::json quad = gltf.primitive({{-1, -0.5f, 0}, {1, -0.5f, 0}, {1, 0.5f, 0}, {-1, 0.5f, 0}},
                                       {0, 1, 2, 0, 2, 3});
  quad["attributes"]["TEXCOORD_0"] = gltf.addAccessor(
      test::packed(std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0}), test::kFloat, 4, "VEC2");
  quad["attributes"]["TEXCOORD_1"] = gltf.addAccessor(
      test::packed(std::vector<float>{1, 1, 0, 1, 0, 0, 1, 0}), test::kFloat, 4, "VEC2");
  quad["material"] = 0;
  gltf.addMesh("quad", {quad});
  gltf.document["materials"] = nlohmann::json::array({material});
  gltf.document["textures"] = nlohmann::json::array();
  gltf.document["images"] = nlohmann::json::array();
  for (std::size_t i = 0; i < images.size(); ++i) {
    gltf.document["textures"].push_back({{"source", i}});
    gltf.document["images"].push_back(
        {{"uri", "data:image/png;base64," + test::base64(images[i])}});
  }
  gltf.document["extensionsUsed"] = {"KHR_texture_transform"};
  gltf.write(path);
}

// An 8x1 RGBA PNG, its left four texels `left` and its right four `right`: sampled at the
// quad's left and right thirds, texels of one colour only meet under the filter.
std::string splitPng(const std::array<uint8_t, 4>& left, const std::array<uint8_t, 4>& right) {
  std::vector<uint8_t> pixels;
  for (int x = 0; x < 8; ++x)
    pixels.insert(pixels.end(), x < 4 ? left.begin() : right.begin(),
                  x < 4 ? left.end() : right.end());
  return test::pngBytes(8, 1, 4, pixels.data());
}

// A 1x8 RGBA PNG, its top four texels `top` and its bottom four `bottom`.
std::string stackedPng(const std::array<uint8_t, 4>& top, const std::array<uint8_t, 4>& bottom) {
  std::vector<uint8_t> pixels;
  for (int y = 0; y < 8; ++y)
    pixels.insert(pixels.end(), y < 4 ? top.begin() : bottom.begin(),
                  y < 4 ? top.end() : bottom.end());
  return test::pngBytes(1, 8, 4, pixels.data());
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
  // `material` names one for all; `ambient` is the environment's ambient light.
  render::Rgba8Image render(const std::string& material, float ambient = 0.0f) {
    std::ofstream(root_ / "level.json") << R"({
      "format": 1, "name": "Pair",
      "camera": { "position": [0, 0, 2.5] },
      "environment": { "ambient": [)" + std::to_string(ambient) +
                                               "," + std::to_string(ambient) + "," +
                                               std::to_string(ambient) + R"(] },
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

  // The quad's left and right pixels (x 12 and 19 of row 8), RGB.
  static std::array<std::array<int, 3>, 2> sides(const render::Rgba8Image& image) {
    std::array<std::array<int, 3>, 2> result{};
    const std::array<uint32_t, 2> columns = {12, 19};
    for (std::size_t side = 0; side < 2; ++side)
      for (std::size_t c = 0; c < 3; ++c)
        result[side][c] = image.pixels[(8 * std::size_t(image.width) + columns[side]) * 4 + c];
    return result;
  }

  // Each side's colour within `tolerance` of the reference's on the same side.
  static void expectSidesNear(const render::Rgba8Image& image, const render::Rgba8Image& reference,
                              int tolerance) {
    const auto got = sides(image), expected = sides(reference);
    for (std::size_t side = 0; side < 2; ++side)
      for (std::size_t c = 0; c < 3; ++c)
        EXPECT_NEAR(got[side][c], expected[side][c], tolerance)
            << (side ? "right" : "left") << " side, channel " << c;
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

namespace {

// glTF's metallicRoughnessTexture (green scales roughness, blue metallic) and emissiveTexture
// (sRGB, scales the emissive factor) render each side as a model whose factors are the
// products does: left a rough metal that glows, right a half-rough dielectric that does not.
TEST_F(ModelMaterialsTest, metallic_roughness_and_emissive_textures_scale_their_factors) {
  const nlohmann::json textured = {{"name", "worn"},
                                   {"emissiveFactor", {0.0, 0.0, 0.5}},
                                   {"emissiveTexture", {{"index", 1}}},
                                   {"pbrMetallicRoughness",
                                    {{"baseColorFactor", {0.9, 0.5, 0.2, 1}},
                                     {"metallicFactor", 1},
                                     {"roughnessFactor", 1},
                                     {"metallicRoughnessTexture", {{"index", 0}}}}}};
  writeTexturedQuadModel(root_ / "pair.gltf", textured,
                         {splitPng({0, 255, 255, 255}, {0, 128, 0, 255}),
                          splitPng({255, 255, 255, 255}, {0, 0, 0, 255})});
  const render::Rgba8Image image = render("");

  writePairModel(
      root_ / "pair.gltf",
      {{"name", "metal"},
       {"emissiveFactor", {0.0, 0.0, 0.5}},
       {"pbrMetallicRoughness",
        {{"baseColorFactor", {0.9, 0.5, 0.2, 1}}, {"metallicFactor", 1}, {"roughnessFactor", 1}}}},
      {{"name", "dielectric"},
       {"pbrMetallicRoughness",
        {{"baseColorFactor", {0.9, 0.5, 0.2, 1}},
         {"metallicFactor", 0},
         {"roughnessFactor", 128.0 / 255.0}}}});
  const render::Rgba8Image reference = render("");
  expectSidesNear(image, reference, 1);
  // The two sides differ, so the texture did something.
  EXPECT_GT(sides(image)[0][2], sides(image)[1][2] + 40);
}

// glTF's occlusionTexture darkens the ambient light only: where it is 0 (strength 1) the quad
// looks as it does without ambient light; where it is 1 as it does without the texture.
TEST_F(ModelMaterialsTest, occlusion_texture_takes_away_ambient_light_only) {
  const nlohmann::json base = plainMaterial("stone", {0.8, 0.8, 0.8, 1});
  nlohmann::json occluded = base;
  occluded["occlusionTexture"] = {{"index", 0}, {"strength", 1.0}};
  writeTexturedQuadModel(root_ / "pair.gltf", occluded,
                         {splitPng({255, 255, 255, 255}, {0, 0, 0, 255})});
  const render::Rgba8Image image = render("", 0.5f);
  writeTexturedQuadModel(root_ / "pair.gltf", base, {});
  const render::Rgba8Image withAmbient = render("", 0.5f);
  const render::Rgba8Image withoutAmbient = render("", 0.0f);
  EXPECT_NEAR(sides(image)[0][0], sides(withAmbient)[0][0], 1);
  EXPECT_NEAR(sides(image)[1][0], sides(withoutAmbient)[1][0], 1);
  EXPECT_GT(sides(withAmbient)[1][0], sides(withoutAmbient)[1][0] + 20);
}

// A base colour texture red on its left half and blue on its right, moved by
// KHR_texture_transform (an offset of half, a half turn, a mirroring scale) or read through
// the second UV set (which runs the other way): each swaps the sides.
TEST_F(ModelMaterialsTest, texture_transform_and_second_uv_set_move_the_texture) {
  writePairModel(root_ / "pair.gltf", plainMaterial("blue", {0, 0, 1, 1}),
                 plainMaterial("red", {1, 0, 0, 1}));
  const render::Rgba8Image swapped = render("");
  const std::string redBlue = splitPng({255, 0, 0, 255}, {0, 0, 255, 255});
  auto painted = [&](const nlohmann::json& textureInfo) {
    nlohmann::json material = plainMaterial("painted", {1, 1, 1, 1});
    material["pbrMetallicRoughness"]["baseColorTexture"] = textureInfo;
    writeTexturedQuadModel(root_ / "pair.gltf", material, {redBlue});
    return render("");
  };
  const render::Rgba8Image plain = painted({{"index", 0}});
  EXPECT_GT(sides(plain)[0][0], 120);  // red on the left as drawn
  EXPECT_GT(sides(plain)[1][2], 120);
  const nlohmann::json transforms[] = {
      {{"offset", {0.5, 0.0}}},
      {{"rotation", 3.14159265358979}},
      {{"scale", {-1.0, 1.0}}},
      {{"texCoord", 1}},
  };
  for (const nlohmann::json& transform : transforms) {
    SCOPED_TRACE(transform.dump());
    expectSidesNear(painted({{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}),
                    swapped, 1);
  }
  SCOPED_TRACE("texCoord 1");
  expectSidesNear(painted({{"index", 0}, {"texCoord", 1}}), swapped, 1);
}

// KHR_texture_transform turns UVs counter-clockwise: uv' = (cos u + sin v, -sin u + cos v).
// A texture red on top and blue below, turned a quarter, samples v' = -u: the quad's left
// (u near 0.2, v' 0.8 after wrapping) blue, its right red; turned the other way, the opposite.
TEST_F(ModelMaterialsTest, texture_rotation_turns_the_way_the_extension_says) {
  writePairModel(root_ / "pair.gltf", plainMaterial("blue", {0, 0, 1, 1}),
                 plainMaterial("red", {1, 0, 0, 1}));
  const render::Rgba8Image blueRed = render("");
  writePairModel(root_ / "pair.gltf", plainMaterial("red", {1, 0, 0, 1}),
                 plainMaterial("blue", {0, 0, 1, 1}));
  const render::Rgba8Image redBlue = render("");
  const std::string redOverBlue = stackedPng({255, 0, 0, 255}, {0, 0, 255, 255});
  auto turned = [&](double radians) {
    nlohmann::json material = plainMaterial("painted", {1, 1, 1, 1});
    material["pbrMetallicRoughness"]["baseColorTexture"] = {
        {"index", 0}, {"extensions", {{"KHR_texture_transform", {{"rotation", radians}}}}}};
    writeTexturedQuadModel(root_ / "pair.gltf", material, {redOverBlue});
    return render("");
  };
  const double quarter = 1.5707963267948966;
  expectSidesNear(turned(quarter), blueRed, 1);
  expectSidesNear(turned(-quarter), redBlue, 1);
}

// alphaMode BLEND draws the quad as glass tinted mix(white, colour, alpha): red at half alpha
// passes (1, 0.5, 0.5). Behind it the green wall is seen through the tint and lit by the sun
// through it (a tinted shadow): a quarter of the green the open wall shows.
TEST_F(ModelMaterialsTest, a_blended_quad_tints_what_is_seen_through_it_and_its_shadow) {
  nlohmann::json tinted = plainMaterial("tinted", {1, 0, 0, 0.5});
  tinted["alphaMode"] = "BLEND";
  writeTexturedQuadModel(root_ / "pair.gltf", tinted, {});
  const render::Rgba8Image image = render("");
  const game::Level level = game::loadLevel(root_ / "level.json");
  EXPECT_EQ(level.materials[level.entities[0].material].kind, scene::MaterialKind::Glass);
  const auto pixel = [&](uint32_t x, uint32_t y, std::size_t c) {
    return image.pixels[(std::size_t(y) * image.width + x) * 4 + c];
  };
  // Row 0 sees the open wall above the quad and its shadow; the centre, the wall through both.
  const float open = scene::srgbToLinear(pixel(16, 0, 1) / 255.0f);
  const float expected = scene::linearToSrgb(0.25f * open) * 255.0f;
  EXPECT_GT(pixel(16, 0, 1), 100);
  EXPECT_NEAR(float(pixel(16, 8, 1)), expected, 2.0f);
  EXPECT_LE(pixel(16, 8, 0), 1);
}

}  // namespace

namespace {

// docs/gltf/showcase.json (the before/after pictures of docs/gltf) loads without a warning,
// each model with the materials docs/gltf/make_showcase.py gave it.
TEST(GltfShowcaseTest, showcase_models_load_with_their_materials_and_no_warning) {
  const game::Level level = game::loadLevel(test::sourceDir() / "docs" / "gltf" / "showcase.json");
  EXPECT_TRUE(level.warnings.empty()) << level.warnings.front();
  auto entity = [&](const std::string& id) {
    for (const game::Entity& candidate : level.entities)
      if (candidate.id == id) return candidate;
    ADD_FAILURE() << "no entity " << id;
    return game::Entity{};
  };
  EXPECT_EQ(entity("cube").meshMaterials.size(), 6u);
  const scene::MaterialDesc& gold = level.materials[entity("sphere").material];
  EXPECT_TRUE(gold.metallicRoughness);
  EXPECT_EQ(gold.metallic, 1.0f);
  EXPECT_EQ(level.materials[entity("screen").material].alphaCutoff, 0.5f);
  const scene::MaterialDesc& pane = level.materials[entity("pane").material];
  EXPECT_EQ(pane.kind, scene::MaterialKind::Glass);
  EXPECT_TRUE(pane.alphaBlend);
}

}  // namespace
