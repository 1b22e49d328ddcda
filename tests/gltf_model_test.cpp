// Tests for loadGltfModel: geometry, UVs, selection, degenerate triangles, materials and
// textures, and the confinement of every file the model names.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "game/gltf_mesh.hpp"
#include "game/level_loader.hpp"
#include "game/primitives.hpp"
#include "gltf_builder.hpp"
#include "temp_dir_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::base64;
using test::GltfBuilder;
using test::kFloat;
using test::kUnsignedByte;
using test::kUnsignedShort;
using test::packed;
using test::packedVec3s;

const fs::path kAssets = fs::path(SIGHTLINE_SOURCE_DIR) / "assets";

using test::writeFile;

std::string readFile(const fs::path& path) {
  std::ifstream stream(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

// A 2x1 RGB PNG, red then green.
std::string tinyPng() {
  const std::array<uint8_t, 6> pixels = {255, 0, 0, 0, 255, 0};
  const std::string png = test::pngBytes(2, 1, 3, pixels.data());
  EXPECT_FALSE(png.empty());
  return png;
}

const std::vector<glm::vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

class GltfModelTest : public test::TempDirTest {
 protected:
  // The message loadGltfModel throws, or a note that it threw nothing.
  std::string loadError(const fs::path& file, const game::GltfSelection& selection = {}) const {
    try {
      game::loadGltfModel(file, root_, selection);
    } catch (const game::LevelError& error) {
      return error.what();
    }
    return "(no error)";
  }
};

using test::texel;

// ----- the textured crate asset -----

TEST(GltfCrate, geometry_matches_the_box_primitive_with_uvs) {
  const game::GltfModel model = game::loadGltfModel(kAssets / "crate.gltf", kAssets);
  EXPECT_EQ(model.mesh.name, "crate");
  EXPECT_EQ(model.mesh.indices.size(), 12u * 3u);
  EXPECT_TRUE(model.warnings.empty());
  // The generator lays out faces, corners and UVs as primitives::box does.
  const scene::MeshData box = game::primitives::box(glm::vec3(1.0f));
  ASSERT_EQ(model.mesh.vertices.size(), box.vertices.size());
  EXPECT_EQ(model.mesh.indices, box.indices);
  for (std::size_t i = 0; i < box.vertices.size(); ++i) {
    EXPECT_EQ(model.mesh.vertices[i].position, box.vertices[i].position) << "vertex " << i;
    EXPECT_EQ(model.mesh.vertices[i].normal, box.vertices[i].normal) << "vertex " << i;
    EXPECT_EQ(model.mesh.vertices[i].uv, box.vertices[i].uv) << "vertex " << i;
  }
  // Known corners: +X face bottom-left and top-right, top face's image top-left.
  EXPECT_EQ(model.mesh.vertices[0].position, glm::vec3(0.5f, -0.5f, 0.5f));
  EXPECT_EQ(model.mesh.vertices[0].uv, glm::vec2(0, 1));
  EXPECT_EQ(model.mesh.vertices[2].position, glm::vec3(0.5f, 0.5f, -0.5f));
  EXPECT_EQ(model.mesh.vertices[2].uv, glm::vec2(1, 0));
  EXPECT_EQ(model.mesh.vertices[11].position, glm::vec3(-0.5f, 0.5f, -0.5f));
  EXPECT_EQ(model.mesh.vertices[11].uv, glm::vec2(0, 0));
}

TEST(GltfCrate, material_factors_and_textures_are_mapped) {
  const game::GltfModel model = game::loadGltfModel(kAssets / "crate.gltf", kAssets);
  ASSERT_FALSE(model.materials.empty());
  const game::GltfMaterial& material = model.materials.front();
  EXPECT_FLOAT_EQ(material.baseColor.r, 0.9f);
  EXPECT_FLOAT_EQ(material.baseColor.g, 0.85f);
  EXPECT_FLOAT_EQ(material.baseColor.b, 0.8f);
  EXPECT_FLOAT_EQ(material.roughness, 0.75f);
  EXPECT_FLOAT_EQ(material.metallic, 0.0f);
  EXPECT_EQ(material.emissive, glm::vec3(0.0f));

  ASSERT_TRUE(material.colorTexture.has_value());
  const scene::TextureDesc& color = *material.colorTexture;
  EXPECT_EQ(color.name, (kAssets / "crate_color.png").string());
  EXPECT_TRUE(color.srgb);
  EXPECT_EQ(color.width, 64u);
  EXPECT_EQ(color.height, 64u);
  EXPECT_EQ(texel(color, 0, 0), (std::array<uint8_t, 4>{92, 62, 34, 255}));
  EXPECT_EQ(texel(color, 32, 8), (std::array<uint8_t, 4>{167, 117, 65, 255}));
  EXPECT_EQ(texel(color, 40, 15), (std::array<uint8_t, 4>{60, 40, 22, 255}));

  ASSERT_TRUE(material.normalTexture.has_value());
  const scene::TextureDesc& normal = *material.normalTexture;
  EXPECT_FALSE(normal.srgb);
  EXPECT_EQ(normal.width, 32u);
  EXPECT_EQ(normal.height, 32u);
  EXPECT_EQ(texel(normal, 16, 20), (std::array<uint8_t, 4>{128, 128, 255, 255}));
  EXPECT_EQ(texel(normal, 16, 16), (std::array<uint8_t, 4>{128, 185, 242, 255}));
}

TEST(GltfCrate, files_read_lists_the_model_buffer_and_images) {
  const fs::path file = kAssets / "crate.gltf";
  const game::GltfModel model = game::loadGltfModel(file, kAssets);
  EXPECT_EQ(model.filesRead,
            (std::vector<fs::path>{file, kAssets / "crate.bin", kAssets / "crate_color.png",
                                   kAssets / "crate_normal.png"}));
}

// ----- geometry -----

TEST_F(GltfModelTest, missing_normals_are_area_weighted_face_normals) {
  GltfBuilder gltf;
  // Vertex 0 is shared by a triangle of doubled area 4 facing +Z and one of doubled area 1
  // facing +X.
  gltf.addMesh("fan", {gltf.primitive({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 1, 0}, {0, 0, 1}},
                                      {0, 1, 2, 0, 3, 4})});
  gltf.write(root_ / "fan.gltf");
  const game::GltfModel model = game::loadGltfModel(root_ / "fan.gltf", root_);
  ASSERT_EQ(model.mesh.vertices.size(), 5u);
  const glm::vec3 shared = model.mesh.vertices[0].normal;
  const glm::vec3 expected = glm::vec3(1, 0, 4) / std::sqrt(17.0f);
  EXPECT_NEAR(shared.x, expected.x, 1e-6f);
  EXPECT_NEAR(shared.y, expected.y, 1e-6f);
  EXPECT_NEAR(shared.z, expected.z, 1e-6f);
  EXPECT_EQ(model.mesh.vertices[1].normal, glm::vec3(0, 0, 1));
  EXPECT_EQ(model.mesh.vertices[4].normal, glm::vec3(1, 0, 0));
  EXPECT_EQ(model.mesh.vertices[1].uv, glm::vec2(0, 0));  // no TEXCOORD_0: zero
  EXPECT_TRUE(model.materials.empty());
}

TEST_F(GltfModelTest, uvs_may_be_floats_or_normalized_bytes_and_shorts) {
  GltfBuilder gltf;
  json floats = gltf.primitive(kTriangle);
  floats["attributes"]["TEXCOORD_0"] =
      gltf.addAccessor(packed(std::vector<float>{0.25f, 0.5f, 1, 0, 2, -1}), kFloat, 3, "VEC2");
  json bytes = gltf.primitive(kTriangle);
  bytes["attributes"]["TEXCOORD_0"] = gltf.addAccessor(
      packed(std::vector<uint8_t>{255, 0, 0, 255, 51, 102}), kUnsignedByte, 3, "VEC2", true);
  json shorts = gltf.primitive(kTriangle);
  shorts["attributes"]["TEXCOORD_0"] =
      gltf.addAccessor(packed(std::vector<uint16_t>{65535, 0, 0, 65535, 13107, 32768}),
                       kUnsignedShort, 3, "VEC2", true);
  gltf.addMesh("uvs", {floats, bytes, shorts});
  gltf.write(root_ / "uvs.gltf");

  const game::GltfModel model = game::loadGltfModel(root_ / "uvs.gltf", root_);
  ASSERT_EQ(model.mesh.vertices.size(), 9u);
  const auto uv = [&](std::size_t i) { return model.mesh.vertices[i].uv; };
  EXPECT_EQ(uv(0), glm::vec2(0.25f, 0.5f));
  EXPECT_EQ(uv(2), glm::vec2(2, -1));  // outside [0, 1] is fine: textures repeat
  EXPECT_EQ(uv(3), glm::vec2(1, 0));
  EXPECT_EQ(uv(4), glm::vec2(0, 1));
  EXPECT_FLOAT_EQ(uv(5).x, 0.2f);
  EXPECT_FLOAT_EQ(uv(5).y, 0.4f);
  EXPECT_EQ(uv(6), glm::vec2(1, 0));
  EXPECT_FLOAT_EQ(uv(8).x, 0.2f);
  EXPECT_FLOAT_EQ(uv(8).y, 32768.0f / 65535.0f);
  EXPECT_EQ(model.mesh.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
}

TEST_F(GltfModelTest, uvs_of_the_wrong_type_or_count_are_refused) {
  GltfBuilder gltf;
  json primitive = gltf.primitive(kTriangle);
  const int unnormalized =
      gltf.addAccessor(packed(std::vector<uint8_t>{1, 0, 0, 1, 1, 1}), kUnsignedByte, 3, "VEC2");
  primitive["attributes"]["TEXCOORD_0"] = unnormalized;
  gltf.addMesh("bad", {primitive});
  gltf.write(root_ / "bad.gltf");
  EXPECT_EQ(loadError(root_ / "bad.gltf"),
            (root_ / "bad.gltf").string() +
                ": mesh \"bad\" primitive 0 TEXCOORD_0 (accessor 1) must hold VEC2 floats or "
                "normalized unsigned bytes or shorts");

  GltfBuilder twoUvModel;
  json twoUvs = twoUvModel.primitive(kTriangle);
  twoUvs["attributes"]["TEXCOORD_0"] =
      twoUvModel.addAccessor(packed(std::vector<float>{0, 0, 1, 1}), kFloat, 2, "VEC2");
  twoUvModel.addMesh("short", {twoUvs});
  twoUvModel.write(root_ / "short.gltf");
  EXPECT_EQ(
      loadError(root_ / "short.gltf"),
      (root_ / "short.gltf").string() + ": mesh \"short\" primitive 0 has 2 UVs for 3 positions");
}

TEST_F(GltfModelTest, degenerate_triangles_are_dropped_with_a_warning) {
  GltfBuilder gltf;
  // Vertex 3 repeats vertex 1's position; 4 lies on the line through 0 and 1.
  gltf.addMesh("mixed", {gltf.primitive({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {3, 0, 0}},
                                        {0, 1, 2,      // fine
                                         0, 0, 2,      // a repeated index
                                         1, 3, 2,      // two corners at one position
                                         0, 1, 4})});  // collinear
  gltf.write(root_ / "mixed.gltf");
  const game::GltfModel model = game::loadGltfModel(root_ / "mixed.gltf", root_);
  EXPECT_EQ(model.mesh.indices, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(model.warnings, (std::vector<std::string>{(root_ / "mixed.gltf").string() +
                                                      ": dropped 3 degenerate triangles"}));
  // Normals come from the surviving triangle alone.
  EXPECT_EQ(model.mesh.vertices[0].normal, glm::vec3(0, 0, 1));
}

TEST_F(GltfModelTest, model_of_only_degenerate_triangles_is_an_error) {
  GltfBuilder gltf;
  gltf.addMesh("flat", {gltf.primitive({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}, {0, 1, 2, 2, 2, 1})});
  gltf.write(root_ / "flat.gltf");
  EXPECT_EQ(loadError(root_ / "flat.gltf"),
            (root_ / "flat.gltf").string() + ": all 2 triangles are degenerate (zero area)");
}

// ----- selection -----

// Root (translated +10 X) holds Left (mesh "Tri", up 1) and Right (mesh "Big", scaled x2).
GltfBuilder nodeTree() {
  GltfBuilder gltf;
  gltf.addMesh("Tri", {gltf.primitive(kTriangle)});
  gltf.addMesh("Big", {gltf.primitive(kTriangle)});
  gltf.document["nodes"] = {
      {{"name", "Root"}, {"translation", {10, 0, 0}}, {"children", {1, 2}}},
      {{"name", "Left"}, {"mesh", 0}, {"translation", {0, 1, 0}}},
      {{"name", "Right"}, {"mesh", 1}, {"scale", {2, 2, 2}}},
  };
  gltf.document["scenes"] = {{{"nodes", {0}}}};
  gltf.document["scene"] = 0;
  return gltf;
}

std::vector<glm::vec3> positionsOf(const scene::MeshData& mesh) {
  std::vector<glm::vec3> positions;
  for (const scene::Vertex& vertex : mesh.vertices) positions.push_back(vertex.position);
  return positions;
}

TEST_F(GltfModelTest, default_selection_is_the_scene_with_transforms_in_document_order) {
  nodeTree().write(root_ / "tree.gltf");
  const game::GltfModel model = game::loadGltfModel(root_ / "tree.gltf", root_);
  EXPECT_EQ(model.mesh.name, "tree");
  EXPECT_EQ(positionsOf(model.mesh),
            (std::vector<glm::vec3>{
                {10, 1, 0}, {11, 1, 0}, {10, 2, 0}, {10, 0, 0}, {12, 0, 0}, {10, 2, 0}}));
  EXPECT_EQ(model.mesh.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
}

TEST_F(GltfModelTest, node_selection_takes_the_node_and_children_where_the_scene_puts_them) {
  GltfBuilder gltf = nodeTree();
  gltf.document["nodes"][1]["children"] = {2};  // Left now also carries Right
  gltf.document["nodes"][0]["children"] = {1};
  gltf.write(root_ / "tree.gltf");
  game::GltfSelection selection;
  selection.node = "Left";
  const game::GltfModel model = game::loadGltfModel(root_ / "tree.gltf", root_, selection);
  EXPECT_EQ(model.mesh.name, "Left");
  // Root's translation and Left's own apply; Right is scaled inside Left.
  EXPECT_EQ(positionsOf(model.mesh),
            (std::vector<glm::vec3>{
                {10, 1, 0}, {11, 1, 0}, {10, 2, 0}, {10, 1, 0}, {12, 1, 0}, {10, 3, 0}}));
  selection.node = "Right";
  EXPECT_EQ(positionsOf(game::loadGltfModel(root_ / "tree.gltf", root_, selection).mesh),
            (std::vector<glm::vec3>{{10, 1, 0}, {12, 1, 0}, {10, 3, 0}}));
}

TEST_F(GltfModelTest, mesh_selection_ignores_node_transforms) {
  nodeTree().write(root_ / "tree.gltf");
  game::GltfSelection selection;
  selection.mesh = "Big";
  const game::GltfModel model = game::loadGltfModel(root_ / "tree.gltf", root_, selection);
  EXPECT_EQ(model.mesh.name, "Big");
  EXPECT_EQ(positionsOf(model.mesh), kTriangle);
  // The wrapper the level loader still uses selects the same way.
  EXPECT_EQ(positionsOf(game::loadGltfMesh(root_ / "tree.gltf", root_, "Big")), kTriangle);
}

TEST_F(GltfModelTest, unknown_node_or_mesh_names_list_the_available_ones) {
  GltfBuilder gltf = nodeTree();
  gltf.document["nodes"].push_back(json::object());  // an unnamed node
  gltf.write(root_ / "tree.gltf");
  const std::string prefix = (root_ / "tree.gltf").string() + ": ";
  game::GltfSelection selection;
  selection.node = "Middle";
  EXPECT_EQ(loadError(root_ / "tree.gltf", selection),
            prefix +
                "has no node named \"Middle\"; its nodes are: \"Root\", \"Left\", \"Right\", "
                "(unnamed #3)");
  selection = {};
  selection.mesh = "Small";
  EXPECT_EQ(loadError(root_ / "tree.gltf", selection),
            prefix + "has no mesh named \"Small\"; its meshes are: \"Tri\", \"Big\"");
}

TEST_F(GltfModelTest, mirroring_node_keeps_counter_clockwise_winding) {
  GltfBuilder gltf;
  gltf.addMesh("Tri", {gltf.primitive(kTriangle, {0, 1, 2})});
  gltf.document["nodes"] = {{{"mesh", 0}, {"scale", {-1, 1, 1}}}};
  gltf.document["scenes"] = {{{"nodes", {0}}}};
  gltf.write(root_ / "mirror.gltf");
  const game::GltfModel model = game::loadGltfModel(root_ / "mirror.gltf", root_);
  EXPECT_EQ(model.mesh.indices, (std::vector<uint32_t>{0, 2, 1}));
  const auto& v = model.mesh.vertices;
  const glm::vec3 face = glm::cross(v[model.mesh.indices[1]].position - v[0].position,
                                    v[model.mesh.indices[2]].position - v[0].position);
  EXPECT_GT(face.z, 0.0f);  // still facing +Z, like the unmirrored triangle
  EXPECT_EQ(v[1].normal, glm::vec3(0, 0, 1));
}

// ----- materials and textures -----

TEST_F(GltfModelTest, every_primitive_keeps_its_material_in_order_of_first_use) {
  GltfBuilder gltf;
  json first = gltf.primitive(kTriangle);
  first["material"] = 1;
  json second = gltf.primitive(kTriangle);
  second["material"] = 0;
  json third = gltf.primitive(kTriangle);  // none: glTF's default material
  gltf.addMesh("three", {first, second, third});
  gltf.document["materials"] = {
      {{"name", "plain"}},
      {{"name", "shiny"},
       {"pbrMetallicRoughness",
        {{"baseColorFactor", {0.5, 0.25, 1.0, 0.5}}, {"metallicFactor", 0.5}}},
       {"emissiveFactor", {0.25, 0.5, 1.0}},
       {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}},
  };
  gltf.document["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  gltf.document["extensionsRequired"] = {"KHR_materials_emissive_strength"};
  gltf.write(root_ / "three.gltf");
  const game::GltfModel model = game::loadGltfModel(root_ / "three.gltf", root_);
  ASSERT_EQ(model.materials.size(), 3u);
  EXPECT_EQ(model.mesh.triangleMaterials, (std::vector<uint32_t>{0, 1, 2}));
  const game::GltfMaterial& shiny = model.materials[0];
  EXPECT_EQ(shiny.name, "shiny");
  EXPECT_EQ(shiny.baseColor, glm::vec3(0.5f, 0.25f, 1.0f));
  EXPECT_FLOAT_EQ(shiny.metallic, 0.5f);
  EXPECT_FLOAT_EQ(shiny.roughness, 1.0f);                  // glTF's default roughnessFactor
  EXPECT_EQ(shiny.emissive, glm::vec3(1.0f, 2.0f, 4.0f));  // emissiveFactor x emissiveStrength
  EXPECT_TRUE(model.warnings.empty());                     // a supported extension
  EXPECT_FALSE(shiny.colorTexture.has_value());
  EXPECT_FALSE(shiny.normalTexture.has_value());
  EXPECT_EQ(model.materials[1].name, "plain");
  EXPECT_EQ(model.materials[1].baseColor, glm::vec3(1.0f));
  EXPECT_EQ(model.materials[2].name, "default");
}

TEST_F(GltfModelTest, what_is_not_drawn_warns_once_per_feature_and_a_required_extension_fails) {
  GltfBuilder gltf;
  json primitive = gltf.primitive(kTriangle);
  primitive["attributes"]["COLOR_0"] =
      gltf.addAccessor(packed(std::vector<float>(12, 1.0f)), kFloat, 3, "VEC4");
  primitive["targets"] = {
      {{"POSITION", gltf.addAccessor(packedVec3s(kTriangle), kFloat, 3, "VEC3")}}};
  primitive["material"] = 0;
  json bark = gltf.primitive(kTriangle);
  bark["material"] = 1;
  gltf.addMesh("tri", {primitive, bark});
  // A BLEND material beside an opaque one in one mesh, a texture on a third UV set, a sampler
  // that clamps.
  gltf.document["materials"] = {
      {{"name", "leaf"},
       {"alphaMode", "BLEND"},
       {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 2}}}}}},
      {{"name", "bark"}}};
  gltf.document["textures"] = {{{"source", 0}, {"sampler", 0}}};
  gltf.document["samplers"] = {{{"wrapS", 33071}, {"wrapT", 10497}}};
  gltf.document["images"] = {{{"uri", "data:image/png;base64," + base64(tinyPng())}}};
  gltf.document["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}}};
  gltf.document["extensionsUsed"] = {"KHR_materials_clearcoat", "EXT_fancy",
                                     "KHR_texture_transform"};
  gltf.write(root_ / "extras.gltf");
  const game::GltfModel model = game::loadGltfModel(root_ / "extras.gltf", root_);
  const std::string file = (root_ / "extras.gltf").string() + ": ";
  EXPECT_EQ(model.warnings,
            (std::vector<std::string>{
                file + "uses the extensions EXT_fancy, KHR_materials_clearcoat, which Sightline "
                       "does not support: ignored",
                file + "has 1 camera: ignored (the level's camera is used)",
                file + "has morph targets: not supported; drawn without them",
                file + "has texture samplers that wrap with CLAMP_TO_EDGE: not supported; every "
                       "texture repeats (REPEAT)",
                file + "material \"leaf\" baseColorTexture uses TEXCOORD_2; only TEXCOORD_0 and "
                       "TEXCOORD_1 are read, so TEXCOORD_0 is used",
                file + "material \"leaf\" has alphaMode BLEND next to opaque materials in the "
                       "same mesh: drawn opaque; give its part an entity of its own (\"node\" or "
                       "\"mesh\") to draw it transparent"}));
  EXPECT_FALSE(model.materials.at(0).alphaBlend);

  gltf.document["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  gltf.write(root_ / "draco.gltf");
  EXPECT_EQ(loadError(root_ / "draco.gltf"),
            (root_ / "draco.gltf").string() +
                ": requires the extension KHR_draco_mesh_compression, which Sightline cannot "
                "honour (it supports KHR_materials_emissive_strength, KHR_texture_transform)");
}

// BLEND where nothing is transparent (as the Khronos sample BoxVertexColors has it) is drawn
// opaque with a warning, not as a filter of its colour; alpha below 1 stays BLEND.
TEST_F(GltfModelTest, blend_with_an_opaque_base_colour_and_no_texture_is_drawn_opaque) {
  GltfBuilder gltf;
  json primitive = gltf.primitive(kTriangle);
  primitive["material"] = 0;
  gltf.addMesh("box", {primitive});
  gltf.document["materials"] = {
      {{"name", "Default"},
       {"alphaMode", "BLEND"},
       {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}}}}};
  gltf.write(root_ / "opaque_blend.gltf");
  const game::GltfModel opaque = game::loadGltfModel(root_ / "opaque_blend.gltf", root_);
  EXPECT_FALSE(opaque.materials.at(0).alphaBlend);
  EXPECT_EQ(opaque.warnings,
            (std::vector<std::string>{(root_ / "opaque_blend.gltf").string() +
                                      ": material \"Default\" has alphaMode BLEND with an opaque "
                                      "base colour and no base colour texture: drawn opaque "
                                      "(vertex colours' alpha is not read)"}));
  gltf.document["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {0.8, 0.8, 0.8, 0.5};
  gltf.write(root_ / "half_blend.gltf");
  const game::GltfModel half = game::loadGltfModel(root_ / "half_blend.gltf", root_);
  EXPECT_TRUE(half.materials.at(0).alphaBlend);
  EXPECT_TRUE(half.warnings.empty());
}

// A one-triangle model whose material uses image 0 as its base colour texture.
GltfBuilder texturedTriangle(const json& image) {
  GltfBuilder gltf;
  json primitive = gltf.primitive(kTriangle);
  primitive["material"] = 0;
  gltf.addMesh("Tri", {primitive});
  gltf.document["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  gltf.document["textures"] = {{{"source", 0}}};
  gltf.document["images"] = json::array({image});
  return gltf;
}

// KHR_texture_transform is read into the texture's mapping; a malformed one is an error that
// names the material, the texture and the field.
TEST_F(GltfModelTest, texture_transform_is_read_and_a_malformed_one_is_named) {
  GltfBuilder gltf = texturedTriangle({{"uri", "data:image/png;base64," + base64(tinyPng())}});
  json& info = gltf.document["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"];
  info["extensions"]["KHR_texture_transform"] = {
      {"offset", {0.25, -1}}, {"rotation", 0.5}, {"scale", {2, 3}}, {"texCoord", 1}};
  gltf.write(root_ / "moved.gltf");
  const game::GltfModel model = game::loadGltfModel(root_ / "moved.gltf", root_);
  const scene::TextureMapping& mapping = model.materials.at(0).textureMappings[0];
  EXPECT_EQ(mapping.uvSet, 1u);
  EXPECT_EQ(mapping.offset, glm::vec2(0.25f, -1.0f));
  EXPECT_EQ(mapping.rotationRadians, 0.5f);
  EXPECT_EQ(mapping.scale, glm::vec2(2.0f, 3.0f));
  EXPECT_TRUE(model.warnings.empty());

  info["extensions"]["KHR_texture_transform"] = {{"offset", {0.25}}};
  gltf.write(root_ / "short.gltf");
  EXPECT_EQ(loadError(root_ / "short.gltf"),
            (root_ / "short.gltf").string() +
                ": material 0 baseColorTexture KHR_texture_transform offset must be an array of 2 "
                "numbers in [-1e6, 1e6]");
  info["extensions"]["KHR_texture_transform"] = {{"texCoord", 0.5}};
  gltf.write(root_ / "half.gltf");
  EXPECT_EQ(loadError(root_ / "half.gltf"),
            (root_ / "half.gltf").string() +
                ": material 0 baseColorTexture KHR_texture_transform texCoord must be a whole "
                "number >= 0");
}

TEST_F(GltfModelTest, embedded_data_uri_image_is_decoded) {
  texturedTriangle({{"uri", "data:image/png;base64," + base64(tinyPng())}})
      .write(root_ / "embedded.gltf");
  const game::GltfModel model = game::loadGltfModel(root_ / "embedded.gltf", root_);
  ASSERT_TRUE(!model.materials.empty() && model.materials.front().colorTexture);
  const scene::TextureDesc& texture = *model.materials.front().colorTexture;
  EXPECT_EQ(texture.name, (root_ / "embedded.gltf").string() + " image 0");
  EXPECT_EQ(texture.rgba, (std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 255}));
  EXPECT_EQ(model.filesRead, std::vector<fs::path>{root_ / "embedded.gltf"});
}

TEST_F(GltfModelTest, glb_image_in_a_buffer_view_is_decoded) {
  GltfBuilder gltf = texturedTriangle(json::object());
  gltf.document["images"][0] = {{"bufferView", gltf.addView(tinyPng())}, {"mimeType", "image/png"}};
  gltf.document["buffers"] = {{{"byteLength", gltf.buffer.size()}}};  // the BIN chunk
  std::string text = gltf.document.dump();
  text.resize((text.size() + 3) / 4 * 4, ' ');
  std::string bin = gltf.buffer;
  bin.resize((bin.size() + 3) / 4 * 4, '\0');
  const auto u32 = [](std::size_t value) {
    const uint32_t v = static_cast<uint32_t>(value);
    return std::string(reinterpret_cast<const char*>(&v), 4);
  };
  writeFile(root_ / "tri.glb", "glTF" + u32(2) + u32(12 + 8 + text.size() + 8 + bin.size()) +
                                   u32(text.size()) + "JSON" + text + u32(bin.size()) +
                                   std::string("BIN\0", 4) + bin);
  const game::GltfModel model = game::loadGltfModel(root_ / "tri.glb", root_);
  ASSERT_TRUE(!model.materials.empty() && model.materials.front().colorTexture);
  EXPECT_EQ(model.materials.front().colorTexture->rgba,
            (std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 255}));
}

TEST_F(GltfModelTest, image_uri_outside_the_allowed_root_is_refused) {
  writeFile(root_.parent_path() / (root_.filename().string() + "-secret.png"), tinyPng());
  texturedTriangle({{"uri", "../" + root_.filename().string() + "-secret.png"}})
      .write(root_ / "sneaky.gltf");
  const std::string error = loadError(root_ / "sneaky.gltf");
  fs::remove(root_.parent_path() / (root_.filename().string() + "-secret.png"));
  EXPECT_EQ(error.rfind((root_ / "sneaky.gltf").string() + ": refers to \"", 0), 0u) << error;
  EXPECT_NE(error.find("-secret.png\", which is outside the directory the model was found in"),
            std::string::npos)
      << error;
}

TEST_F(GltfModelTest, missing_or_bad_images_are_errors_naming_model_and_image) {
  const std::string prefix = (root_ / "m.gltf").string() + ": material 0 baseColorTexture";
  texturedTriangle({{"uri", "nowhere.png"}}).write(root_ / "m.gltf");
  EXPECT_EQ(loadError(root_ / "m.gltf"),
            prefix + " image 0 \"nowhere.png\" was not found or could not be read");

  writeFile(root_ / "half.png", tinyPng().substr(0, 40));
  texturedTriangle({{"uri", "half.png"}}).write(root_ / "m.gltf");
  EXPECT_EQ(
      loadError(root_ / "m.gltf")
          .rfind(prefix + ": " + (root_ / "half.png").string() + ": cannot decode the PNG image",
                 0),
      0u);
}

TEST_F(GltfModelTest, oversized_embedded_image_is_refused_before_decoding) {
  // Signature and IHDR of a 5000x5000 RGBA PNG and nothing else: only the header is read.
  const std::string header =
      std::string("\x89PNG\r\n\x1a\n", 8) +
      std::string("\0\0\0\x0dIHDR\0\0\x13\x88\0\0\x13\x88\x08\x06\0\0\0", 21) +
      std::string(4, '\0');
  texturedTriangle({{"uri", "data:image/png;base64," + base64(header)}}).write(root_ / "big.gltf");
  const std::string file = (root_ / "big.gltf").string();
  EXPECT_EQ(loadError(root_ / "big.gltf"),
            file + ": material 0 baseColorTexture: " + file +
                " image 0: image is 5000x5000; textures are limited to 4096x4096");
}

TEST_F(GltfModelTest, texture_that_names_no_image_is_an_error) {
  GltfBuilder gltf = texturedTriangle({{"uri", "data:image/png;base64," + base64(tinyPng())}});
  gltf.document["textures"][0].erase("source");
  gltf.write(root_ / "m.gltf");
  EXPECT_EQ(loadError(root_ / "m.gltf"), (root_ / "m.gltf").string() +
                                             ": material 0 baseColorTexture uses texture 0, "
                                             "which has no PNG or JPEG image");
}

TEST_F(GltfModelTest, external_buffer_and_image_are_listed_in_files_read) {
  GltfBuilder gltf = texturedTriangle({{"uri", "textures/tiny.png"}});
  writeFile(root_ / "textures" / "tiny.png", tinyPng());
  gltf.document["buffers"] = {{{"byteLength", gltf.buffer.size()}, {"uri", "tri.bin"}}};
  writeFile(root_ / "tri.bin", gltf.buffer);
  writeFile(root_ / "tri.gltf", gltf.document.dump());
  const game::GltfModel model = game::loadGltfModel(root_ / "tri.gltf", root_);
  EXPECT_EQ(model.filesRead, (std::vector<fs::path>{root_ / "tri.gltf", root_ / "tri.bin",
                                                    root_ / "textures" / "tiny.png"}));
  EXPECT_EQ(model.materials.front().colorTexture->name, (root_ / "textures" / "tiny.png").string());
  EXPECT_EQ(readFile(root_ / "tri.bin"), gltf.buffer);
}

}  // namespace
