#include "game/level_format/sections.hpp"

// The "camera" and "rendering" sections: where the level is seen from, and how deep mirrors go.
namespace game::level_format {

scene::CameraDesc readCamera(const LevelReader& reader, const OrderedJson& camera,
                             const std::string& pointer) {
  reader.checkKeys(camera, pointer, {"position", "yaw_degrees", "pitch_degrees", "fov_degrees"},
                   {"position"});
  scene::CameraDesc desc;
  desc.position =
      reader.readVec3(camera["position"], childPointer(pointer, "position"), kCoordinate);
  desc.yawDegrees = reader.readOptionalNumber(camera, "yaw_degrees", pointer, kAnyNumber, 0.0f);
  desc.pitchDegrees = reader.readOptionalNumber(camera, "pitch_degrees", pointer,
                                                NumberRule{-90.0, true, 90.0, true}, 0.0f);
  desc.verticalFovDegrees = reader.readOptionalNumber(camera, "fov_degrees", pointer,
                                                      NumberRule{0.0, false, 179.0, true}, 60.0f);
  return desc;
}

void readRendering(const LevelReader& reader, const OrderedJson& rendering,
                   const std::string& pointer, Level& level) {
  reader.checkKeys(rendering, pointer, {"max_mirror_bounces", "light_via_mirrors"}, {});
  level.maxMirrorBounces =
      reader.readOptionalCount(rendering, "max_mirror_bounces", pointer, 0, kMaxMirrorBounces, 4);
  level.lightViaMirrors = reader.readOptionalBool(rendering, "light_via_mirrors", pointer, true);
}

}  // namespace game::level_format
