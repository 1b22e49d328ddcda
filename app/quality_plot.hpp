#pragma once
// What the image-quality benches (bench-quality, bench-upscale) share: a camera strafing to the
// side (bench --strafe uses it too), and the frame of an SVG plot (background, title, axes box
// and labels).
#include <ostream>
#include <string>

#include <glm/glm.hpp>

#include "game/level.hpp"
#include "scene/scene_desc.hpp"

namespace app {

// `camera` moved `metres` to its right (along the ground, by its yaw); negative: to its left.
scene::CameraDesc strafed(scene::CameraDesc camera, float metres);
// How far bench-quality's moving camera, and bench's with --strafe, strafes a frame.
inline constexpr float kStrafeStepMetres = 0.01f;

// Where a camera walking `metres` from the level's camera can go without passing through a
// wall (a walk into one would measure its inside), by ray casts against the level's geometry:
// its right, its left, ahead or behind, the first with room; where none has, the one with most.
struct Walk {
  const char* name = "to its right";
  glm::vec3 direction{1.0f, 0.0f, 0.0f};  // unit, in the ground plane
};
Walk walkWithRoom(const game::Level& level, float metres);

// The plot area of every quality plot, in SVG pixels.
struct PlotArea {
  double left = 70, top = 40, width = 560, height = 360;
};

// Writes the SVG header, a white page, the title, the plot's box and the axis labels.
void writePlotFrame(std::ostream& svg, const PlotArea& area, const std::string& title,
                    const std::string& xLabel, const std::string& yLabel);

}  // namespace app
