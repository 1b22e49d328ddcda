// Tests for the JSON level loader, the built-in primitives and the glTF mesh loader.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "game/gltf_mesh.hpp"
#include "game/json_positions.hpp"
#include "game/level.hpp"
#include "game/level_loader.hpp"
#include "game/primitives.hpp"
#include "render/color.hpp"

namespace {

namespace fs = std::filesystem;

// The smallest valid level; error tests swap one piece of it for something wrong.
const std::string kMinimalLevel = R"({
  "format": 1,
  "name": "Test",
  "camera": {"position": [0, 1, 5]},
  "materials": {"grey": {"color": [0.5, 0.5, 0.5]}},
  "meshes": {"cube": {"box": {"size": [1, 1, 1]}}},
  "entities": {"crate": {"mesh": "cube", "material": "grey"}},
  "lights": {}
}
)";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "test bug: \"" << from << "\" not in the level";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The message parseLevel throws, or a note that it threw nothing.
std::string parseError(const std::string& text, const fs::path& file = "levels/test.json",
                       const game::LevelLoadOptions& options = {}) {
  try {
    game::parseLevel(text, file, options);
  } catch (const game::LevelError& error) {
    return error.what();
  }
  return "(no error)";
}

std::string loadError(const fs::path& file, const game::LevelLoadOptions& options = {}) {
  try {
    game::loadLevel(file, options);
  } catch (const game::LevelError& error) {
    return error.what();
  }
  return "(no error)";
}

void writeFile(const fs::path& path, const std::string& contents) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << contents;
}

// A fresh directory per test, removed afterwards.
class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::temp_directory_path() / ("sightline-" + std::string(info->name()) + "-" +
                                         std::to_string(std::random_device{}()));
    fs::create_directories(root_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }
  fs::path root_;
};

// ----- glTF writing helpers -----

std::string base64(const std::string& bytes) {
  static const char* const alphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string encoded;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t group = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) group |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) group |= static_cast<unsigned char>(bytes[i + 2]);
    encoded += alphabet[(group >> 18) & 63];
    encoded += alphabet[(group >> 12) & 63];
    encoded += i + 1 < bytes.size() ? alphabet[(group >> 6) & 63] : '=';
    encoded += i + 2 < bytes.size() ? alphabet[group & 63] : '=';
  }
  return encoded;
}

enum class IndexType { None = 0, U8 = 5121, U16 = 5123, U32 = 5125 };

template <typename T>
void appendBytes(std::string& bytes, const T& value) {
  bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// A glTF document holding `mesh` (positions only, so the loader must compute normals) in one
// buffer; accessor 0 holds positions, accessor 1 the indices.
struct GltfFile {
  nlohmann::json document;
  std::string buffer;
};

GltfFile makeGltf(const render::MeshData& mesh, IndexType indexType) {
  GltfFile file;
  for (const auto& vertex : mesh.vertices) {
    for (int axis = 0; axis < 3; ++axis) appendBytes(file.buffer, vertex.position[axis]);
  }
  const std::size_t positionBytes = file.buffer.size();
  for (const uint32_t index : mesh.indices) {
    if (indexType == IndexType::U8) appendBytes(file.buffer, static_cast<uint8_t>(index));
    if (indexType == IndexType::U16) appendBytes(file.buffer, static_cast<uint16_t>(index));
    if (indexType == IndexType::U32) appendBytes(file.buffer, index);
  }
  const std::size_t indexBytes = file.buffer.size() - positionBytes;

  nlohmann::json primitive = {{"attributes", {{"POSITION", 0}}}};
  nlohmann::json accessors = nlohmann::json::array();
  nlohmann::json views = nlohmann::json::array();
  views.push_back({{"buffer", 0}, {"byteOffset", 0}, {"byteLength", positionBytes}});
  accessors.push_back({{"bufferView", 0},
                       {"componentType", 5126},
                       {"count", mesh.vertices.size()},
                       {"type", "VEC3"}});
  if (indexType != IndexType::None) {
    views.push_back({{"buffer", 0}, {"byteOffset", positionBytes}, {"byteLength", indexBytes}});
    accessors.push_back({{"bufferView", 1},
                         {"componentType", static_cast<int>(indexType)},
                         {"count", mesh.indices.size()},
                         {"type", "SCALAR"}});
    primitive["indices"] = 1;
  }
  file.document = {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"meshes", {{{"name", "Cube"}, {"primitives", {primitive}}}}},
      {"buffers", {{{"byteLength", file.buffer.size()}}}},
      {"bufferViews", views},
      {"accessors", accessors},
  };
  return file;
}

// Writes `path`; the buffer goes next to it as <stem>.bin unless `embedded`.
void writeGltf(const fs::path& path, GltfFile file, bool embedded) {
  if (embedded) {
    file.document["buffers"][0]["uri"] =
        "data:application/octet-stream;base64," + base64(file.buffer);
  } else {
    const std::string binName = path.stem().string() + ".bin";
    file.document["buffers"][0]["uri"] = binName;
    writeFile(path.parent_path() / binName, file.buffer);
  }
  writeFile(path, file.document.dump(2));
}

