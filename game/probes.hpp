#pragma once
// The game's eyes: what the ray-gen shader measures for the rules, and the readings it returns.
// The renderer fills ProbeReadings from its probe buffer; game/rules turns them into progress.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "game/level.hpp"

namespace game {

// A focus goal's probe: the share of the centred focus region whose final path reached the
// entity (directly, through glass or via mirrors).
struct FocusProbe {
  uint32_t entity = 0;           // index into Level::entities
  glm::vec2 region{0.2f, 0.2f};  // centred box, fractions of the screen width and height
};

// Exposure of a sensor entity (a lit goal) or of the player's body (stealth) to one light.
struct ExposureProbe {
  enum class Target { Entity, Player };
  Target target = Target::Entity;
  uint32_t entity = 0;  // Target::Entity: index into Level::entities
  uint32_t light = 0;   // index into Level::lights
  // For the HUD's meter: what it measures, in the player's words, and the reading that counts
  // (a lit sensor at or above it; a watcher sees the player above it).
  std::string label;
  float threshold = 0.5f;
  // A colour sensor counts one channel of the light (times the tints on the way).
  scene::ExposureChannel channel = scene::ExposureChannel::Luminance;
};

// Every probe a level needs, in a fixed order: focus goals and lit goals in the order they
// appear in the goal tree (depth first), then stealth lose conditions in file order, then the
// focus, lit and seen conditions of the logic's rules (file order, depth first).
struct ProbeLayout {
  std::vector<FocusProbe> focus;
  std::vector<ExposureProbe> exposure;
  size_t firstLogicFocus = 0;  // where the logic's probes start
  size_t firstLogicExposure = 0;
};
ProbeLayout probeLayout(const Level& level);

// One probe frame's results, parallel to ProbeLayout's vectors.
struct ProbeReadings {
  uint64_t tick = 0;                 // the simulation tick whose world state was rendered
  std::vector<float> focusCoverage;  // [0, 1]: covered pixels / focus-region pixels
  std::vector<float> exposure;       // [0, 1]: share of sample points on the target that see
                                     // the light (area lights: over points on the light)
};

// Which exposure meters the HUD shows when it has room for `rows`, in the layout's order: a
// watcher's first (being seen loses the level), then those reading something, then the rest;
// a meter with the same words as an earlier one measures the same thing and is shown once.
// `readings` may be empty (none arrived yet).
std::vector<size_t> hudMeters(const std::vector<ExposureProbe>& meters,
                              const std::vector<float>& readings, size_t rows);

}  // namespace game
