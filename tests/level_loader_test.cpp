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
#include "gltf_builder.hpp"
#include "scene/color.hpp"
#include "temp_dir_fixture.hpp"

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

using test::writeFile;

// A fresh directory per test, removed afterwards.
using test::TempDirTest;

// ----- glTF writing helpers -----

using test::base64;

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

GltfFile makeGltf(const scene::MeshData& mesh, IndexType indexType) {
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
void expectOutwardFacing(const scene::MeshData& mesh, const glm::vec3& center = glm::vec3(0.0f)) {
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
  EXPECT_FLOAT_EQ(scene::srgbToLinear(0.5f), 0.21404114f);
  EXPECT_FLOAT_EQ(scene::srgbToLinear(0.04045f), 0.04045f / 12.92f);  // linear segment
  EXPECT_FLOAT_EQ(scene::srgbToLinear(1.0f), 1.0f);
  EXPECT_FLOAT_EQ(scene::srgbToLinear(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(scene::linearToSrgb(0.002f), 12.92f * 0.002f);
  EXPECT_FLOAT_EQ(scene::linearToSrgb(0.21404114f), 0.5f);
  const glm::vec3 linear = scene::srgbToLinear(glm::vec3(0.2f, 0.5f, 1.0f));
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
  EXPECT_EQ(level.lights[0].type, scene::LightType::Directional);
  EXPECT_EQ(level.lights[0].direction, glm::vec3(0, -1, 0));  // normalised
  EXPECT_EQ(level.lights[0].color, glm::vec3(1.0f));          // white by default
  EXPECT_FLOAT_EQ(level.lights[0].intensity, 3.0f);
  EXPECT_EQ(level.lights[1].type, scene::LightType::Point);
  EXPECT_EQ(level.lights[1].position, glm::vec3(0, 3, 0));
  EXPECT_FLOAT_EQ(level.lights[1].color.g, 0.21404114f);
  EXPECT_FLOAT_EQ(level.lights[1].intensity, 60.0f);
}

TEST(LevelLoader, loader_reads_every_field_of_format_1) {
  const std::string text = R"({
  "format": 1,
  "name": "The Blue Room",
  "description": "Glass, a mirror and a lamp.",
  "author": "A. Author",
  "hint": "Look through the glass.",
  "camera": {"position": [0, 1.7, 6], "pitch_degrees": -5},
  "environment": {"sky_zenith": [1, 0, 0.5], "sky_horizon": "#000000", "sky_intensity": 2},
  "rendering": {"max_mirror_bounces": 7},
  "materials": {
    "plain": {},
    "mirror": {"mirror": {"reflectance": 0.5, "tint": [1, 0.5, 0.25]}},
    "perfect_mirror": {"mirror": {}},
    "blue_glass": {"glass": {"tint": [0.2, 0.4, 1.0]}}
  },
  "meshes": {
    "crate": {"box": {"size": [1, 1, 1]}},
    "orb": {"sphere": {"radius": 0.4}}
  },
  "entities": {
    "orb": {"mesh": "orb", "material": "plain", "position": [0, 1, 0]},
    "bulb": {"mesh": "orb", "material": "plain", "scale": 0.2, "casts_shadow": false},
    "lift": {"mesh": "crate", "material": "plain", "position": [9, 9, 9],
             "rotation_degrees": [1, 2, 3],
      "mover": {"duration_seconds": 4, "repeat": "ping_pong", "easing": "smooth",
                "keyframes": [{"position": [3, 0.5, 0]},
                              {"position": [3, 2.5, 0], "rotation_degrees": [0, 90, 0]},
                              {"rotation_degrees": [0, 180, 0]}]}},
    "door": {"mesh": "crate", "material": "plain", "mover": {"keyframes": [{}, {}]}},
    "mirror_stand": {"mesh": "crate", "material": "mirror",
      "interactable": {"type": "rotate", "axis": [0, 2, 0], "min_degrees": -45,
                       "max_degrees": 45, "start_degrees": 10}},
    "turntable": {"mesh": "crate", "material": "perfect_mirror",
      "interactable": {"type": "rotate", "min_degrees": 20, "max_degrees": 40}},
    "slider": {"mesh": "crate", "material": "blue_glass",
      "interactable": {"type": "slide", "axis": [0, 0, -3], "min": -1, "max": 1, "start": 0.5}},
    "lever": {"mesh": "crate", "material": "plain",
      "interactable": {"type": "switch", "light": "spot", "starts_on": false}},
    "button": {"mesh": "crate", "material": "plain",
      "interactable": {"type": "switch", "light": "lamp"}}
  },
  "lights": {
    "sun": {"type": "directional", "direction": [0, -3, 4], "color": [1, 1, 1], "intensity": 3,
            "angular_diameter_degrees": 0.5},
    "lamp": {"type": "point", "position": [0, 2.7, 0], "intensity": 5},
    "panel": {"type": "rectangle", "position": [0, 3, 0], "direction": [0, -2, 0],
              "size": [1, 0.5], "intensity": 10},
    "globe": {"type": "sphere", "position": [2, 2, 2], "radius": 0.2, "intensity": 20},
    "spot": {"type": "disk", "position": [-2, 3, 0], "direction": [0, 0, 5], "radius": 0.3,
             "intensity": 15, "enabled": false}
  },
  "goal": {
    "type": "all",
    "of": [
      {"type": "focus", "orb": "orb", "region": [0.2, 0.3], "coverage": 0.3,
       "rise_per_second": 0.75, "fall_per_second": 0.125},
      {"type": "any", "of": [
        {"type": "lit", "sensor": "slider", "light": "panel", "threshold": 0.25,
         "hold_seconds": 2},
        {"type": "reach", "min": [-1, 0, -6], "max": [1, 3, -4]}]},
      {"type": "focus", "orb": "bulb"},
      {"type": "lit", "sensor": "lift", "light": "sun"}
    ]
  },
  "lose": [
    {"type": "stealth", "watcher": "globe", "exposure_limit": 0.2, "seconds": 1.5},
    {"type": "fall", "below": -5},
    {"type": "stealth", "watcher": "lamp"}
  ]
}
)";
  const game::Level level = game::parseLevel(text, "levels/blue.json");
  EXPECT_EQ(level.name, "The Blue Room");
  EXPECT_EQ(level.description, "Glass, a mirror and a lamp.");
  EXPECT_EQ(level.author, "A. Author");
  EXPECT_EQ(level.hint, "Look through the glass.");
  EXPECT_EQ(level.maxMirrorBounces, 7u);
  // Sky colours are converted from sRGB, then multiplied by sky_intensity.
  EXPECT_FLOAT_EQ(level.environment.skyZenith.r, 2.0f);
  EXPECT_FLOAT_EQ(level.environment.skyZenith.g, 0.0f);
  EXPECT_FLOAT_EQ(level.environment.skyZenith.b, 2.0f * scene::srgbToLinear(0.5f));
  EXPECT_EQ(level.environment.skyHorizon, glm::vec3(0.0f));

  ASSERT_EQ(level.materials.size(), 4u);
  const scene::MaterialDesc& plain = level.materials[0];
  EXPECT_EQ(plain.kind, scene::MaterialKind::Diffuse);
  EXPECT_EQ(plain.baseColor, glm::vec3(1.0f));  // white by default
  EXPECT_FLOAT_EQ(plain.specular, 0.0f);
  EXPECT_FLOAT_EQ(plain.roughness, 0.5f);
  EXPECT_EQ(plain.colorTexture, -1);
  EXPECT_EQ(plain.normalTexture, -1);
  // Tints are linear: reflectance times tint, no sRGB conversion.
  EXPECT_EQ(level.materials[1].kind, scene::MaterialKind::Mirror);
  EXPECT_EQ(level.materials[1].mirrorTint, glm::vec3(0.5f, 0.25f, 0.125f));
  EXPECT_EQ(level.materials[2].kind, scene::MaterialKind::Mirror);
  EXPECT_EQ(level.materials[2].mirrorTint, glm::vec3(1.0f));
  EXPECT_EQ(level.materials[3].kind, scene::MaterialKind::Glass);
  EXPECT_EQ(level.materials[3].glassTint, glm::vec3(0.2f, 0.4f, 1.0f));
  EXPECT_TRUE(level.textures.empty());

  ASSERT_EQ(level.entities.size(), 9u);
  const game::Entity& bulb = level.entities[1];
  EXPECT_EQ(bulb.scale, glm::vec3(0.2f));
  EXPECT_FALSE(bulb.castsShadow);
  EXPECT_TRUE(level.entities[0].castsShadow);
  EXPECT_FALSE(level.entities[0].mover || level.entities[0].interactable);

  const game::Entity& lift = level.entities[2];
  ASSERT_TRUE(lift.mover.has_value());
  EXPECT_FALSE(lift.interactable.has_value());
  EXPECT_FLOAT_EQ(lift.mover->durationSeconds, 4.0f);
  EXPECT_EQ(lift.mover->repeat, game::Mover::Repeat::PingPong);
  EXPECT_EQ(lift.mover->easing, game::Mover::Easing::Smooth);
  ASSERT_EQ(lift.mover->keyframes.size(), 3u);
  // What a keyframe leaves out is the entity's own pose.
  EXPECT_EQ(lift.mover->keyframes[0].position, glm::vec3(3, 0.5f, 0));
  EXPECT_EQ(lift.mover->keyframes[0].rotationDegrees, glm::vec3(1, 2, 3));
  EXPECT_EQ(lift.mover->keyframes[1].position, glm::vec3(3, 2.5f, 0));
  EXPECT_EQ(lift.mover->keyframes[1].rotationDegrees, glm::vec3(0, 90, 0));
  EXPECT_EQ(lift.mover->keyframes[2].position, glm::vec3(9, 9, 9));
  EXPECT_EQ(lift.mover->keyframes[2].rotationDegrees, glm::vec3(0, 180, 0));
  const game::Mover& door = *level.entities[3].mover;
  EXPECT_FLOAT_EQ(door.durationSeconds, 1.0f);
  EXPECT_EQ(door.repeat, game::Mover::Repeat::Loop);
  EXPECT_EQ(door.easing, game::Mover::Easing::Linear);

  const game::Interactable& stand = *level.entities[4].interactable;
  EXPECT_EQ(stand.type, game::Interactable::Type::Rotate);
  EXPECT_EQ(stand.axis, glm::vec3(0, 1, 0));  // normalised
  EXPECT_FLOAT_EQ(stand.min, -45.0f);
  EXPECT_FLOAT_EQ(stand.max, 45.0f);
  EXPECT_FLOAT_EQ(stand.start, 10.0f);
  const game::Interactable& turntable = *level.entities[5].interactable;
  EXPECT_EQ(turntable.axis, glm::vec3(0, 1, 0));  // default: about +Y
  EXPECT_FLOAT_EQ(turntable.start, 20.0f);        // 0 pulled into [min, max]
  const game::Interactable& slider = *level.entities[6].interactable;
  EXPECT_EQ(slider.type, game::Interactable::Type::Slide);
  EXPECT_EQ(slider.axis, glm::vec3(0, 0, -1));
  EXPECT_FLOAT_EQ(slider.min, -1.0f);
  EXPECT_FLOAT_EQ(slider.max, 1.0f);
  EXPECT_FLOAT_EQ(slider.start, 0.5f);
  const game::Interactable& lever = *level.entities[7].interactable;
  EXPECT_EQ(lever.type, game::Interactable::Type::Switch);
  EXPECT_EQ(lever.light, 4u);  // "spot"
  EXPECT_FALSE(lever.startsOn);
  EXPECT_EQ(level.entities[8].interactable->light, 1u);  // "lamp"
  EXPECT_TRUE(level.entities[8].interactable->startsOn);

  ASSERT_EQ(level.lightIds, (std::vector<std::string>{"sun", "lamp", "panel", "globe", "spot"}));
  const scene::LightDesc& sun = level.lights[0];
  EXPECT_EQ(sun.type, scene::LightType::Directional);
  EXPECT_EQ(sun.direction, glm::vec3(0, -0.6f, 0.8f));
  EXPECT_FLOAT_EQ(sun.angularDiameterRadians, glm::radians(0.5f));
  EXPECT_TRUE(sun.enabled);
  EXPECT_FLOAT_EQ(level.lights[1].angularDiameterRadians, 0.0f);
  const scene::LightDesc& panel = level.lights[2];
  EXPECT_EQ(panel.type, scene::LightType::Rectangle);
  EXPECT_EQ(panel.position, glm::vec3(0, 3, 0));
  EXPECT_EQ(panel.direction, glm::vec3(0, -1, 0));
  EXPECT_EQ(panel.size, glm::vec2(1, 0.5f));
  EXPECT_FLOAT_EQ(panel.intensity, 10.0f);
  const scene::LightDesc& globe = level.lights[3];
  EXPECT_EQ(globe.type, scene::LightType::Sphere);
  EXPECT_EQ(globe.position, glm::vec3(2, 2, 2));
  EXPECT_FLOAT_EQ(globe.radius, 0.2f);
  EXPECT_FLOAT_EQ(globe.intensity, 20.0f);
  const scene::LightDesc& spot = level.lights[4];
  EXPECT_EQ(spot.type, scene::LightType::Disk);
  EXPECT_EQ(spot.direction, glm::vec3(0, 0, 1));
  EXPECT_FLOAT_EQ(spot.radius, 0.3f);
  EXPECT_FALSE(spot.enabled);

  ASSERT_TRUE(level.goal.has_value());
  const game::Goal& goal = *level.goal;
  EXPECT_EQ(goal.type, game::Goal::Type::All);
  ASSERT_EQ(goal.children.size(), 4u);
  const game::Goal& focus = goal.children[0];
  EXPECT_EQ(focus.type, game::Goal::Type::Focus);
  EXPECT_EQ(focus.entity, 0u);
  EXPECT_EQ(focus.region, glm::vec2(0.2f, 0.3f));
  EXPECT_FLOAT_EQ(focus.coverage, 0.3f);
  EXPECT_FLOAT_EQ(focus.risePerSecond, 0.75f);
  EXPECT_FLOAT_EQ(focus.fallPerSecond, 0.125f);
  const game::Goal& any = goal.children[1];
  EXPECT_EQ(any.type, game::Goal::Type::Any);
  ASSERT_EQ(any.children.size(), 2u);
  EXPECT_EQ(any.children[0].type, game::Goal::Type::Lit);
  EXPECT_EQ(any.children[0].entity, 6u);  // "slider"
  EXPECT_EQ(any.children[0].light, 2u);   // "panel"
  EXPECT_FLOAT_EQ(any.children[0].threshold, 0.25f);
  EXPECT_FLOAT_EQ(any.children[0].holdSeconds, 2.0f);
  EXPECT_EQ(any.children[1].type, game::Goal::Type::Reach);
  EXPECT_EQ(any.children[1].min, glm::vec3(-1, 0, -6));
  EXPECT_EQ(any.children[1].max, glm::vec3(1, 3, -4));
  // Defaults.
  const game::Goal& defaultFocus = goal.children[2];
  EXPECT_EQ(defaultFocus.entity, 1u);
  EXPECT_EQ(defaultFocus.region, glm::vec2(0.2f, 0.2f));
  EXPECT_FLOAT_EQ(defaultFocus.coverage, 0.5f);
  EXPECT_FLOAT_EQ(defaultFocus.risePerSecond, 0.5f);
  EXPECT_FLOAT_EQ(defaultFocus.fallPerSecond, 0.25f);
  const game::Goal& defaultLit = goal.children[3];
  EXPECT_EQ(defaultLit.entity, 2u);
  EXPECT_EQ(defaultLit.light, 0u);
  EXPECT_FLOAT_EQ(defaultLit.threshold, 0.5f);
  EXPECT_FLOAT_EQ(defaultLit.holdSeconds, 0.0f);

  ASSERT_EQ(level.lose.size(), 3u);
  EXPECT_EQ(level.lose[0].type, game::LoseCondition::Type::Stealth);
  EXPECT_EQ(level.lose[0].light, 3u);  // "globe"
  EXPECT_FLOAT_EQ(level.lose[0].exposureLimit, 0.2f);
  EXPECT_FLOAT_EQ(level.lose[0].seconds, 1.5f);
  EXPECT_EQ(level.lose[1].type, game::LoseCondition::Type::Fall);
  EXPECT_FLOAT_EQ(level.lose[1].below, -5.0f);
  EXPECT_EQ(level.lose[2].light, 1u);
  EXPECT_FLOAT_EQ(level.lose[2].exposureLimit, 0.5f);
  EXPECT_FLOAT_EQ(level.lose[2].seconds, 1.0f);

  EXPECT_EQ(level.sourceFiles, std::vector<fs::path>{"levels/blue.json"});
  EXPECT_TRUE(level.warnings.empty());

  const scene::SceneDesc scene = game::buildSceneDesc(level);
  EXPECT_EQ(scene.maxMirrorBounces, 7u);
  ASSERT_EQ(scene.instances.size(), 9u);
  EXPECT_FALSE(scene.instances[1].castsShadow);
  EXPECT_TRUE(scene.instances[0].castsShadow);
  ASSERT_EQ(scene.lights.size(), 5u);
  EXPECT_FALSE(scene.lights[4].enabled);
  EXPECT_FLOAT_EQ(scene.lights[4].radius, 0.3f);
  EXPECT_EQ(scene.lights[2].size, glm::vec2(1, 0.5f));
  EXPECT_FLOAT_EQ(scene.lights[0].angularDiameterRadians, glm::radians(0.5f));

  const game::LevelFeatures features = game::levelFeatures(level);
  EXPECT_EQ(features.instances, 9u);
  EXPECT_EQ(features.triangles, 2u * (2 * 32 * 15) + 7u * 12);
  EXPECT_EQ(features.lights, 5u);
  EXPECT_TRUE(features.glass);
  EXPECT_TRUE(features.mirrors);
  EXPECT_EQ(features.mirrorBounces, 7u);
  EXPECT_TRUE(features.areaLights);
  EXPECT_FALSE(features.textures);
  EXPECT_TRUE(features.movers);
  EXPECT_TRUE(features.interactables);
}

TEST(LevelLoader, features_of_a_plain_level_are_off) {
  const game::Level level = game::parseLevel(kMinimalLevel, "levels/test.json");
  const game::LevelFeatures features = game::levelFeatures(level);
  EXPECT_EQ(features.triangles, 12u);
  EXPECT_EQ(features.instances, 1u);
  EXPECT_FALSE(features.glass || features.mirrors || features.areaLights || features.textures ||
               features.movers || features.interactables);
  EXPECT_EQ(features.mirrorBounces, 0u);  // no mirrors: the cap does not matter
  EXPECT_FALSE(level.goal.has_value());
  EXPECT_TRUE(level.lose.empty());
  EXPECT_EQ(level.maxMirrorBounces, 4u);
  EXPECT_EQ(game::buildSceneDesc(level).maxMirrorBounces, 4u);
}

TEST(LevelLoader, a_flat_mirror_routes_light_and_a_curved_one_warns) {
  std::string text = replaced(kMinimalLevel, R"("grey": {"color": [0.5, 0.5, 0.5]})",
                              R"("grey": {"mirror": {"reflectance": 0.9}})");
  text =
      replaced(text, R"("lights": {})",
               R"("lights": {"lamp": {"type": "point", "position": [0, 3, 0], "intensity": 5}})");
  const game::Level flat = game::parseLevel(text, "levels/test.json");
  EXPECT_TRUE(game::levelFeatures(flat).lightViaMirrors);
  EXPECT_TRUE(flat.warnings.empty());

  const std::string curvedText =
      replaced(text, R"({"box": {"size": [1, 1, 1]}})", R"({"sphere": {"radius": 1}})");
  const game::Level curved = game::parseLevel(curvedText, "levels/test.json");
  EXPECT_FALSE(game::levelFeatures(curved).lightViaMirrors);
  EXPECT_EQ(curved.warnings,
            (std::vector<std::string>{
                "levels/test.json:7:25: /entities/crate: a mirror on a curved mesh shows the "
                "reflected view but sends no light on (only flat mirror faces light surfaces and "
                "sensors)"}));

  // A level can turn routing off: then a curved mirror loses nothing and nothing warns.
  const std::string offText =
      replaced(curvedText, R"("lights")", R"("rendering": {"light_via_mirrors": false}, "lights")");
  const game::Level off = game::parseLevel(offText, "levels/test.json");
  EXPECT_FALSE(off.lightViaMirrors);
  EXPECT_TRUE(off.warnings.empty());
  EXPECT_FALSE(
      game::levelFeatures(
          game::parseLevel(replaced(text, R"("lights")",
                                    R"("rendering": {"light_via_mirrors": false}, "lights")"),
                           "levels/test.json"))
          .lightViaMirrors);
  EXPECT_FALSE(game::buildSceneDesc(off).lightViaMirrors);
}

TEST(LevelLoader, shipped_levels_load) {
  for (const char* name :
       {"01_first_light.json", "02_penumbra.json", "03_glass_and_mirrors.json"}) {
    const fs::path file = fs::path(SIGHTLINE_SOURCE_DIR) / "levels" / name;
    EXPECT_NO_THROW(game::loadLevel(file)) << name << ": " << loadError(file);
  }
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
  const scene::SceneDesc scene = game::buildSceneDesc(level);
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
  const scene::MeshData box = game::primitives::box({2, 4, 6});
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
  const scene::MeshData sphere = game::primitives::sphere(2.0f, 12, 6);
  EXPECT_EQ(sphere.vertices.size(), 7u * 13u);
  EXPECT_EQ(sphere.indices.size(), 6u * 12u * 5u);
  expectOutwardFacing(sphere);
  for (const auto& vertex : sphere.vertices) {
    EXPECT_NEAR(glm::length(vertex.position), 2.0f, 1e-5f);
    EXPECT_NEAR(glm::length(vertex.normal - vertex.position / 2.0f), 0.0f, 1e-5f);
  }
}

TEST(Primitives, plane_faces_up) {
  const scene::MeshData plane = game::primitives::plane(4.0f, 2.0f);
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
  const scene::MeshData cylinder = game::primitives::cylinder(1.0f, 3.0f, 8);
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

TEST(LevelErrors, paths_are_json_pointers_with_array_elements_as_indices) {
  const std::string text = replaced(kMinimalLevel, R"("lights": {})",
                                    R"("lights": {"sun": {"type": "point", "position": [0, 5, 0],
                                                  "intensity": 1}},
  "goal": {"type": "all", "of": [{"type": "reach", "min": [0, 0, 0], "max": [1, 1, 1]},
                                  {"type": "focus", "orb": "sun"}]},
  "lose": [{"type": "fall", "below": -5}, {"type": "stealth", "watcher": "sun", "seconds": 0}])");
  EXPECT_EQ(parseError(text),
            "levels/test.json:11:60: /goal/of/1/orb: \"sun\" is a light, "
            "expected an entity id");
  EXPECT_EQ(parseError(replaced(text, R"("orb": "sun")", R"("orb": "crate")")),
            "levels/test.json:12:92: /lose/1/seconds: expected a number > 0, got 0");
}