// A mesh with no holes is closed around `center` when every face points away from it.
void expectOutwardFacing(const render::MeshData& mesh, const glm::vec3& center = glm::vec3(0.0f)) {
  ASSERT_EQ(mesh.indices.size() % 3, 0u);
  for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
    const glm::vec3 a = mesh.vertices.at(mesh.indices[i]).position;
    const glm::vec3 b = mesh.vertices.at(mesh.indices[i + 1]).position;
    const glm::vec3 c = mesh.vertices.at(mesh.indices[i + 2]).position;
    const glm::vec3 faceNormal = glm::cross(b - a, c - a);
    ASSERT_GT(glm::length(faceNormal), 0.0f) << "degenerate triangle " << i / 3;
    ASSERT_GT(glm::dot(faceNormal, (a + b + c) / 3.0f - center), 0.0f)
        << "triangle " << i / 3 << " is clockwise seen from outside";
  }
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const auto& vertex = mesh.vertices[i];
    ASSERT_NEAR(glm::length(vertex.normal), 1.0f, 1e-5f) << "vertex " << i;
    ASSERT_GT(glm::dot(vertex.normal, vertex.position - center), 0.0f)
        << "vertex " << i << " has an inward normal";
  }
}

// ----- colour -----

TEST(Color, srgb_conversion_uses_the_exact_curves) {
  EXPECT_FLOAT_EQ(render::srgbToLinear(0.5f), 0.21404114f);
  EXPECT_FLOAT_EQ(render::srgbToLinear(0.04045f), 0.04045f / 12.92f);  // linear segment
  EXPECT_FLOAT_EQ(render::srgbToLinear(1.0f), 1.0f);
  EXPECT_FLOAT_EQ(render::srgbToLinear(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(render::linearToSrgb(0.002f), 12.92f * 0.002f);
  EXPECT_FLOAT_EQ(render::linearToSrgb(0.21404114f), 0.5f);
  const glm::vec3 linear = render::srgbToLinear(glm::vec3(0.2f, 0.5f, 1.0f));
  EXPECT_FLOAT_EQ(linear.x, 0.033104767f);
  EXPECT_FLOAT_EQ(linear.y, 0.21404114f);
  EXPECT_FLOAT_EQ(linear.z, 1.0f);
}

// ----- a valid level -----

TEST(LevelLoader, loader_reads_a_complete_level_with_every_value_converted) {
  const std::string text = R"({
  "format": 1,
  "name": "First Light",
  "description": "A room with a lamp.",
  "camera": {"position": [1, 2, 3], "yaw_degrees": 30, "pitch_degrees": -10, "fov_degrees": 70},
  "environment": {"sky_zenith": "#ff8000", "ambient": [0.5, 0.5, 0.5]},
  "materials": {
    "stone": {"color": [0.5, 0.2, 1.0]},
    "lamp": {"color": "#FFFFFF", "specular": 0.25, "roughness": 1, "emissive": [0.5, 1, 0],
             "emissive_strength": 4}
  },
  "meshes": {
    "floor": {"plane": {"size": [10, 20]}},
    "ball": {"sphere": {"radius": 0.5, "segments": 8, "rings": 4}},
    "post": {"cylinder": {"radius": 0.1, "height": 2, "segments": 6}},
    "crate": {"box": {"size": [1, 2, 3]}}
  },
  "entities": {
    "ground": {"mesh": "floor", "material": "stone"},
    "bulb": {"mesh": "ball", "material": "lamp", "position": [0, 3, 0],
             "rotation_degrees": [10, 20, 30], "scale": 2},
    "box1": {"mesh": "crate", "material": "stone", "scale": [1, 2, 3]}
  },
  "lights": {
    "sun": {"type": "directional", "direction": [0, -2, 0], "intensity": 3},
    "bulb_light": {"type": "point", "position": [0, 3, 0], "color": [1, 0.5, 0], "intensity": 60}
  }
}
)";
  const game::Level level = game::parseLevel(text, "levels/first.json");
  EXPECT_EQ(level.file, fs::path("levels/first.json"));
  EXPECT_EQ(level.format, 1);
  EXPECT_EQ(level.name, "First Light");
  EXPECT_EQ(level.description, "A room with a lamp.");
  EXPECT_EQ(level.camera.position, glm::vec3(1, 2, 3));
  EXPECT_FLOAT_EQ(level.camera.yawDegrees, 30.0f);
  EXPECT_FLOAT_EQ(level.camera.pitchDegrees, -10.0f);
  EXPECT_FLOAT_EQ(level.camera.verticalFovDegrees, 70.0f);

  EXPECT_FLOAT_EQ(level.environment.skyZenith.r, 1.0f);
  EXPECT_FLOAT_EQ(level.environment.skyZenith.g, 0.2158605f);  // 0x80 = 128/255
  EXPECT_FLOAT_EQ(level.environment.skyZenith.b, 0.0f);
  EXPECT_EQ(level.environment.skyHorizon, glm::vec3(0.0f));  // defaults to black
  EXPECT_FLOAT_EQ(level.environment.ambient.g, 0.21404114f);

  ASSERT_EQ(level.materialIds, (std::vector<std::string>{"stone", "lamp"}));
  ASSERT_EQ(level.materials.size(), 2u);
  EXPECT_FLOAT_EQ(level.materials[0].baseColor.r, 0.21404114f);
  EXPECT_FLOAT_EQ(level.materials[0].baseColor.g, 0.033104767f);
  EXPECT_FLOAT_EQ(level.materials[0].baseColor.b, 1.0f);
  EXPECT_FLOAT_EQ(level.materials[0].specular, 0.0f);
  EXPECT_FLOAT_EQ(level.materials[0].roughness, 0.5f);
  EXPECT_EQ(level.materials[0].emissive, glm::vec3(0.0f));
  EXPECT_EQ(level.materials[1].baseColor, glm::vec3(1.0f));
  EXPECT_FLOAT_EQ(level.materials[1].specular, 0.25f);
  EXPECT_FLOAT_EQ(level.materials[1].roughness, 1.0f);
  EXPECT_FLOAT_EQ(level.materials[1].emissive.r, 4.0f * 0.21404114f);  // linear, then scaled
  EXPECT_FLOAT_EQ(level.materials[1].emissive.g, 4.0f);
  EXPECT_FLOAT_EQ(level.materials[1].emissive.b, 0.0f);

  ASSERT_EQ(level.meshIds, (std::vector<std::string>{"floor", "ball", "post", "crate"}));
  EXPECT_EQ(level.meshes[0].vertices.size(), 4u);
  EXPECT_EQ(level.meshes[0].vertices[2].position, glm::vec3(5, 0, -10));
  EXPECT_EQ(level.meshes[1].vertices.size(), 5u * 9u);
  EXPECT_EQ(level.meshes[1].indices.size(), 6u * 8u * 3u);
  EXPECT_EQ(level.meshes[2].indices.size(), 12u * 6u);
  EXPECT_EQ(level.meshes[3].name, "crate");

  ASSERT_EQ(level.entities.size(), 3u);
  EXPECT_EQ(level.entities[0].id, "ground");
  EXPECT_EQ(level.entities[0].mesh, 0u);
  EXPECT_EQ(level.entities[0].material, 0u);
  EXPECT_EQ(level.entities[0].position, glm::vec3(0.0f));
  EXPECT_EQ(level.entities[0].scale, glm::vec3(1.0f));
  EXPECT_EQ(level.entities[1].id, "bulb");
  EXPECT_EQ(level.entities[1].mesh, 1u);
  EXPECT_EQ(level.entities[1].material, 1u);
  EXPECT_EQ(level.entities[1].position, glm::vec3(0, 3, 0));
  EXPECT_EQ(level.entities[1].rotationDegrees, glm::vec3(10, 20, 30));  // pitch, yaw, roll
  EXPECT_EQ(level.entities[1].scale, glm::vec3(2.0f));
  EXPECT_EQ(level.entities[2].mesh, 3u);
  EXPECT_EQ(level.entities[2].scale, glm::vec3(1, 2, 3));

  ASSERT_EQ(level.lightIds, (std::vector<std::string>{"sun", "bulb_light"}));
  EXPECT_EQ(level.lights[0].type, render::LightType::Directional);
  EXPECT_EQ(level.lights[0].direction, glm::vec3(0, -1, 0));  // normalised
  EXPECT_EQ(level.lights[0].color, glm::vec3(1.0f));          // white by default
  EXPECT_FLOAT_EQ(level.lights[0].intensity, 3.0f);
  EXPECT_EQ(level.lights[1].type, render::LightType::Point);
  EXPECT_EQ(level.lights[1].position, glm::vec3(0, 3, 0));
  EXPECT_FLOAT_EQ(level.lights[1].color.g, 0.21404114f);
  EXPECT_FLOAT_EQ(level.lights[1].intensity, 60.0f);
}

