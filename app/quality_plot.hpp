#pragma once
// What the image-quality benches (bench-quality, bench-upscale) share: a camera strafing to the
// right, and the frame of an SVG plot (background, title, axes box and labels).
#include <ostream>
#include <string>

#include "scene/scene_desc.hpp"

namespace app {

// `camera` moved `metres` to its right (along the ground, by its yaw).
scene::CameraDesc strafed(scene::CameraDesc camera, float metres);

// The plot area of every quality plot, in SVG pixels.
struct PlotArea {
  double left = 70, top = 40, width = 560, height = 360;
};

// Writes the SVG header, a white page, the title, the plot's box and the axis labels.
void writePlotFrame(std::ostream& svg, const PlotArea& area, const std::string& title,
                    const std::string& xLabel, const std::string& yLabel);

}  // namespace app
