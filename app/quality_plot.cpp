#include "app/quality_plot.hpp"

#include <cmath>

#include <glm/glm.hpp>

#include "game/collision.hpp"

namespace app {
namespace {

glm::vec3 rightOf(const scene::CameraDesc& camera) {
  const float yaw = glm::radians(camera.yawDegrees);
  return glm::vec3(std::cos(yaw), 0.0f, -std::sin(yaw));
}

}  // namespace

scene::CameraDesc strafed(scene::CameraDesc camera, float metres) {
  camera.position += rightOf(camera) * metres;
  return camera;
}

Walk walkWithRoom(const game::Level& level, float metres) {
  constexpr float kClearance = 0.3f;  // what the camera keeps from a wall at the end
  const game::CollisionWorld world(level);
  const glm::vec3 right = rightOf(level.camera);
  const glm::vec3 ahead(right.z, 0.0f, -right.x);
  const Walk walks[] = {
      {"to its right", right}, {"to its left", -right}, {"ahead", ahead}, {"backwards", -ahead}};
  const float reach = metres + kClearance;
  Walk roomiest = walks[0];
  float most = -1.0f;
  for (const Walk& walk : walks) {
    const auto hit = world.rayCast(level.camera.position, walk.direction, reach);
    const float room = hit ? hit->distance : reach;
    if (room >= reach) return walk;
    if (room > most) {
      most = room;
      roomiest = walk;
    }
  }
  return roomiest;
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