TEST(LevelLoader, optional_camera_values_take_their_defaults) {
  const game::Level level = game::parseLevel(kMinimalLevel, "levels/test.json");
  EXPECT_FLOAT_EQ(level.camera.yawDegrees, 0.0f);
  EXPECT_FLOAT_EQ(level.camera.pitchDegrees, 0.0f);
  EXPECT_FLOAT_EQ(level.camera.verticalFovDegrees, 60.0f);
  EXPECT_EQ(level.environment.ambient, glm::vec3(0.0f));
  EXPECT_TRUE(level.lights.empty());
  EXPECT_TRUE(level.description.empty());
}

TEST(LevelLoader, ids_keep_the_order_they_have_in_the_file) {
  const std::string text =
      replaced(kMinimalLevel, R"("materials": {"grey": {"color": [0.5, 0.5, 0.5]}})",
               R"("materials": {"zeta": {"color": "#000000"}, "alpha": {"color": "#000000"},
                       "grey": {"color": "#000000"}})");
  EXPECT_EQ(game::parseLevel(text, "levels/test.json").materialIds,
            (std::vector<std::string>{"zeta", "alpha", "grey"}));
}

TEST(LevelLoader, entity_transform_applies_scale_then_roll_pitch_yaw_then_translation) {
  game::Entity entity;
  entity.position = {1, 2, 3};
  entity.rotationDegrees = {0, 90, 0};  // yaw only: +X turns to -Z
  entity.scale = glm::vec3(2.0f);
  const glm::vec4 moved = game::entityTransform(entity) * glm::vec4(1, 0, 0, 1);
  EXPECT_NEAR(moved.x, 1.0f, 1e-6f);
  EXPECT_NEAR(moved.y, 2.0f, 1e-6f);
  EXPECT_NEAR(moved.z, 1.0f, 1e-6f);

  game::Entity pitchedAndYawed;
  pitchedAndYawed.rotationDegrees = {90, 90, 0};  // pitch +Y to +Z, then yaw +Z to +X
  const glm::vec4 up = game::entityTransform(pitchedAndYawed) * glm::vec4(0, 1, 0, 0);
  EXPECT_NEAR(up.x, 1.0f, 1e-6f);
  EXPECT_NEAR(up.y, 0.0f, 1e-6f);
  EXPECT_NEAR(up.z, 0.0f, 1e-6f);

  game::Entity rolledAndPitched;
  rolledAndPitched.rotationDegrees = {90, 0, 90};  // roll +X to +Y, then pitch +Y to +Z
  const glm::vec4 right = game::entityTransform(rolledAndPitched) * glm::vec4(1, 0, 0, 0);
  EXPECT_NEAR(right.x, 0.0f, 1e-6f);
  EXPECT_NEAR(right.y, 0.0f, 1e-6f);
  EXPECT_NEAR(right.z, 1.0f, 1e-6f);
}