TEST(LevelErrors, a_trailing_comma_is_named_where_it_is) {
  EXPECT_EQ(parseError("{\n  \"format\": 1,\n  \"name\": \"x\",\n}", "levels/bad.json"),
            "levels/bad.json:3:14: invalid JSON: trailing comma before '}'; JSON allows none");
  EXPECT_EQ(parseError("{\"format\": 1, \"name\": [1, 2, ]}", "levels/bad.json"),
            "levels/bad.json:1:28: invalid JSON: trailing comma before ']'; JSON allows none");
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

TEST(LevelLoader, casts_shadow_directional_keeps_a_caster_of_directional_light_alone) {
  const std::string text = replaced(kMinimalLevel, R"({"mesh": "cube", "material": "grey"})",
                                    R"({"mesh": "cube", "material": "grey",
                                        "casts_shadow": "directional"})");
  const game::Level level = game::parseLevel(text, "levels/test.json");
  EXPECT_TRUE(level.entities[0].castsShadow);
  EXPECT_TRUE(level.entities[0].shadowsDirectionalOnly);
  const scene::SceneDesc scene = game::buildSceneDesc(level);
  EXPECT_TRUE(scene.instances[0].castsShadow);
  EXPECT_TRUE(scene.instances[0].shadowsDirectionalOnly);
  // A default entity casts every shadow; any other string is refused with the choices.
  const game::Level plain = game::parseLevel(kMinimalLevel, "levels/test.json");
  EXPECT_FALSE(plain.entities[0].shadowsDirectionalOnly);
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"({"mesh": "cube", "material": "grey"})",
                                R"({"mesh": "cube", "material": "grey", "casts_shadow": "sun"})")),
            "levels/test.json:7:78: /entities/crate/casts_shadow: expected true, false or "
            "\"directional\", got \"sun\"");
}

