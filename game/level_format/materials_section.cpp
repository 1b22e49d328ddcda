#include "game/level_format/sections.hpp"

// The "materials" section.
namespace game::level_format {

scene::MaterialDesc readMaterial(LevelReader& reader, const OrderedJson& material,
                                 const std::string& pointer, Level& level) {
  reader.checkKeys(material, pointer,
                   {"color", "specular", "metallic", "roughness", "emissive", "emissive_strength",
                    "texture", "normal_map", "mirror", "glass"},
                   {});
  scene::MaterialDesc desc;
  desc.baseColor = reader.readOptionalColor(material, "color", pointer, glm::vec3(1.0f));
  desc.specular = reader.readOptionalNumber(material, "specular", pointer, kUnitInterval, 0.0f);
  desc.roughness = reader.readOptionalNumber(material, "roughness", pointer, kUnitFraction, 0.5f);
  if (material.contains("metallic")) {
    if (material.contains("specular")) {
      reader.failKey(pointer, "specular",
                     "a material is shaded by \"metallic\" (glTF's metallic-roughness model) or "
                     "by \"specular\" (Blinn-Phong), not both; remove one");
    }
    desc.metallicRoughness = true;
    desc.metallic = reader.readOptionalNumber(material, "metallic", pointer, kUnitInterval, 0.0f);
  }
  const glm::vec3 emissive =
      reader.readOptionalColor(material, "emissive", pointer, glm::vec3(0.0f));
  desc.emissive = emissive * reader.readOptionalNumber(material, "emissive_strength", pointer,
                                                       kIntensity, 1.0f);
  if (material.contains("mirror") && material.contains("glass")) {
    reader.failKey(pointer, "glass",
                   "a material is a mirror or glass, not both; remove \"mirror\" or \"glass\"");
  }
  if (material.contains("mirror")) {
    const std::string mirrorPointer = childPointer(pointer, "mirror");
    const OrderedJson& mirror = material["mirror"];
    reader.checkKeys(mirror, mirrorPointer, {"reflectance", "tint"}, {});
    const float reflectance =
        reader.readOptionalNumber(mirror, "reflectance", mirrorPointer, kUnitInterval, 1.0f);
    const glm::vec3 tint =
        mirror.contains("tint")
            ? reader.readTint(mirror["tint"], childPointer(mirrorPointer, "tint"))
            : glm::vec3(1.0f);
    desc.kind = scene::MaterialKind::Mirror;
    desc.mirrorTint = reflectance * tint;
  }
  if (material.contains("glass")) {
    const std::string glassPointer = childPointer(pointer, "glass");
    const OrderedJson& glass = material["glass"];
    reader.checkKeys(glass, glassPointer, {"tint"}, {"tint"});
    desc.kind = scene::MaterialKind::Glass;
    desc.glassTint = reader.readTint(glass["tint"], childPointer(glassPointer, "tint"));
  }
  if (material.contains("texture")) {
    desc.colorTexture =
        reader.readTexture(material["texture"], childPointer(pointer, "texture"), true, level);
  }
  if (material.contains("normal_map")) {
    desc.normalTexture = reader.readTexture(material["normal_map"],
                                            childPointer(pointer, "normal_map"), false, level);
  }
  return desc;
}

}  // namespace game::level_format