TEST(LevelLoader, scene_description_has_one_instance_per_entity) {
  const std::string text =
      replaced(kMinimalLevel, R"("entities": {"crate": {"mesh": "cube", "material": "grey"}})",
               R"("entities": {"a": {"mesh": "cube", "material": "grey"},
                      "b": {"mesh": "cube", "material": "grey", "position": [4, 5, 6]}},
  "environment": {"ambient": "#ffffff"})");
  const game::Level level = game::parseLevel(text, "levels/test.json");
  const render::SceneDesc scene = game::buildSceneDesc(level);
  EXPECT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].indices.size(), 36u);
  EXPECT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.environment.ambient, glm::vec3(1.0f));
  ASSERT_EQ(scene.instances.size(), 2u);
  EXPECT_EQ(scene.instances[1].mesh, 0u);
  EXPECT_EQ(scene.instances[1].material, 0u);
  EXPECT_EQ(scene.instances[1].objectToWorld[3], glm::vec4(4, 5, 6, 1));
  EXPECT_EQ(scene.instances[1].objectToWorld, game::entityTransform(level.entities[1]));
}

// ----- primitives -----

TEST(Primitives, box_has_flat_outward_faces) {
  const render::MeshData box = game::primitives::box({2, 4, 6});
  EXPECT_EQ(box.vertices.size(), 24u);
  EXPECT_EQ(box.indices.size(), 36u);
  expectOutwardFacing(box);
  for (const auto& vertex : box.vertices) {
    EXPECT_FLOAT_EQ(std::abs(vertex.position.x), 1.0f);
    EXPECT_FLOAT_EQ(std::abs(vertex.position.y), 2.0f);
    EXPECT_FLOAT_EQ(std::abs(vertex.position.z), 3.0f);
  }
}

TEST(Primitives, sphere_has_smooth_outward_normals) {
  const render::MeshData sphere = game::primitives::sphere(2.0f, 12, 6);
  EXPECT_EQ(sphere.vertices.size(), 7u * 13u);
  EXPECT_EQ(sphere.indices.size(), 6u * 12u * 5u);
  expectOutwardFacing(sphere);
  for (const auto& vertex : sphere.vertices) {
    EXPECT_NEAR(glm::length(vertex.position), 2.0f, 1e-5f);
    EXPECT_NEAR(glm::length(vertex.normal - vertex.position / 2.0f), 0.0f, 1e-5f);
  }
}

TEST(Primitives, plane_faces_up) {
  const render::MeshData plane = game::primitives::plane(4.0f, 2.0f);
  EXPECT_EQ(plane.vertices.size(), 4u);
  EXPECT_EQ(plane.indices.size(), 6u);
  for (const auto& vertex : plane.vertices) {
    EXPECT_EQ(vertex.normal, glm::vec3(0, 1, 0));
    EXPECT_FLOAT_EQ(std::abs(vertex.position.x), 2.0f);
    EXPECT_FLOAT_EQ(vertex.position.y, 0.0f);
    EXPECT_FLOAT_EQ(std::abs(vertex.position.z), 1.0f);
  }
  expectOutwardFacing(plane, {0, -1, 0});  // seen from above
}

TEST(Primitives, cylinder_has_smooth_sides_and_flat_caps) {
  const render::MeshData cylinder = game::primitives::cylinder(1.0f, 3.0f, 8);
  EXPECT_EQ(cylinder.vertices.size(), 4u * 9u);
  EXPECT_EQ(cylinder.indices.size(), 12u * 8u);
  expectOutwardFacing(cylinder);
  int capVertices = 0;
  for (const auto& vertex : cylinder.vertices) {
    EXPECT_FLOAT_EQ(std::abs(vertex.position.y), 1.5f);
    if (std::abs(vertex.normal.y) == 1.0f) {
      ++capVertices;
    } else {
      EXPECT_FLOAT_EQ(vertex.normal.y, 0.0f);
    }
  }
  EXPECT_EQ(capVertices, 2 * 9);
}

// ----- source positions -----

TEST(JsonPositions, scanner_finds_values_keys_and_array_elements) {
  const std::string text = "{\n  \"a\": [1, {\"b~/c\": \"x\"}],\n  \"d\": {}\n}";
  const game::JsonPositions positions = game::JsonPositions::scan(text);
  auto expectAt = [](game::SourcePosition at, int line, int column) {
    EXPECT_EQ(at.line, line);
    EXPECT_EQ(at.column, column);
  };
  expectAt(positions.valueAt(""), 1, 1);
  expectAt(positions.valueAt("/a"), 2, 8);
  expectAt(positions.keyAt("/a"), 2, 3);
  expectAt(positions.valueAt("/a/0"), 2, 9);
  expectAt(positions.valueAt("/a/1"), 2, 12);
  expectAt(positions.valueAt("/a/1/b~0~1c"), 2, 21);
  expectAt(positions.valueAt("/d"), 3, 8);
  expectAt(positions.valueAt("/d/missing"), 3, 8);  // falls back to the enclosing value
  EXPECT_FALSE(positions.firstDuplicateKey().has_value());
}

// ----- error messages -----

TEST(LevelErrors, loader_reports_line_and_column_of_bad_value) {
  const std::string text = R"({
  "format": 1,
  "name": "Glass",
  "camera": {"position": [0, 1, 5]},
  "materials": {
    "glass": {"color": [1, 1, 1], "roughness": "1,5"}
  },
  "meshes": {"cube": {"box": {"size": [1, 1, 1]}}},
  "entities": {"crate": {"mesh": "cube", "material": "glass"}},
  "lights": {}
}
)";
  EXPECT_EQ(parseError(text, "levels/03.json"),
            "levels/03.json:6:48: /materials/glass/roughness: expected a number in (0, 1], got "
            "\"1,5\"");
}