TEST(LevelErrors, unknown_key_suggests_the_nearest_allowed_key) {
  auto entityError = [](const std::string& entity) {
    return parseError(replaced(kMinimalLevel, R"({"mesh": "cube", "material": "grey"})", entity));
  };
  EXPECT_EQ(entityError(R"({"mesh": "cube", "material": "grey", "postion": [0, 0, 0]})"),
            "levels/test.json:7:62: /entities/crate: unknown key \"postion\"; did you mean "
            "\"position\"?");
  // Case and '_' differences count as near misses whatever their edit distance.
  EXPECT_NE(entityError(R"({"mesh": "cube", "material": "grey", "castsShadow": false})")
                .find("/entities/crate: unknown key \"castsShadow\"; did you mean "
                      "\"casts_shadow\"?"),
            std::string::npos);
  EXPECT_NE(entityError(R"({"mesh": "cube", "material": "grey", "Scale": 2})")
                .find("did you mean \"scale\"?"),
            std::string::npos);
}

TEST(LevelErrors, unknown_key_without_a_near_miss_lists_the_allowed_keys) {
  const std::string text =
      replaced(kMinimalLevel, R"({"color": [0.5, 0.5, 0.5]})", R"({"paint": [0.5, 0.5, 0.5]})");
  EXPECT_EQ(
      parseError(text),
      "levels/test.json:5:26: /materials/grey: unknown key \"paint\"; allowed keys: "
      "\"color\", \"specular\", \"metallic\", \"roughness\", \"emissive\", \"emissive_strength\", "
      "\"texture\", \"normal_map\", \"mirror\", \"glass\"");
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"("name": "Test")", R"("Name": "Test")")),
            "levels/test.json:3:3: unknown key \"Name\"; did you mean \"name\"?");
}

