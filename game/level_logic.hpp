#pragma once
// A level's logic as plain data: named rules, each a condition over what the game knows (probe
// readings, the player's place, interactables, time, other rules) and the actions it runs on
// the world. game/logic.hpp runs them; docs/LEVELS.md ("Logic") is the author's description.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/probes.hpp"

namespace game {

struct Condition {
  enum class Type {
    Focus,     // the orb covers `coverage` of the centred focus region
    Lit,       // the sensor's exposure to `light` ≥ threshold
    Seen,      // the player's exposure to the watcher `light` > threshold
    Inside,    // the player's feet inside [min, max]
    Rotation,  // a rotate interactable's angle in [low, high] degrees
    Slide,     // a slide interactable's offset in [low, high] metres
    Switch,    // a switch interactable is on (or off)
    Timer,     // `seconds` since the level started, or since `rule` last fired
    Fired,     // `rule` has fired
    All,
    Any,
    Not,
  };
  Type type = Type::Fired;
  uint32_t entity = 0;           // Focus: the orb; Lit: the sensor; Rotation/Slide/Switch
  uint32_t light = 0;            // Lit, Seen
  std::string label;             // Lit, Seen: the HUD meter's words; "" for the default ones
  glm::vec2 region{0.2f, 0.2f};  // Focus
  float coverage = 0.5f;         // Focus
  float threshold = 0.5f;        // Lit, Seen
  scene::ExposureChannel channel = scene::ExposureChannel::Luminance;  // Lit: "color"
  glm::vec3 min{0.0f};                                                 // Inside
  glm::vec3 max{0.0f};                                                 // Inside
  float low = 0.0f;                                                    // Rotation, Slide
  float high = 0.0f;                                                   // Rotation, Slide
  bool on = true;                                                      // Switch
  float seconds = 0.0f;                                                // Timer
  std::optional<uint32_t> rule;     // Fired; Timer: since this rule last fired
  float holdSeconds = 0.0f;         // the condition must hold this long before it counts
  std::vector<Condition> children;  // All, Any; Not: exactly one
};

struct Action {
  enum class Type {
    Play,     // a mover runs forwards
    Reverse,  // a mover runs backwards
    Stop,     // a mover stops where it is
    Goto,     // a mover runs to `keyframe` and stops there
    LightOn,
    LightOff,
    LightToggle,
    Show,  // an entity is rendered, traced and collided with again
    Hide,  // ... or not
    Lock,  // an interactable cannot be used
    Unlock,
    SetRespawn,  // a fall puts the player back at `position` instead of losing the level
    Message,     // `text` on the HUD for `seconds`
    Win,
    Lose,
  };
  Type type = Type::Win;
  uint32_t entity = 0;       // Play/Reverse/Stop/Goto: the mover; Show/Hide; Lock/Unlock
  uint32_t light = 0;        // LightOn/LightOff/LightToggle
  uint32_t keyframe = 0;     // Goto
  glm::vec3 position{0.0f};  // SetRespawn: the feet
  float yawDegrees = 0.0f;   // SetRespawn
  std::string text;          // Message; Lose: the reason shown
  float seconds = 3.0f;      // Message
};

struct Rule {
  // Once: fires the first time its condition becomes true. Repeat: every time it becomes true.
  // While: its actions hold while the condition does and are undone when it stops holding.
  enum class Mode { Once, Repeat, While };
  std::string id;
  Mode mode = Mode::Once;
  Condition condition;
  std::vector<Action> actions;
};

// The name a level file gives the action kind ("light_toggle"), as its "do" field reads it.
const char* actionName(Action::Type type);

}  // namespace game
