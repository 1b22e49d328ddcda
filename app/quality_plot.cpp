#include "app/quality_plot.hpp"

#include <cmath>

#include <glm/glm.hpp>

namespace app {

scene::CameraDesc strafed(scene::CameraDesc camera, float metres) {
  const float yaw = glm::radians(camera.yawDegrees);
  camera.position += glm::vec3(std::cos(yaw), 0.0f, -std::sin(yaw)) * metres;
  return camera;
}

void writePlotFrame(std::ostream& svg, const PlotArea& area, const std::string& title,
                    const std::string& xLabel, const std::string& yLabel) {
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='700' height='460' "
         "font-family='sans-serif' font-size='12'>\n<rect width='700' height='460' fill='white'/>\n"
      << "<text x='" << area.left << "' y='24' font-size='14'>" << title << "</text>\n"
      << "<rect x='" << area.left << "' y='" << area.top << "' width='" << area.width
      << "' height='" << area.height << "' fill='none' stroke='black'/>\n"
      << "<text x='" << area.left + area.width / 2 - 80 << "' y='" << area.top + area.height + 34
      << "'>" << xLabel << "</text>\n"
      << "<text x='14' y='" << area.top + area.height / 2 << "' transform='rotate(-90 14 "
      << area.top + area.height / 2 << ")'>" << yLabel << "</text>\n";
}

}  // namespace app
