#include "game/level_format/sections.hpp"

// The "environment" section: sky and ambient light.
namespace game::level_format {

scene::EnvironmentDesc readEnvironment(const LevelReader& reader, const OrderedJson& environment,
                                       const std::string& pointer) {
  reader.checkKeys(environment, pointer, {"sky_zenith", "sky_horizon", "sky_intensity", "ambient"},
                   {});
  scene::EnvironmentDesc desc;
  const float skyIntensity =
      reader.readOptionalNumber(environment, "sky_intensity", pointer, kIntensity, 1.0f);
  desc.skyZenith =
      reader.readOptionalColor(environment, "sky_zenith", pointer, glm::vec3(0.0f)) * skyIntensity;
  desc.skyHorizon =
      reader.readOptionalColor(environment, "sky_horizon", pointer, glm::vec3(0.0f)) * skyIntensity;
  desc.ambient = reader.readOptionalColor(environment, "ambient", pointer, glm::vec3(0.0f));
  return desc;
}

}  // namespace game::level_format