TEST(LevelErrors, missing_required_key_points_at_its_object) {
  const std::string text = replaced(kMinimalLevel, R"("camera": {"position": [0, 1, 5]})",
                                    R"("camera": {"fov_degrees": 50})");
  EXPECT_EQ(parseError(text), "levels/test.json:4:13: /camera: missing required key \"position\"");
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"("material": "grey")", R"("casts_shadow": true)")),
            "levels/test.json:7:25: /entities/crate: missing required key \"material\" (mesh "
            "\"cube\" is not a glTF model, so the entity must name one)");
}

TEST(LevelErrors, dangling_ids_suggest_a_near_miss_or_list_the_known_ids) {
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"("mesh": "cube")", R"("mesh": "cub")")),
            "levels/test.json:7:34: /entities/crate/mesh: unknown mesh \"cub\"; did you mean "
            "\"cube\"?");
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"("mesh": "cube")", R"("mesh": "sphere")")),
            "levels/test.json:7:34: /entities/crate/mesh: unknown mesh \"sphere\"; known meshes: "
            "\"cube\"");
  EXPECT_NE(parseError(replaced(kMinimalLevel, R"("material": "grey")", R"("material": "GREY")"))
                .find("/entities/crate/material: unknown material \"GREY\"; did you mean "
                      "\"grey\"?"),
            std::string::npos);
}

TEST(LevelErrors, reference_to_an_id_of_another_kind_says_what_it_is) {
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"("material": "grey")", R"("material": "cube")")),
            "levels/test.json:7:54: /entities/crate/material: \"cube\" is a mesh, expected a "
            "material id");
  const std::string withSwitch =
      replaced(kMinimalLevel, R"("material": "grey")",
               R"("material": "grey", "interactable": {"type": "switch", "light": "crate"})");
  EXPECT_NE(
      parseError(withSwitch)
          .find("/entities/crate/interactable/light: \"crate\" is an entity, expected a light "
                "id"),
      std::string::npos);
  // Lights are optional, so a level may have none to name.
  EXPECT_NE(
      parseError(replaced(withSwitch, R"("light": "crate")", R"("light": "lamp")"))
          .find("/entities/crate/interactable/light: unknown light \"lamp\"; the level has no "
                "lights"),
      std::string::npos);
}

TEST(LevelErrors, duplicate_ids_name_their_kind) {
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"({"grey": {"color": [0.5, 0.5, 0.5]}})",
                                R"({"grey": {}, "grey": {}})")),
            "levels/test.json:5:29: /materials: duplicate material id \"grey\"");
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"("name": "Test")", R"("name": "A", "name": "B")")),
            "levels/test.json:3:16: duplicate key \"name\"");
}

TEST(LevelErrors, colour_and_tint_errors_say_what_they_expect) {
  EXPECT_EQ(parseError(replaced(kMinimalLevel, "[0.5, 0.5, 0.5]", "\"#12345\"")),
            "levels/test.json:5:35: /materials/grey/color: expected a colour: [r, g, b] with "
            "components in [0, 1] or a string \"#rrggbb\", got \"#12345\"");
  EXPECT_EQ(parseError(replaced(kMinimalLevel, "[0.5, 0.5, 0.5]", "[0.5, 1.5, 0.5]")),
            "levels/test.json:5:41: /materials/grey/color/1: expected a number in [0, 1], got 1.5");
  auto materialError = [](const std::string& material) {
    return parseError(replaced(kMinimalLevel, R"({"color": [0.5, 0.5, 0.5]})", material));
  };
  EXPECT_EQ(materialError(R"({"glass": {"tint": "0,5"}})"),
            "levels/test.json:5:44: /materials/grey/glass/tint: expected 3 numbers in [0, 1], got "
            "\"0,5\"");
  EXPECT_NE(materialError(R"({"glass": {}})")
                .find("/materials/grey/glass: missing required key \"tint\""),
            std::string::npos);
  EXPECT_NE(materialError(R"({"mirror": {"reflectance": 1.1}})")
                .find("/materials/grey/mirror/reflectance: expected a number in [0, 1], got 1.1"),
            std::string::npos);
  EXPECT_EQ(materialError(R"({"mirror": {}, "glass": {"tint": [1, 1, 1]}})"),
            "levels/test.json:5:40: /materials/grey: a material is a mirror or glass, not both; "
            "remove \"mirror\" or \"glass\"");
}