TEST(LevelErrors, syntax_error_reports_line_and_column_and_nlohmanns_reason) {
  const std::string text = "{\n  \"format\": 1,\n  \"name\": x\n}";
  EXPECT_EQ(parseError(text, "levels/bad.json"),
            "levels/bad.json:3:11: invalid JSON: syntax error while parsing value - invalid "
            "literal; last read: '\"name\": x'");
}

TEST(LevelErrors, truncated_file_is_a_syntax_error_at_its_end) {
  EXPECT_EQ(parseError("{\n  \"format\": 1,\n", "levels/cut.json"),
            "levels/cut.json:3:1: invalid JSON: syntax error while parsing object key - "
            "unexpected end of input; expected string literal");
}

TEST(LevelErrors, unknown_key_is_named_with_the_allowed_keys) {
  const std::string text =
      replaced(kMinimalLevel, R"({"color": [0.5, 0.5, 0.5]})", R"({"colour": [0.5, 0.5, 0.5]})");
  EXPECT_EQ(parseError(text),
            "levels/test.json:5:26: /materials/grey/colour: unknown key \"colour\"; allowed keys: "
            "color, specular, roughness, emissive, emissive_strength");
}

TEST(LevelErrors, missing_required_key_points_at_its_object) {
  const std::string text = replaced(kMinimalLevel, R"("camera": {"position": [0, 1, 5]})",
                                    R"("camera": {"fov_degrees": 50})");
  EXPECT_EQ(parseError(text), "levels/test.json:4:13: /camera: missing required key \"position\"");
}

TEST(LevelErrors, entity_with_unknown_mesh_lists_the_known_meshes) {
  const std::string text = replaced(kMinimalLevel, R"("mesh": "cube")", R"("mesh": "cub")");
  EXPECT_EQ(parseError(text),
            "levels/test.json:7:34: /entities/crate/mesh: unknown mesh \"cub\"; known meshes: "
            "\"cube\"");
}

TEST(LevelErrors, entity_with_unknown_material_lists_the_known_materials) {
  const std::string text =
      replaced(kMinimalLevel, R"("material": "grey")", R"("material": "gray")");
  EXPECT_NE(parseError(text).find("/entities/crate/material: unknown material \"gray\"; known "
                                  "materials: \"grey\""),
            std::string::npos);
}

TEST(LevelErrors, colour_errors_say_what_a_colour_is) {
  EXPECT_EQ(parseError(replaced(kMinimalLevel, "[0.5, 0.5, 0.5]", "\"#12345\"")),
            "levels/test.json:5:35: /materials/grey/color: expected a colour: [r, g, b] with "
            "components in [0, 1] or a string \"#rrggbb\", got \"#12345\"");
  EXPECT_EQ(parseError(replaced(kMinimalLevel, "[0.5, 0.5, 0.5]", "[0.5, 1.5, 0.5]")),
            "levels/test.json:5:41: /materials/grey/color/1: expected a number in [0, 1], got 1.5");
}

TEST(LevelErrors, number_rules_name_their_range) {
  auto cameraError = [](const std::string& camera) {
    return parseError(replaced(kMinimalLevel, R"({"position": [0, 1, 5]})", camera));
  };
  EXPECT_NE(cameraError(R"({"position": [0, 1, 5], "fov_degrees": 0})")
                .find("/camera/fov_degrees: expected a number in (0, 179], got 0"),
            std::string::npos);
  EXPECT_NE(cameraError(R"({"position": [0, 1, 5], "fov_degrees": 180})")
                .find("/camera/fov_degrees: expected a number in (0, 179], got 180"),
            std::string::npos);
  EXPECT_EQ(cameraError(R"({"position": [0, 1e999, 5]})"),
            "levels/test.json:4:30: invalid JSON: number overflow parsing '1e999'");
  EXPECT_NE(cameraError(R"({"position": [0, 1e300, 5]})")
                .find("/camera/position/1: expected a 32-bit float, got 1e+300"),
            std::string::npos);
  EXPECT_NE(cameraError(R"({"position": [0, 1]})")
                .find("/camera/position: expected an array of 3 numbers [x, y, z], got [0,1]"),
            std::string::npos);
  EXPECT_NE(cameraError(R"({"position": [0, true, 5]})")
                .find("/camera/position/1: expected a number, got true"),
            std::string::npos);
}

TEST(LevelErrors, tessellation_counts_must_be_integers_in_range) {
  auto meshError = [](const std::string& mesh) {
    return parseError(replaced(kMinimalLevel, R"({"box": {"size": [1, 1, 1]}})", mesh));
  };
  EXPECT_NE(meshError(R"({"sphere": {"radius": 1, "segments": 2.5}})")
                .find("/meshes/cube/sphere/segments: expected an integer in [3, 4096], got 2.5"),
            std::string::npos);
  EXPECT_NE(meshError(R"({"sphere": {"radius": 1, "rings": 1}})")
                .find("/meshes/cube/sphere/rings: expected an integer in [2, 2048], got 1"),
            std::string::npos);
  EXPECT_NE(
      meshError(R"({"cylinder": {"radius": 1, "height": 1, "segments": 99999999999999999999}})")
          .find("/meshes/cube/cylinder/segments: expected an integer in [3, 4096]"),
      std::string::npos);
  EXPECT_NE(meshError(R"({"box": {"size": [1, 0, 1]}})")
                .find("/meshes/cube/box/size/1: expected a number > 0, got 0"),
            std::string::npos);
  EXPECT_NE(meshError(R"({"plane": {"size": [1, 1, 1]}})")
                .find("/meshes/cube/plane/size: expected an array of 2 numbers [width, depth]"),
            std::string::npos);
}

