#pragma once
// What level authors read off the running game (play's F3 overlay and copy key): what the
// crosshair is on, and the current view and point as JSON to paste into a level.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "game/level.hpp"
#include "game/world.hpp"

namespace game {

struct CrosshairTarget {
  uint32_t entity = 0;
  glm::vec3 point{0.0f};  // in level coordinates
  float distance = 0.0f;  // from the eye, metres
};

// How far the overlay looks: far enough for any level's far wall.
constexpr float kAuthorViewMetres = 500.0f;

// The nearest surface on the view's centre line (what collides: shown entities), if any.
std::optional<CrosshairTarget> crosshairTarget(const World& world);

// The overlay's lines for it: "entity gate, material gate", "at (0.00, 1.50, 4.00), 3.21 m",
// and for an interactable its state: "rotate 45.0 degrees of 0..90", "slide 0.60 m of 0..1",
// "switch on"; ", locked" when a rule locked it.
std::vector<std::string> describeCrosshair(const Level& level, const World& world,
                                           const CrosshairTarget& target);

// The current view as a level's camera block, one line:
// "camera": { "position": [x, y, z], "yaw_degrees": Y, "pitch_degrees": P, "fov_degrees": F }
std::string cameraJson(const World& world);

// A point as an entity's position member: "position": [x, y, z] (two decimals).
std::string positionJson(const glm::vec3& point);

}  // namespace game