TEST(LevelErrors, number_rules_name_their_range_and_limit) {
  auto cameraError = [](const std::string& camera) {
    return parseError(replaced(kMinimalLevel, R"({"position": [0, 1, 5]})", camera));
  };
  EXPECT_NE(cameraError(R"({"position": [0, 1, 5], "fov_degrees": 0})")
                .find("/camera/fov_degrees: expected a number in (0, 179], got 0"),
            std::string::npos);
  EXPECT_NE(cameraError(R"({"position": [0, 1, 5], "pitch_degrees": 90.5})")
                .find("/camera/pitch_degrees: expected a number in [-90, 90], got 90.5"),
            std::string::npos);
  EXPECT_EQ(cameraError(R"({"position": [0, 250000, 5]})"),
            "levels/test.json:4:30: /camera/position/1: expected a number in [-100000, 100000], "
            "got 250000; positions and sizes are limited to ±100000 m");
  EXPECT_NE(cameraError(R"({"position": [0, 1, 5], "yaw_degrees": 1e300})")
                .find("/camera/yaw_degrees: expected a number, got 1e+300; numbers are stored as "
                      "32-bit floats, within ±3.4e38"),
            std::string::npos);
  EXPECT_NE(cameraError(R"({"position": [0, 1]})")
                .find("/camera/position: expected an array of 3 numbers [x, y, z], got [0,1]"),
            std::string::npos);
  EXPECT_NE(cameraError(R"({"position": [0, true, 5]})")
                .find("/camera/position/1: expected a number in [-100000, 100000], got true"),
            std::string::npos);
  // JSON has no NaN: the string is a type error.
  EXPECT_NE(cameraError(R"({"position": [0, "NaN", 5]})")
                .find("/camera/position/1: expected a number in [-100000, 100000], got \"NaN\""),
            std::string::npos);
  EXPECT_NE(parseError(replaced(kMinimalLevel, R"("lights": {})",
                                R"("lights": {"l": {"type": "point", "position": [0, 0, 0],
                                               "intensity": 2e9}})"))
                .find("/lights/l/intensity: expected a number in [0, 1000000000], got "
                      "2000000000; intensities are limited to 1e9"),
            std::string::npos);
}

TEST(LevelErrors, numbers_too_large_for_a_double_are_named_by_their_path) {
  auto cameraError = [](const std::string& camera) {
    return parseError(replaced(kMinimalLevel, R"({"position": [0, 1, 5]})", camera));
  };
  EXPECT_EQ(cameraError(R"({"position": [0, 1e999, 5]})"),
            "levels/test.json:4:30: /camera/position/1: expected a finite number, got 1e999, "
            "which is too large to represent");
  EXPECT_EQ(cameraError(R"({"position": [0, 1, 5], "fov_degrees": -1E+400})"),
            "levels/test.json:4:52: /camera/fov_degrees: expected a finite number, got -1E+400, "
            "which is too large to represent");
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
                .find("/meshes/cube/box/size/1: expected a number in (0, 100000], got 0"),
            std::string::npos);
  EXPECT_NE(meshError(R"({"plane": {"size": [1, 1, 1]}})")
                .find("/meshes/cube/plane/size: expected an array of 2 numbers [width, depth]"),
            std::string::npos);
}

TEST(LevelErrors, triangle_limit_is_checked_before_a_mesh_is_built) {
  // 2 * 4096 * 244 = 1998848 triangles fit; a second sphere does not.
  const std::string big = R"({"sphere": {"radius": 1, "segments": 4096, "rings": 245}})";
  const std::string text = replaced(kMinimalLevel, R"("cube": {"box": {"size": [1, 1, 1]}})",
                                    R"("a": )" + big + R"(, "cube": {"box": {"size": [1, 1, 1]}},
                                     "b": )" +
                                        big);
  EXPECT_NE(parseError(text).find("/meshes/b: this mesh brings the level to 3997708 triangles, "
                                  "more than the limit of 2000000"),
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
                .find("/meshes/cube: \"mesh\" picks part of a glTF model and needs \"gltf\""),
            std::string::npos);
  EXPECT_EQ(meshError(R"({"gltf": "a.gltf", "node": "A", "mesh": "B"})"),
            "levels/test.json:6:54: /meshes/cube: \"node\" and \"mesh\" both pick part of the "
            "model; give only one");
}

TEST(LevelErrors, scale_light_and_entity_values_are_checked) {
  auto entityError = [](const std::string& extra) {
    return parseError(
        replaced(kMinimalLevel, R"("material": "grey")", R"("material": "grey", )" + extra));
  };
  EXPECT_NE(entityError(R"("scale": 0)")
                .find("/entities/crate/scale: expected a number in (0, "
                      "100000], got 0"),
            std::string::npos);
  EXPECT_NE(entityError(R"("scale": "big")")
                .find("/entities/crate/scale: expected a number > 0 or an array of 3 numbers > 0, "
                      "got \"big\""),
            std::string::npos);
  EXPECT_NE(
      entityError(R"("casts_shadow": "no")")
          .find(
              "/entities/crate/casts_shadow: expected true, false or \"directional\", got \"no\""),
      std::string::npos);
  EXPECT_NE(entityError(R"("mover": {"keyframes": [{}, {}]}, "interactable": {"type": "slide"})")
                .find("/entities/crate: an entity is a mover or interactable, not both"),
            std::string::npos);
  EXPECT_NE(entityError(R"("interactable": {"type": "slide", "axis": [0, 0, 0], "min": 0,
                                             "max": 1})")
                .find("/entities/crate/interactable/axis: expected a non-zero direction [x, y, z], "
                      "got [0,0,0]"),
            std::string::npos);
  EXPECT_NE(entityError(R"("interactable": {"type": "rotate", "min_degrees": 10,
                                             "max_degrees": 5})")
                .find("/entities/crate/interactable/max_degrees: expected a number >= min_degrees "
                      "(10), got 5"),
            std::string::npos);
  EXPECT_NE(entityError(R"("interactable": {"type": "slide", "axis": [1, 0, 0], "min": 0,
                                             "max": 1, "start": 2})")
                .find("/entities/crate/interactable/start: expected a number from min to max, [0, "
                      "1], got 2"),
            std::string::npos);
  EXPECT_NE(entityError(R"("interactable": {"type": "slide", "light": "x"})")
                .find("/entities/crate/interactable: unknown key \"light\" for a slide "
                      "interactable; allowed keys: \"type\", \"axis\", \"min\", \"max\", "
                      "\"start\""),
            std::string::npos);
  EXPECT_NE(entityError(R"("mover": {"keyframes": [{}], "repeat": "pingpong"})")
                .find("/entities/crate/mover/repeat: expected one of \"once\", \"loop\", "
                      "\"ping_pong\", got \"pingpong\"; did you mean \"ping_pong\"?"),
            std::string::npos);
  EXPECT_NE(entityError(R"("mover": {"keyframes": [{}]})")
                .find("/entities/crate/mover/keyframes: expected 2 to 256 keyframes, got 1"),
            std::string::npos);

  auto lightError = [](const std::string& light) {
    return parseError(
        replaced(kMinimalLevel, R"("lights": {})", R"("lights": {"l": )" + light + "}"));
  };
  EXPECT_NE(lightError(R"({"type": "directional", "direction": [0, 0, 0], "intensity": 1})")
                .find("/lights/l/direction: expected a non-zero direction [x, y, z], got [0,0,0]"),
            std::string::npos);
  EXPECT_NE(lightError(R"({"type": "spot", "intensity": 1})")
                .find("/lights/l/type: expected one of \"point\", \"directional\", \"sphere\", "
                      "\"rectangle\", \"disk\", got \"spot\""),
            std::string::npos);
  EXPECT_NE(lightError(R"({"type": "disc", "intensity": 1})").find("did you mean \"disk\"?"),
            std::string::npos);
  EXPECT_NE(lightError(R"({"type": "point", "position": [0, 0, 0], "intensity": -1})")
                .find("/lights/l/intensity: expected a number in [0, 1000000000], got -1"),
            std::string::npos);
  EXPECT_NE(lightError(R"({"type": "point", "direction": [0, 0, 1], "intensity": 1})")
                .find("/lights/l: unknown key \"direction\" for a point light; allowed keys: "
                      "\"type\", \"position\", \"color\", \"intensity\", \"enabled\""),
            std::string::npos);
  EXPECT_NE(lightError(R"({"type": "directional", "direction": [0, -1, 0], "intensity": 1,
                          "angular_diameter_degrees": 31})")
                .find("/lights/l/angular_diameter_degrees: expected a number in [0, 30], got 31"),
            std::string::npos);
  EXPECT_NE(lightError(R"({"type": "rectangle", "position": [0, 0, 0], "direction": [0, -1, 0],
                          "intensity": 1})")
                .find("/lights/l: missing required key \"size\""),
            std::string::npos);
}