TEST(LevelErrors, mesh_must_have_exactly_one_shape) {
  auto meshError = [](const std::string& mesh) {
    return parseError(replaced(kMinimalLevel, R"({"box": {"size": [1, 1, 1]}})", mesh));
  };
  EXPECT_EQ(meshError(R"({"box": {"size": [1, 1, 1]}, "sphere": {"radius": 1}})"),
            "levels/test.json:6:22: /meshes/cube: expected exactly one of \"box\", \"sphere\", "
            "\"plane\", \"cylinder\", \"gltf\", got \"box\", \"sphere\"");
  EXPECT_NE(meshError("{}").find("/meshes/cube: expected exactly one of"), std::string::npos);
  EXPECT_NE(meshError(R"({"box": {"size": [1, 1, 1]}, "mesh": "Body"})")
                .find("/meshes/cube/mesh: \"mesh\" picks a mesh inside a glTF file and needs "
                      "\"gltf\""),
            std::string::npos);
}

TEST(LevelErrors, scale_and_light_values_are_checked) {
  EXPECT_NE(parseError(replaced(kMinimalLevel, R"("material": "grey")",
                                R"("material": "grey", "scale": 0)"))
                .find("/entities/crate/scale: expected a number > 0, got 0"),
            std::string::npos);
  EXPECT_NE(parseError(replaced(kMinimalLevel, R"("material": "grey")",
                                R"("material": "grey", "scale": "big")"))
                .find("/entities/crate/scale: expected a number > 0 or an array of 3 numbers > 0, "
                      "got \"big\""),
            std::string::npos);
  auto lightError = [](const std::string& light) {
    return parseError(
        replaced(kMinimalLevel, R"("lights": {})", R"("lights": {"l": )" + light + "}"));
  };
  EXPECT_NE(lightError(R"({"type": "directional", "direction": [0, 0, 0], "intensity": 1})")
                .find("/lights/l/direction: expected a non-zero direction [x, y, z], got [0,0,0]"),
            std::string::npos);
  EXPECT_NE(lightError(R"({"type": "spot", "intensity": 1})")
                .find("/lights/l/type: expected \"point\" or \"directional\", got \"spot\""),
            std::string::npos);
  EXPECT_NE(lightError(R"({"type": "point", "position": [0, 0, 0], "intensity": -1})")
                .find("/lights/l/intensity: expected a number >= 0, got -1"),
            std::string::npos);
  EXPECT_NE(lightError(R"({"type": "point", "direction": [0, 0, 1], "intensity": 1})")
                .find("/lights/l/direction: unknown key \"direction\"; allowed keys: type, "
                      "position, color, intensity"),
            std::string::npos);
}

TEST(LevelErrors, ids_format_and_structure_are_checked) {
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"("grey": {)", R"("gr ey": {)")),
            "levels/test.json:5:17: /materials/gr ey: invalid material id \"gr ey\": ids are "
            "non-empty and use only letters, digits, '_' and '-'");
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"("format": 1)", R"("format": 2)")),
            "levels/test.json:2:13: /format: unsupported format 2; this version reads format 1");
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"("name": "Test")", R"("name": "")")),
            "levels/test.json:3:11: /name: expected a non-empty string, got \"\"");
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"({"crate": {"mesh": "cube", "material": "grey"}})",
                                "{}")),
            "levels/test.json:7:15: /entities: a level needs at least one entity, got {}");
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"("name": "Test")", R"("name": "A", "name": "B")")),
            "levels/test.json:3:16: /name: duplicate key \"name\"");
  EXPECT_EQ(parseError("[1, 2]"), "levels/test.json:1:1: /: expected an object, got [1,2]");
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"(  "format": 1,)", "")),
            "levels/test.json:1:1: /: missing required key \"format\"");
}

TEST_F(TempDirTest, loader_reports_files_it_cannot_open_or_that_are_too_large) {
  EXPECT_EQ(loadError(root_ / "missing.json"),
            (root_ / "missing.json").string() + ": cannot open level file");
  EXPECT_EQ(loadError(root_), root_.string() + ": cannot open level file");
  const fs::path huge = root_ / "huge.json";
  writeFile(huge, std::string((16u << 20) + 1, ' '));
  EXPECT_EQ(loadError(huge), huge.string() + ": level file is larger than the 16 MiB limit");
  EXPECT_EQ(parseError(std::string((16u << 20) + 1, ' ')),
            "levels/test.json: level file is larger than the 16 MiB limit");
}

TEST_F(TempDirTest, loader_reads_a_level_file_from_disk) {
  writeFile(root_ / "levels" / "one.json", kMinimalLevel);
  const game::Level level = game::loadLevel(root_ / "levels" / "one.json");
  EXPECT_EQ(level.name, "Test");
  EXPECT_EQ(level.file, root_ / "levels" / "one.json");
}

// ----- model files -----

TEST(LevelErrors, loader_rejects_asset_path_outside_level_root) {
  auto gltfError = [](const std::string& path) {
    return parseError(replaced(kMinimalLevel, R"({"box": {"size": [1, 1, 1]}})",
                               R"({"gltf": ")" + path + R"("})"));
  };
  EXPECT_EQ(gltfError("../../etc/passwd"),
            "levels/test.json:6:31: /meshes/cube/gltf: model path \"../../etc/passwd\" must stay "
            "inside the level's directory or assets/");
  EXPECT_NE(gltfError("/etc/model.gltf")
                .find("/meshes/cube/gltf: model path \"/etc/model.gltf\" must be relative to the "
                      "level's directory or assets/"),
            std::string::npos);
  EXPECT_NE(gltfError("model.obj")
                .find("/meshes/cube/gltf: expected a path to a .gltf or .glb file, got "
                      "\"model.obj\""),
            std::string::npos);
  EXPECT_NE(gltfError("missing.gltf")
                .find("/meshes/cube/gltf: model file \"missing.gltf\" not found; looked in: "
                      "\"levels\""),
            std::string::npos);
}

