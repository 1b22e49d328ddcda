#include "game/level_format/sections.hpp"

// The "lights" section.
namespace game::level_format {

scene::LightDesc readLight(const LevelReader& reader, const OrderedJson& light,
                           const std::string& pointer, std::optional<uint32_t>& carrier) {
  static const std::vector<std::string> kTypes{"point", "directional", "sphere", "rectangle",
                                               "disk"};
  const std::size_t type = reader.readType(light, pointer, kTypes);
  const std::string what = withArticle(kTypes[type]) + " light";
  scene::LightDesc desc;
  switch (type) {
    case 0:
      reader.checkKeys(light, pointer,
                       {"type", "position", "color", "intensity", "enabled", "rides"},
                       {"position", "intensity"}, what);
      desc.type = scene::LightType::Point;
      break;
    case 1:
      reader.checkKeys(light, pointer,
                       {"type", "direction", "angular_diameter_degrees", "color", "intensity",
                        "enabled", "rides"},
                       {"direction", "intensity"}, what);
      desc.type = scene::LightType::Directional;
      desc.angularDiameterRadians = glm::radians(reader.readOptionalNumber(
          light, "angular_diameter_degrees", pointer, NumberRule{0.0, true, 30.0, true}, 0.0f));
      break;
    case 2:
      reader.checkKeys(light, pointer,
                       {"type", "position", "radius", "color", "intensity", "enabled", "rides"},
                       {"position", "radius", "intensity"}, what);
      desc.type = scene::LightType::Sphere;
      desc.radius = reader.readNumber(light["radius"], childPointer(pointer, "radius"), kLength);
      break;
    case 3:
      reader.checkKeys(
          light, pointer,
          {"type", "position", "direction", "size", "color", "intensity", "enabled", "rides"},
          {"position", "direction", "size", "intensity"}, what);
      desc.type = scene::LightType::Rectangle;
      desc.size = reader.readVec2(light["size"], childPointer(pointer, "size"), kLength,
                                  "an array of 2 numbers [width, height]");
      break;
    default:
      reader.checkKeys(
          light, pointer,
          {"type", "position", "direction", "radius", "color", "intensity", "enabled", "rides"},
          {"position", "direction", "radius", "intensity"}, what);
      desc.type = scene::LightType::Disk;
      desc.radius = reader.readNumber(light["radius"], childPointer(pointer, "radius"), kLength);
      break;
  }
  if (light.contains("position")) {
    desc.position =
        reader.readVec3(light["position"], childPointer(pointer, "position"), kCoordinate);
  }
  if (light.contains("direction")) {
    desc.direction = reader.readDirection(light["direction"], childPointer(pointer, "direction"));
  }
  desc.color = reader.readOptionalColor(light, "color", pointer, glm::vec3(1.0f));
  desc.intensity =
      reader.readNumber(light["intensity"], childPointer(pointer, "intensity"), kIntensity);
  desc.enabled = reader.readOptionalBool(light, "enabled", pointer, true);
  carrier.reset();
  if (light.contains("rides"))
    carrier = reader.readReference(light["rides"], childPointer(pointer, "rides"), IdKind::Entity);
  return desc;
}

}  // namespace game::level_format