TEST(LevelErrors, goals_and_lose_conditions_are_checked) {
  auto goalError = [](const std::string& goal) {
    return parseError(replaced(kMinimalLevel, R"("lights": {})", R"("goal": )" + goal));
  };
  EXPECT_NE(goalError(R"({"type": "all", "of": []})")
                .find("/goal/of: expected an array of 1 to 16 goals, got []"),
            std::string::npos);
  EXPECT_NE(goalError(R"({"type": "reach", "min": [0, 0, 0], "max": [1, 0, 1]})")
                .find("/goal/max/1: expected a number > min[1] (0), got 0"),
            std::string::npos);
  EXPECT_NE(goalError(R"({"type": "focus", "orb": "crate", "region": [0, 0.5]})")
                .find("/goal/region/0: expected a number in (0, 1], got 0"),
            std::string::npos);
  EXPECT_NE(goalError(R"({"type": "lit", "sensor": "crate"})")
                .find("/goal: missing required key \"light\""),
            std::string::npos);
  EXPECT_NE(goalError(R"({"of": []})").find("/goal: missing required key \"type\""),
            std::string::npos);
  std::string nested = R"({"type": "reach", "min": [0, 0, 0], "max": [1, 1, 1]})";
  for (int depth = 0; depth < 9; ++depth) nested = R"({"type": "any", "of": [)" + nested + "]}";
  EXPECT_NE(goalError(nested).find("goals nest more than 8 deep, the limit"), std::string::npos);

  auto loseError = [](const std::string& lose) {
    return parseError(replaced(kMinimalLevel, R"("lights": {})", R"("lose": )" + lose));
  };
  EXPECT_NE(loseError(R"({"type": "fall", "below": 0})")
                .find("/lose: expected an array of lose conditions, got an object"),
            std::string::npos);
  EXPECT_NE(loseError(R"([{"type": "fall", "below": 0}, {"type": "stelth"}])")
                .find("/lose/1/type: expected one of \"stealth\", \"fall\", got \"stelth\"; did "
                      "you mean \"stealth\"?"),
            std::string::npos);
}

TEST(LevelErrors, ids_format_and_structure_are_checked) {
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"("grey": {)", R"("gr ey": {)")),
            "levels/test.json:5:17: /materials: invalid material id \"gr ey\": ids are "
            "non-empty and use only letters, digits, '_' and '-'");
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"("format": 1)", R"("format": 2)")),
            "levels/test.json:2:13: /format: unsupported format 2; this version reads format 1");
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"("name": "Test")", R"("name": "")")),
            "levels/test.json:3:11: /name: expected a string of 1 to 80 characters, got \"\"");
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"("name": "Test")",
                                R"("name": ")" + std::string(81, 'x') + "\"")),
            "levels/test.json:3:11: /name: expected a string of 1 to 80 characters, got 81 "
            "characters");
  // Characters, not bytes: 80 two-byte letters fit.
  std::string eighty;
  for (int i = 0; i < 80; ++i) eighty += "\xC3\xA9";
  EXPECT_EQ(
      game::parseLevel(replaced(kMinimalLevel, R"("name": "Test")", R"("name": ")" + eighty + "\""),
                       "levels/test.json")
          .name,
      eighty);
  EXPECT_NE(parseError(replaced(kMinimalLevel, R"("name": "Test")",
                                R"("name": "Test", "hint": ")" + std::string(2001, 'x') + "\""))
                .find("/hint: expected a string of 0 to 2000 characters, got 2001 characters"),
            std::string::npos);
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"({"crate": {"mesh": "cube", "material": "grey"}})",
                                "{}")),
            "levels/test.json:7:15: /entities: a level needs at least one entity, got {}");
  EXPECT_EQ(parseError("[1, 2]"), "levels/test.json:1:1: expected an object, got [1,2]");
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"(  "format": 1,)", "")),
            "levels/test.json:1:1: missing required key \"format\"");
}

TEST(LevelErrors, section_sizes_are_limited) {
  std::string lights;
  for (int i = 0; i < 65; ++i) {
    lights += (i == 0 ? "" : ", ") + std::string("\"l") + std::to_string(i) +
              R"(": {"type": "point", "position": [0, 0, 0], "intensity": 1})";
  }
  EXPECT_EQ(parseError(replaced(kMinimalLevel, R"("lights": {})", R"("lights": {)" + lights + "}")),
            "levels/test.json:8:13: /lights: 65 lights, more than the limit of 64");
  std::string keyframes;
  for (int i = 0; i < 257; ++i) keyframes += (i == 0 ? "{}" : ", {}");
  EXPECT_NE(
      parseError(replaced(kMinimalLevel, R"("material": "grey")",
                          R"("material": "grey", "mover": {"keyframes": [)" + keyframes + "]}"))
          .find("/entities/crate/mover/keyframes: 257 keyframes, more than the limit of 256"),
      std::string::npos);
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
  EXPECT_EQ(level.sourceFiles, std::vector<fs::path>{root_ / "levels" / "one.json"});
}

// ----- model and texture files -----

// The message for a level whose cube mesh is a glTF model at `path`.
std::string gltfPathError(const std::string& path) {
  return parseError(
      replaced(kMinimalLevel, R"({"box": {"size": [1, 1, 1]}})", R"({"gltf": ")" + path + R"("})"));
}