TEST_F(TempDirTest, loader_rejects_symlink_that_leaves_the_level_directory) {
  writeGltf(root_ / "outside" / "box.gltf",
            makeGltf(game::primitives::box(glm::vec3(1)), IndexType::U16), false);
  fs::create_directories(root_ / "levels");
  fs::create_directory_symlink(root_ / "outside", root_ / "levels" / "linked");
  writeFile(
      root_ / "levels" / "one.json",
      replaced(kMinimalLevel, R"({"box": {"size": [1, 1, 1]}})", R"({"gltf": "linked/box.gltf"})"));
  EXPECT_NE(loadError(root_ / "levels" / "one.json")
                .find("model path \"linked/box.gltf\" must stay inside the level's directory or "
                      "assets/"),
            std::string::npos);
}

TEST_F(TempDirTest, level_loads_a_gltf_box_next_to_the_level) {
  const render::MeshData box = game::primitives::box({1, 2, 3});
  writeGltf(root_ / "levels" / "models" / "box.gltf", makeGltf(box, IndexType::U16), false);
  writeFile(
      root_ / "levels" / "one.json",
      replaced(kMinimalLevel, R"({"box": {"size": [1, 1, 1]}})", R"({"gltf": "models/box.gltf"})"));
  const game::Level level = game::loadLevel(root_ / "levels" / "one.json");
  ASSERT_EQ(level.meshes.size(), 1u);
  const render::MeshData& mesh = level.meshes[0];
  EXPECT_EQ(mesh.indices.size() / 3, 12u);
  EXPECT_EQ(mesh.vertices.size(), 24u);
  expectOutwardFacing(mesh);
  // Normals were computed from the faces and match the box's own.
  for (std::size_t i = 0; i < box.vertices.size(); ++i) {
    EXPECT_EQ(mesh.vertices[i].position, box.vertices[i].position);
    EXPECT_NEAR(glm::length(mesh.vertices[i].normal - box.vertices[i].normal), 0.0f, 1e-6f);
  }
}

TEST_F(TempDirTest, gltf_in_the_sibling_assets_directory_is_found) {
  writeGltf(root_ / "assets" / "models" / "box.glTF",
            makeGltf(game::primitives::box(glm::vec3(1)), IndexType::U32), false);
  writeFile(
      root_ / "levels" / "one.json",
      replaced(kMinimalLevel, R"({"box": {"size": [1, 1, 1]}})", R"({"gltf": "models/box.glTF"})"));
  EXPECT_EQ(game::loadLevel(root_ / "levels" / "one.json").meshes[0].indices.size(), 36u);

  // Explicit asset roots replace the default.
  game::LevelLoadOptions options;
  options.assetRoots = {root_ / "elsewhere"};
  fs::create_directories(root_ / "elsewhere");
  EXPECT_NE(loadError(root_ / "levels" / "one.json", options).find("not found; looked in:"),
            std::string::npos);
  options.assetRoots = {root_ / "elsewhere", root_ / "assets"};
  EXPECT_EQ(game::loadLevel(root_ / "levels" / "one.json", options).meshes[0].indices.size(), 36u);
}

TEST_F(TempDirTest, gltf_with_embedded_buffer_and_byte_indices_loads) {
  writeGltf(root_ / "box.gltf", makeGltf(game::primitives::box(glm::vec3(1)), IndexType::U8), true);
  const render::MeshData mesh = game::loadGltfMesh(root_ / "box.gltf", root_);
  EXPECT_EQ(mesh.indices.size(), 36u);
  EXPECT_EQ(mesh.name, "box");
  expectOutwardFacing(mesh);
}

