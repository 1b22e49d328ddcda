#pragma once
// A loaded level: plain data, fully validated. No Vulkan here.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "game/level_logic.hpp"
#include "scene/scene_desc.hpp"

namespace game {

struct Keyframe {
  glm::vec3 position{0.0f};
  glm::vec3 rotationDegrees{0.0f};  // same convention as Entity::rotationDegrees
};

// A keyframed path; keyframes are evenly spaced over the duration.
struct Mover {
  enum class Repeat { Once, Loop, PingPong };
  enum class Easing { Linear, Smooth, EaseIn, EaseOut };
  float durationSeconds = 1.0f;
  Repeat repeat = Repeat::Loop;
  Easing easing = Easing::Linear;
  std::vector<Keyframe> keyframes;  // 2..256
  bool startsPlaying = true;        // false: waits at its first keyframe for a rule to play it
};

struct Interactable {
  enum class Type { Rotate, Slide, Switch };
  Type type = Type::Rotate;
  glm::vec3 axis{0.0f, 1.0f, 0.0f};  // unit; Rotate: rotation axis, Slide: rail direction
  float min = 0.0f;                  // Rotate: degrees, Slide: metres
  float max = 0.0f;
  float start = 0.0f;
  uint32_t light = 0;  // Switch: index into Level::lights
  bool startsOn = true;
};

// The name a level file gives the interactable kind ("rotate", "slide", "switch").
const char* interactableName(Interactable::Type type);

struct Entity {
  std::string id;
  uint32_t mesh = 0;      // index into Level::meshes
  uint32_t material = 0;  // index into Level::materials
  // A glTF mesh of several materials shown with its own: the level material for each of the
  // mesh's (empty: `material` everywhere, as when the entity names one).
  std::vector<uint32_t> meshMaterials;
  glm::vec3 position{0.0f};
  glm::vec3 rotationDegrees{0.0f};  // x: pitch, y: yaw, z: roll; applied yaw, pitch, roll
  glm::vec3 scale{1.0f};
  bool castsShadow = true;
  // "casts_shadow": "directional": it shadows directional lights only (with castsShadow).
  bool shadowsDirectionalOnly = false;
  std::optional<Mover> mover;  // at most one of mover and interactable
  std::optional<Interactable> interactable;
};

struct Goal {
  enum class Type { Focus, Lit, Reach, All, Any };
  Type type = Type::Focus;
  std::string label;             // the player's words for it; "" for the default ones
  uint32_t entity = 0;           // Focus: the orb; Lit: the sensor (index into entities)
  uint32_t light = 0;            // Lit: index into lights
  glm::vec2 region{0.2f, 0.2f};  // Focus: centred box, fractions of the screen
  float coverage = 0.5f;         // Focus
  float risePerSecond = 0.5f;    // Focus
  float fallPerSecond = 0.25f;   // Focus
  float threshold = 0.5f;        // Lit
  scene::ExposureChannel channel = scene::ExposureChannel::Luminance;  // Lit: "color"
  float holdSeconds = 0.0f;                                            // Lit
  glm::vec3 min{0.0f};                                                 // Reach
  glm::vec3 max{0.0f};                                                 // Reach
  std::vector<Goal> children;                                          // All, Any
};

struct LoseCondition {
  enum class Type { Stealth, Fall };
  Type type = Type::Fall;
  std::string label;           // the player's words for it; "" for the default ones
  uint32_t light = 0;          // Stealth: the watcher
  float exposureLimit = 0.5f;  // Stealth
  float seconds = 1.0f;        // Stealth
  float below = 0.0f;          // Fall: height in metres
};

struct Level {
  std::filesystem::path file;  // the JSON it came from
  int format = 1;
  std::string name;
  std::string description;
  std::string author;
  std::string hint;
  scene::CameraDesc camera;
  scene::EnvironmentDesc environment;  // sky colours already times sky_intensity
  uint32_t maxMirrorBounces = 4;
  bool lightViaMirrors = true;           // "light_via_mirrors": flat mirrors send lights' light on
  std::vector<std::string> materialIds;  // parallel to materials
  std::vector<scene::MaterialDesc> materials;
  std::vector<scene::TextureDesc> textures;  // referenced by materials
  std::vector<std::string> meshIds;          // parallel to meshes
  std::vector<scene::MeshData> meshes;
  // Parallel to meshes: a glTF model's own materials by name, in mesh-material order (empty for
  // built-in shapes and models without materials), for `sightline info`.
  std::vector<std::vector<std::string>> meshMaterialNames;
  std::vector<Entity> entities;
  std::vector<std::string> lightIds;  // parallel to lights
  std::vector<scene::LightDesc> lights;
  // Parallel to lights: the entity a light rides on ("rides"), moving and turning with it.
  std::vector<std::optional<uint32_t>> lightCarriers;
  std::optional<Goal> goal;
  std::vector<LoseCondition> lose;
  std::vector<Rule> rules;  // the "logic" section, in file order
  // Every file the level was built from (the JSON, models, buffers, textures), for reload.
  std::vector<std::filesystem::path> sourceFiles;
  std::vector<std::string> warnings;  // e.g. degenerate triangles dropped, with file and count
};

glm::mat4 entityTransform(const Entity& entity);

// An entity's or light's id in double quotes, for messages and labels; "#2" for one without an
// id (levels built in code).
std::string quotedEntityId(const Level& level, uint32_t entity);
std::string quotedLightId(const Level& level, uint32_t light);

class World;

// What the renderer needs to draw the level, its entities and lights as `world` has them.
scene::SceneDesc buildSceneDesc(const Level& level, const World& world);
// The same as the level starts (interactables at their start values, movers at time 0,
// switches' lights as the switches start), from a World made for it.
scene::SceneDesc buildSceneDesc(const Level& level);

// The renderer features a level uses, for `sightline info` and pipeline variants.
struct LevelFeatures {
  size_t triangles = 0;  // summed over instances
  size_t instances = 0;
  size_t lights = 0;
  bool glass = false;
  bool mirrors = false;
  uint32_t mirrorBounces = 0;    // the level's max_mirror_bounces when it has mirrors, else 0
  bool lightViaMirrors = false;  // a flat mirror, a light and bounces: the LIGHT_ROUTES variant
  bool areaLights = false;       // any light with extent (area, or a sun with a diameter)
  bool textures = false;
  bool movers = false;
  bool interactables = false;
};
LevelFeatures levelFeatures(const Level& level);

}  // namespace game