TEST(LevelErrors, loader_rejects_asset_path_outside_level_root) {
  EXPECT_EQ(gltfPathError("../../etc/passwd"),
            "levels/test.json:6:31: /meshes/cube/gltf: model path \"../../etc/passwd\" leaves the "
            "level's directory and the asset directory");
  EXPECT_EQ(
      gltfPathError("models/../../../x.gltf"),
      "levels/test.json:6:31: /meshes/cube/gltf: model path \"models/../../../x.gltf\" leaves "
      "the level's directory and the asset directory");
  EXPECT_EQ(gltfPathError("/etc/model.gltf"),
            "levels/test.json:6:31: /meshes/cube/gltf: model path \"/etc/model.gltf\" is absolute; "
            "write it relative to the level file or starting with \"assets/\"");
  EXPECT_NE(gltfPathError("C:/models/a.gltf").find("is absolute"), std::string::npos);
  EXPECT_EQ(gltfPathError("models%2F..%2Fx.gltf"),
            "levels/test.json:6:31: /meshes/cube/gltf: model path \"models%2F..%2Fx.gltf\" "
            "contains '%': percent-encoding is not supported; write the file name as it is on "
            "disk");
  EXPECT_EQ(gltfPathError(R"(models\\a.gltf)"),
            "levels/test.json:6:31: /meshes/cube/gltf: model path \"models\\a.gltf\" contains a "
            "backslash; separate directories with '/'");
  EXPECT_EQ(gltfPathError("model.obj"),
            "levels/test.json:6:31: /meshes/cube/gltf: expected a path to a .gltf or .glb file, "
            "got \"model.obj\"");
  EXPECT_EQ(gltfPathError("missing.gltf"),
            "levels/test.json:6:31: /meshes/cube/gltf: model file \"missing.gltf\" not found "
            "(looked for levels/missing.gltf)");
}

TEST_F(TempDirTest, loader_rejects_symlink_that_leaves_the_level_directory) {
  writeGltf(root_ / "outside" / "box.gltf",
            makeGltf(game::primitives::box(glm::vec3(1)), IndexType::U16), false);
  fs::create_directories(root_ / "levels");
  fs::create_directory_symlink(root_ / "outside", root_ / "levels" / "linked");
  writeFile(
      root_ / "levels" / "one.json",
      replaced(kMinimalLevel, R"({"box": {"size": [1, 1, 1]}})", R"({"gltf": "linked/box.gltf"})"));
  EXPECT_EQ(loadError(root_ / "levels" / "one.json"),
            (root_ / "levels" / "one.json").string() +
                ":6:31: /meshes/cube/gltf: model path \"linked/box.gltf\" leads outside the "
                "level's directory and the asset directory through a symbolic link");

  // A link to a single file is followed the same way; one that stays inside is fine.
  fs::create_symlink(root_ / "outside" / "box.gltf", root_ / "levels" / "box.gltf");
  writeFile(root_ / "levels" / "two.json",
            replaced(kMinimalLevel, R"({"box": {"size": [1, 1, 1]}})", R"({"gltf": "box.gltf"})"));
  EXPECT_NE(loadError(root_ / "levels" / "two.json").find("through a symbolic link"),
            std::string::npos);
  fs::create_directories(root_ / "levels" / "models");
  fs::rename(root_ / "outside" / "box.gltf", root_ / "levels" / "models" / "box.gltf");
  fs::rename(root_ / "outside" / "box.bin", root_ / "levels" / "models" / "box.bin");
  fs::create_directory_symlink(root_ / "levels" / "models", root_ / "levels" / "alias");
  writeFile(
      root_ / "levels" / "three.json",
      replaced(kMinimalLevel, R"({"box": {"size": [1, 1, 1]}})", R"({"gltf": "alias/box.gltf"})"));
  EXPECT_EQ(game::loadLevel(root_ / "levels" / "three.json").meshes[0].indices.size(), 36u);
}

TEST_F(TempDirTest, level_loads_a_gltf_box_next_to_the_level) {
  const scene::MeshData box = game::primitives::box({1, 2, 3});
  writeGltf(root_ / "levels" / "models" / "box.gltf", makeGltf(box, IndexType::U16), false);
  writeFile(
      root_ / "levels" / "one.json",
      replaced(kMinimalLevel, R"({"box": {"size": [1, 1, 1]}})", R"({"gltf": "models/box.gltf"})"));
  const game::Level level = game::loadLevel(root_ / "levels" / "one.json");
  ASSERT_EQ(level.meshes.size(), 1u);
  const scene::MeshData& mesh = level.meshes[0];
  EXPECT_EQ(mesh.name, "cube");  // the level's mesh id
  EXPECT_EQ(mesh.indices.size() / 3, 12u);
  EXPECT_EQ(mesh.vertices.size(), 24u);
  expectOutwardFacing(mesh);
  // Normals were computed from the faces and match the box's own.
  for (std::size_t i = 0; i < box.vertices.size(); ++i) {
    EXPECT_EQ(mesh.vertices[i].position, box.vertices[i].position);
    EXPECT_NEAR(glm::length(mesh.vertices[i].normal - box.vertices[i].normal), 0.0f, 1e-6f);
  }
  EXPECT_EQ(level.sourceFiles, (std::vector<fs::path>{root_ / "levels" / "one.json",
                                                      root_ / "levels" / "models" / "box.gltf",
                                                      root_ / "levels" / "models" / "box.bin"}));
}

TEST_F(TempDirTest, assets_paths_resolve_against_the_asset_root) {
  writeGltf(root_ / "assets" / "models" / "box.glTF",
            makeGltf(game::primitives::box(glm::vec3(1)), IndexType::U32), false);
  writeFile(root_ / "levels" / "one.json",
            replaced(kMinimalLevel, R"({"box": {"size": [1, 1, 1]}})",
                     R"({"gltf": "assets/models/box.glTF"})"));
  // Default: the assets/ directory beside the level's directory.
  EXPECT_EQ(game::loadLevel(root_ / "levels" / "one.json").meshes[0].indices.size(), 36u);

  // Explicit asset roots replace the default; the first that exists is used.
  game::LevelLoadOptions options;
  fs::create_directories(root_ / "elsewhere");
  options.assetRoots = {root_ / "elsewhere"};
  EXPECT_EQ(loadError(root_ / "levels" / "one.json", options),
            (root_ / "levels" / "one.json").string() +
                ":6:31: /meshes/cube/gltf: model file \"assets/models/box.glTF\" not found "
                "(looked for " +
                (root_ / "elsewhere" / "models" / "box.glTF").string() + ")");
  options.assetRoots = {root_ / "nowhere", root_ / "assets", root_ / "elsewhere"};
  EXPECT_EQ(game::loadLevel(root_ / "levels" / "one.json", options).meshes[0].indices.size(), 36u);
  options.assetRoots = {root_ / "nowhere"};
  EXPECT_EQ(loadError(root_ / "levels" / "one.json", options),
            (root_ / "levels" / "one.json").string() +
                ":6:31: /meshes/cube/gltf: model path \"assets/models/box.glTF\" names the asset "
                "directory, but there is none (looked for \"" +
                (root_ / "nowhere").string() + "\")");

  // A relative path is relative to the level file only.
  writeFile(
      root_ / "levels" / "two.json",
      replaced(kMinimalLevel, R"({"box": {"size": [1, 1, 1]}})", R"({"gltf": "models/box.glTF"})"));
  EXPECT_NE(loadError(root_ / "levels" / "two.json").find("not found"), std::string::npos);
}