TEST_F(TempDirTest, glb_with_its_buffer_in_the_binary_chunk_loads) {
  const GltfFile file = makeGltf(game::primitives::box(glm::vec3(1)), IndexType::U16);
  std::string json = file.document.dump();  // no buffer uri: the BIN chunk is buffer 0
  json.resize((json.size() + 3) / 4 * 4, ' ');
  std::string bin = file.buffer;
  bin.resize((bin.size() + 3) / 4 * 4, '\0');
  std::string glb = "glTF";
  appendBytes(glb, uint32_t{2});
  appendBytes(glb, static_cast<uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  appendBytes(glb, static_cast<uint32_t>(json.size()));
  glb += "JSON" + json;
  appendBytes(glb, static_cast<uint32_t>(bin.size()));
  glb += std::string("BIN\0", 4) + bin;
  writeFile(root_ / "box.glb", glb);
  const render::MeshData mesh = game::loadGltfMesh(root_ / "box.glb", root_);
  EXPECT_EQ(mesh.indices.size(), 36u);
  expectOutwardFacing(mesh);
}

TEST_F(TempDirTest, gltf_without_indices_gets_flat_normals) {
  render::MeshData unindexed;
  const render::MeshData box = game::primitives::box(glm::vec3(2));
  for (const uint32_t index : box.indices) unindexed.vertices.push_back(box.vertices[index]);
  writeGltf(root_ / "soup.gltf", makeGltf(unindexed, IndexType::None), true);
  const render::MeshData mesh = game::loadGltfMesh(root_ / "soup.gltf", root_);
  EXPECT_EQ(mesh.vertices.size(), 36u);
  EXPECT_EQ(mesh.indices.size(), 36u);
  expectOutwardFacing(mesh);
}

TEST_F(TempDirTest, gltf_node_transforms_apply_and_mirroring_keeps_faces_outward) {
  GltfFile file = makeGltf(game::primitives::box(glm::vec3(1)), IndexType::U16);
  file.document["nodes"] = {{{"children", {1}}, {"translation", {10, 0, 0}}},
                            {{"mesh", 0}, {"scale", {-2, 1, 1}}}};
  writeGltf(root_ / "mirrored.gltf", file, true);
  const render::MeshData mesh = game::loadGltfMesh(root_ / "mirrored.gltf", root_);
  EXPECT_EQ(mesh.indices.size(), 36u);
  for (const auto& vertex : mesh.vertices) EXPECT_FLOAT_EQ(std::abs(vertex.position.x - 10), 1.0f);
  expectOutwardFacing(mesh, {10, 0, 0});
}

TEST_F(TempDirTest, gltf_mesh_can_be_picked_by_name) {
  GltfFile file = makeGltf(game::primitives::box(glm::vec3(1)), IndexType::U16);
  file.document["nodes"][0]["translation"] = {5, 0, 0};
  writeGltf(root_ / "named.gltf", file, true);
  const render::MeshData mesh = game::loadGltfMesh(root_ / "named.gltf", root_, "Cube");
  EXPECT_EQ(mesh.name, "Cube");
  expectOutwardFacing(mesh);  // in the mesh's own space: the node's translation is not applied
  try {
    game::loadGltfMesh(root_ / "named.gltf", root_, "Sphere");
    FAIL() << "expected an error";
  } catch (const game::LevelError& error) {
    EXPECT_EQ(std::string(error.what()), (root_ / "named.gltf").string() +
                                             ": has no mesh named \"Sphere\"; its meshes are: "
                                             "\"Cube\"");
  }
}

// The message loadGltfMesh throws for a box glTF changed by `edit`.
template <typename Edit>
std::string brokenGltfError(const fs::path& directory, Edit edit) {
  GltfFile file = makeGltf(game::primitives::box(glm::vec3(1)), IndexType::U16);
  edit(file);
  writeGltf(directory / "broken.gltf", file, false);
  try {
    game::loadGltfMesh(directory / "broken.gltf", directory);
  } catch (const game::LevelError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST_F(TempDirTest, broken_gltf_files_are_reported_with_their_name) {
  const std::string prefix = (root_ / "broken.gltf").string() + ": ";
  EXPECT_EQ(brokenGltfError(root_,
                            [](GltfFile& file) {
                              const std::size_t at = 24 * 12 + 2 * 5;  // the sixth index
                              file.buffer[at] = 99;
                              file.buffer[at + 1] = 0;
                            }),
            prefix +
                "mesh \"Cube\" primitive 0 index 99 (at 5) is out of range: the "
                "primitive has 24 vertices");
  EXPECT_EQ(
      brokenGltfError(
          root_, [](GltfFile& file) { file.document["meshes"][0]["primitives"][0]["mode"] = 1; }),
      prefix +
          "mesh \"Cube\" primitive 0 has mode 1 (LINES); only TRIANGLES (4) is "
          "supported");
  EXPECT_EQ(brokenGltfError(
                root_,
                [](GltfFile& file) { file.document["meshes"][0]["primitives"][0]["indices"] = 7; }),
            prefix + "cannot load glTF: primitive indices accessor out of bounds");
  EXPECT_EQ(
      brokenGltfError(root_, [](GltfFile& file) { file.document["accessors"][0]["count"] = 25; }),
      prefix +
          "mesh \"Cube\" primitive 0 POSITION (accessor 0) reads past the end of its "
          "buffer");
  EXPECT_EQ(brokenGltfError(root_,
                            [](GltfFile& file) {
                              file.document["meshes"][0]["primitives"] = nlohmann::json::array();
                            }),
            prefix + "contains no triangles");
  EXPECT_EQ(brokenGltfError(root_,
                            [](GltfFile& file) {
                              file.document["buffers"][0]["byteLength"] = file.buffer.size();
                              file.document["asset"] = "not an object";
                            })
                .rfind(prefix + "cannot load glTF: ", 0),
            0u);
}

TEST_F(TempDirTest, gltf_that_is_missing_or_not_json_is_reported) {
  try {
    game::loadGltfMesh(root_ / "nothing.gltf", root_);
    FAIL() << "expected an error";
  } catch (const game::LevelError& error) {
    EXPECT_EQ(std::string(error.what()),
              (root_ / "nothing.gltf").string() + ": cannot open glTF file");
  }
  writeFile(root_ / "garbage.gltf", "{ not json");
  try {
    game::loadGltfMesh(root_ / "garbage.gltf", root_);
    FAIL() << "expected an error";
  } catch (const game::LevelError& error) {
    EXPECT_EQ(std::string(error.what())
                  .rfind((root_ / "garbage.gltf").string() + ": cannot load glTF: ", 0),
              0u);
  }
}

TEST_F(TempDirTest, gltf_buffer_outside_the_allowed_directory_is_refused) {
  const GltfFile file = makeGltf(game::primitives::box(glm::vec3(1)), IndexType::U16);
  writeFile(root_ / "secret.bin", file.buffer);
  nlohmann::json document = file.document;
  document["buffers"][0]["uri"] = "../secret.bin";
  writeFile(root_ / "levels" / "box.gltf", document.dump());
  writeFile(root_ / "levels" / "one.json",
            replaced(kMinimalLevel, R"({"box": {"size": [1, 1, 1]}})", R"({"gltf": "box.gltf"})"));
  const std::string error = loadError(root_ / "levels" / "one.json");
  EXPECT_EQ(error.rfind((root_ / "levels" / "one.json").string() + ":6:31: /meshes/cube/gltf: " +
                            (root_ / "levels" / "box.gltf").string() + ": refers to \"",
                        0),
            0u)
      << error;
  EXPECT_NE(error.find("secret.bin\", which is outside the directory the model was found in"),
            std::string::npos)
      << error;
}

}  // namespace