TEST_F(TempDirTest, gltf_material_textures_and_source_files) {
  const fs::path assets = fs::path(SIGHTLINE_SOURCE_DIR) / "assets";
  writeFile(root_ / "levels" / "crates.json", R"({
  "format": 1,
  "name": "Crates",
  "camera": {"position": [0, 1, 5]},
  "materials": {
    "painted": {"color": [1, 1, 1], "texture": "assets/crate_color.png",
                "normal_map": "assets/crate_normal.png"},
    "again": {"texture": "assets/crate_color.png"},
    "as_normals": {"normal_map": "assets/crate_color.png"}
  },
  "meshes": {
    "crate": {"gltf": "assets/crate.gltf"},
    "by_node": {"gltf": "assets/crate.gltf", "node": "crate"},
    "by_mesh": {"gltf": "assets/crate.gltf", "mesh": "crate"}
  },
  "entities": {
    "a": {"mesh": "crate"},
    "b": {"mesh": "crate", "position": [2, 0, 0]},
    "c": {"mesh": "by_node", "material": "painted"},
    "d": {"mesh": "by_mesh"}
  }
})");
  game::LevelLoadOptions options;
  options.assetRoots = {assets};
  const game::Level level = game::loadLevel(root_ / "levels" / "crates.json", options);

  // A file named twice is decoded once; the same file as a normal map is a second texture.
  ASSERT_EQ(level.materials.size(), 5u);
  EXPECT_EQ(level.materials[0].colorTexture, 0);
  EXPECT_EQ(level.materials[0].normalTexture, 1);
  EXPECT_EQ(level.materials[1].colorTexture, 0);
  EXPECT_EQ(level.materials[2].normalTexture, 2);
  EXPECT_EQ(level.materials[2].colorTexture, -1);
  ASSERT_EQ(level.textures.size(), 3u);  // the model's textures are the same images
  EXPECT_TRUE(level.textures[0].srgb);
  EXPECT_FALSE(level.textures[1].srgb);
  EXPECT_FALSE(level.textures[2].srgb);
  EXPECT_EQ(level.textures[0].width, 64u);
  EXPECT_EQ(level.textures[1].width, 32u);

  // Entities without a material use the model's, one per mesh, named after it.
  ASSERT_EQ(level.materialIds, (std::vector<std::string>{"painted", "again", "as_normals",
                                                         "crate#gltf", "by_mesh#gltf"}));
  EXPECT_EQ(level.entities[0].material, 3u);
  EXPECT_EQ(level.entities[1].material, 3u);
  EXPECT_EQ(level.entities[2].material, 0u);
  EXPECT_EQ(level.entities[3].material, 4u);
  const scene::MaterialDesc& wood = level.materials[3];
  EXPECT_EQ(wood.kind, scene::MaterialKind::Diffuse);
  EXPECT_EQ(wood.baseColor, glm::vec3(0.9f, 0.85f, 0.8f));  // glTF factors are linear already
  EXPECT_TRUE(wood.metallicRoughness);                      // glTF's own shading model
  EXPECT_FLOAT_EQ(wood.metallic, 0.0f);
  EXPECT_FLOAT_EQ(wood.roughness, 0.75f);
  EXPECT_EQ(wood.colorTexture, 0);
  EXPECT_EQ(wood.normalTexture, 1);

  EXPECT_EQ(level.meshes[0].indices.size(), level.meshes[1].indices.size());
  EXPECT_EQ(level.meshes[1].name, "by_node");
  EXPECT_EQ(level.sourceFiles,
            (std::vector<fs::path>{root_ / "levels" / "crates.json", assets / "crate_color.png",
                                   assets / "crate_normal.png", assets / "crate.gltf",
                                   assets / "crate.bin"}));
  const game::LevelFeatures features = game::levelFeatures(level);
  EXPECT_TRUE(features.textures);
  EXPECT_EQ(game::buildSceneDesc(level).textures.size(), 3u);
}

TEST_F(TempDirTest, gltf_without_a_material_needs_one_from_the_level) {
  writeGltf(root_ / "levels" / "box.gltf",
            makeGltf(game::primitives::box(glm::vec3(1)), IndexType::U16), true);
  writeFile(root_ / "levels" / "one.json",
            replaced(replaced(kMinimalLevel, R"({"box": {"size": [1, 1, 1]}})",
                              R"({"gltf": "box.gltf"})"),
                     R"("mesh": "cube", "material": "grey")", R"("mesh": "cube")"));
  EXPECT_EQ(loadError(root_ / "levels" / "one.json"),
            (root_ / "levels" / "one.json").string() +
                ":7:25: /entities/crate: missing required key \"material\" (mesh \"cube\" is a "
                "glTF model without a material, so the entity must name one)");
}

TEST_F(TempDirTest, texture_paths_follow_the_path_rules) {
  fs::create_directories(root_ / "levels");
  fs::copy_file(fs::path(SIGHTLINE_SOURCE_DIR) / "assets" / "crate_color.png",
                root_ / "levels" / "wood.PNG");
  auto textureError = [&](const std::string& path) {
    writeFile(root_ / "levels" / "one.json",
              replaced(kMinimalLevel, R"({"color": [0.5, 0.5, 0.5]})",
                       R"({"texture": ")" + path + R"("})"));
    return loadError(root_ / "levels" / "one.json");
  };
  const std::string prefix = (root_ / "levels" / "one.json").string() + ":5:37: ";
  EXPECT_EQ(textureError("wood.PNG"), "(no error)");
  EXPECT_EQ(textureError("wood.bmp"),
            prefix +
                "/materials/grey/texture: expected a path to a .png, .jpg or .jpeg file, got "
                "\"wood.bmp\"");
  EXPECT_EQ(textureError("../levels/../../wood.png"),
            prefix +
                "/materials/grey/texture: texture path \"../levels/../../wood.png\" leaves the "
                "level's directory and the asset directory");
  EXPECT_EQ(textureError("wood%20.png"),
            prefix +
                "/materials/grey/texture: texture path \"wood%20.png\" contains '%': "
                "percent-encoding is not supported; write the file name as it is on disk");
  writeFile(root_ / "levels" / "broken.png", "not a png");
  EXPECT_EQ(textureError("broken.png")
                .rfind(prefix + "/materials/grey/texture: " +
                           (root_ / "levels" / "broken.png").string() + ": ",
                       0),
            0u);
}

TEST_F(TempDirTest, gltf_with_embedded_buffer_and_byte_indices_loads) {
  writeGltf(root_ / "box.gltf", makeGltf(game::primitives::box(glm::vec3(1)), IndexType::U8), true);
  const scene::MeshData mesh = game::loadGltfMesh(root_ / "box.gltf", root_);
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
  const scene::MeshData mesh = game::loadGltfMesh(root_ / "box.glb", root_);
  EXPECT_EQ(mesh.indices.size(), 36u);
  expectOutwardFacing(mesh);
}

TEST_F(TempDirTest, gltf_without_indices_gets_flat_normals) {
  scene::MeshData unindexed;
  const scene::MeshData box = game::primitives::box(glm::vec3(2));
  for (const uint32_t index : box.indices) unindexed.vertices.push_back(box.vertices[index]);
  writeGltf(root_ / "soup.gltf", makeGltf(unindexed, IndexType::None), true);
  const scene::MeshData mesh = game::loadGltfMesh(root_ / "soup.gltf", root_);
  EXPECT_EQ(mesh.vertices.size(), 36u);
  EXPECT_EQ(mesh.indices.size(), 36u);
  expectOutwardFacing(mesh);
}

TEST_F(TempDirTest, gltf_node_transforms_apply_and_mirroring_keeps_faces_outward) {
  GltfFile file = makeGltf(game::primitives::box(glm::vec3(1)), IndexType::U16);
  file.document["nodes"] = {{{"children", {1}}, {"translation", {10, 0, 0}}},
                            {{"mesh", 0}, {"scale", {-2, 1, 1}}}};
  writeGltf(root_ / "mirrored.gltf", file, true);
  const scene::MeshData mesh = game::loadGltfMesh(root_ / "mirrored.gltf", root_);
  EXPECT_EQ(mesh.indices.size(), 36u);
  for (const auto& vertex : mesh.vertices) EXPECT_FLOAT_EQ(std::abs(vertex.position.x - 10), 1.0f);
  expectOutwardFacing(mesh, {10, 0, 0});
}

TEST_F(TempDirTest, gltf_mesh_can_be_picked_by_name) {
  GltfFile file = makeGltf(game::primitives::box(glm::vec3(1)), IndexType::U16);
  file.document["nodes"][0]["translation"] = {5, 0, 0};
  writeGltf(root_ / "named.gltf", file, true);
  const scene::MeshData mesh = game::loadGltfMesh(root_ / "named.gltf", root_, "Cube");
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
