#include "game/level_format/sections.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

// The "entities" section, with the movers and interactables an entity may be.
namespace game::level_format {

namespace {

// The materials made from a glTF mesh's own, one per mesh material, created on first use as
// "<mesh id>#gltf" (the first) and "<mesh id>#gltf:<n>" (the n-th after it).
std::vector<uint32_t> modelMaterials(LevelReader& reader, uint32_t mesh,
                                     const std::string& entityPointer, Level& level) {
  const std::string& meshId = level.meshIds[mesh];
  LevelReader::MeshMaterialSource& materialSource = reader.meshMaterialSources[mesh];
  if (materialSource.gltfMaterials.empty()) {
    reader.failMissing(
        entityPointer, "material",
        " (mesh \"" + meshId + "\" " +
            (materialSource.isGltf ? "is a glTF model without a material" : "is not a glTF model") +
            ", so the entity must name one)");
  }
  std::vector<uint32_t> result;
  for (std::size_t k = 0; k < materialSource.gltfMaterials.size(); ++k) {
    const std::string materialId = meshId + "#gltf" + (k ? ":" + std::to_string(k) : "");
    const auto existing = std::find(level.materialIds.begin(), level.materialIds.end(), materialId);
    if (existing != level.materialIds.end()) {
      result.push_back(static_cast<uint32_t>(existing - level.materialIds.begin()));
      continue;
    }
    if (level.materials.size() >= kMaxMaterials) {
      reader.failValue(entityPointer, "the glTF materials of mesh \"" + meshId +
                                          "\" make more than " + std::to_string(kMaxMaterials) +
                                          " materials, the limit");
    }
    GltfMaterial& source = materialSource.gltfMaterials[k];
    scene::MaterialDesc desc;
    desc.baseColor = source.baseColor;
    desc.metallicRoughness = true;
    desc.metallic = source.metallic;
    desc.alpha = source.alpha;
    desc.alphaCutoff = source.alphaCutoff;
    desc.roughness = source.roughness;
    desc.emissive = source.emissive;
    desc.normalScale = source.normalScale;
    desc.occlusionStrength = source.occlusionStrength;
    desc.textureMappings = source.textureMappings;
    if (source.alphaBlend) {
      // Drawn as glass whose tint is the colour mixed in by its alpha (per point in the shader;
      // these are the factors' own, for what reads the tint on the host).
      desc.kind = scene::MaterialKind::Glass;
      desc.alphaBlend = true;
      desc.glassTint = glm::mix(glm::vec3(1.0f), source.baseColor, source.alpha);
    }
    const std::string meshPointer = childPointer("/meshes", meshId);
    for (auto [texture, slot] :
         {std::pair{&source.colorTexture, &desc.colorTexture},
          std::pair{&source.normalTexture, &desc.normalTexture},
          std::pair{&source.metallicRoughnessTexture, &desc.metallicRoughnessTexture},
          std::pair{&source.occlusionTexture, &desc.occlusionTexture},
          std::pair{&source.emissiveTexture, &desc.emissiveTexture}}) {
      if (!*texture) continue;
      *slot = reader.addModelTexture(std::move(**texture), meshPointer, level);
      texture->reset();
    }
    level.materialIds.push_back(materialId);
    level.materials.push_back(desc);
    result.push_back(static_cast<uint32_t>(level.materials.size() - 1));
  }
  return result;
}

Mover readMover(const LevelReader& reader, const OrderedJson& mover, const std::string& pointer,
                const Entity& entity) {
  reader.checkKeys(mover, pointer,
                   {"duration_seconds", "repeat", "easing", "keyframes", "starts_playing"},
                   {"keyframes"});
  Mover result;
  result.durationSeconds =
      reader.readOptionalNumber(mover, "duration_seconds", pointer, kPositiveNumber, 1.0f);
  result.repeat = static_cast<Mover::Repeat>(
      reader.readOptionalChoice(mover, "repeat", pointer, {"once", "loop", "ping_pong"}, 1));
  result.easing = static_cast<Mover::Easing>(reader.readOptionalChoice(
      mover, "easing", pointer, {"linear", "smooth", "ease_in", "ease_out"}, 0));
  result.startsPlaying = reader.readOptionalBool(mover, "starts_playing", pointer, true);
  const OrderedJson& keyframes = mover["keyframes"];
  const std::string keyframesPointer = childPointer(pointer, "keyframes");
  if (!keyframes.is_array()) {
    reader.expected(keyframes, keyframesPointer, "an array of 2 to 256 keyframes");
  }
  if (keyframes.size() > kMaxKeyframes) {
    reader.failValue(keyframesPointer, std::to_string(keyframes.size()) +
                                           " keyframes, more than the limit of " +
                                           std::to_string(kMaxKeyframes));
  }
  if (keyframes.size() < kMinKeyframes) {
    reader.failValue(keyframesPointer,
                     "expected 2 to 256 keyframes, got " + std::to_string(keyframes.size()));
  }
  for (std::size_t i = 0; i < keyframes.size(); ++i) {
    const std::string keyframePointer = childPointer(keyframesPointer, i);
    const OrderedJson& keyframe = keyframes[i];
    reader.checkKeys(keyframe, keyframePointer, {"position", "rotation_degrees"}, {});
    // A keyframe leaves out what does not change from the entity's own pose.
    Keyframe pose{entity.position, entity.rotationDegrees};
    if (keyframe.contains("position")) {
      pose.position = reader.readVec3(keyframe["position"],
                                      childPointer(keyframePointer, "position"), kCoordinate);
    }
    if (keyframe.contains("rotation_degrees")) {
      pose.rotationDegrees =
          reader.readVec3(keyframe["rotation_degrees"],
                          childPointer(keyframePointer, "rotation_degrees"), kAnyNumber);
    }
    result.keyframes.push_back(pose);
  }
  return result;
}

// min <= start <= max, with start defaulting to 0 pulled into the range.
void readRange(const LevelReader& reader, const OrderedJson& object, const std::string& pointer,
               const char* minKey, const char* maxKey, const char* startKey, const NumberRule& rule,
               Interactable& result) {
  std::tie(result.min, result.max) = reader.readOrderedPair(object, pointer, minKey, maxKey, rule);
  result.start = std::clamp(0.0f, result.min, result.max);
  if (object.contains(startKey)) {
    const std::string startPointer = childPointer(pointer, startKey);
    result.start = reader.readNumber(object[startKey], startPointer, rule);
    if (result.start < result.min || result.start > result.max) {
      reader.failValue(startPointer, std::string("expected a number from ") + minKey + " to " +
                                         maxKey + ", [" + formatNumber(result.min) + ", " +
                                         formatNumber(result.max) + "], got " +
                                         describeValue(object[startKey]));
    }
  }
}

Interactable readInteractable(const LevelReader& reader, const OrderedJson& interactable,
                              const std::string& pointer) {
  static const std::vector<std::string> kTypes{"rotate", "slide", "switch"};
  const std::size_t type = reader.readType(interactable, pointer, kTypes);
  const std::string what = "a " + kTypes[type] + " interactable";
  Interactable result;
  result.type = static_cast<Interactable::Type>(type);
  if (result.type == Interactable::Type::Rotate) {
    reader.checkKeys(interactable, pointer,
                     {"type", "axis", "min_degrees", "max_degrees", "start_degrees"},
                     {"min_degrees", "max_degrees"}, what);
    if (interactable.contains("axis")) {
      result.axis = reader.readDirection(interactable["axis"], childPointer(pointer, "axis"));
    }
    readRange(reader, interactable, pointer, "min_degrees", "max_degrees", "start_degrees",
              kAnyNumber, result);
  } else if (result.type == Interactable::Type::Slide) {
    reader.checkKeys(interactable, pointer, {"type", "axis", "min", "max", "start"},
                     {"axis", "min", "max"}, what);
    result.axis = reader.readDirection(interactable["axis"], childPointer(pointer, "axis"));
    readRange(reader, interactable, pointer, "min", "max", "start", kCoordinate, result);
  } else {
    reader.checkKeys(interactable, pointer, {"type", "light", "starts_on"}, {"light"}, what);
    result.light =
        reader.readReference(interactable["light"], childPointer(pointer, "light"), IdKind::Light);
    result.startsOn = reader.readOptionalBool(interactable, "starts_on", pointer, true);
  }
  return result;
}

}  // namespace

Entity readEntity(LevelReader& reader, const std::string& id, const OrderedJson& entity,
                  const std::string& pointer, Level& level) {
  reader.checkKeys(entity, pointer,
                   {"mesh", "material", "position", "rotation_degrees", "scale", "casts_shadow",
                    "mover", "interactable"},
                   {"mesh"});
  Entity result;
  result.id = id;
  result.mesh = reader.readReference(entity["mesh"], childPointer(pointer, "mesh"), IdKind::Mesh);
  if (entity.contains("material")) {
    result.material = reader.readReference(entity["material"], childPointer(pointer, "material"),
                                           IdKind::Material);
  } else {
    result.meshMaterials = modelMaterials(reader, result.mesh, pointer, level);
    result.material = result.meshMaterials.front();
    if (result.meshMaterials.size() == 1) result.meshMaterials.clear();
  }
  if (entity.contains("position")) {
    result.position =
        reader.readVec3(entity["position"], childPointer(pointer, "position"), kCoordinate);
  }
  if (entity.contains("rotation_degrees")) {
    // [pitch about X, yaw about Y, roll about Z], stored in that order.
    result.rotationDegrees = reader.readVec3(entity["rotation_degrees"],
                                             childPointer(pointer, "rotation_degrees"), kAnyNumber);
  }
  if (entity.contains("scale")) {
    const OrderedJson& scale = entity["scale"];
    const std::string scalePointer = childPointer(pointer, "scale");
    if (scale.is_number()) {
      result.scale = glm::vec3(reader.readNumber(scale, scalePointer, kLength));
    } else if (scale.is_array() && scale.size() == 3) {
      result.scale = reader.readVec3(scale, scalePointer, kLength);
    } else {
      reader.expected(scale, scalePointer, "a number > 0 or an array of 3 numbers > 0");
    }
  }
  if (entity.contains("casts_shadow") && entity["casts_shadow"] == "directional") {
    result.shadowsDirectionalOnly = true;  // still a caster, for directional lights
  } else if (entity.contains("casts_shadow") && !entity["casts_shadow"].is_boolean()) {
    reader.expected(entity["casts_shadow"], childPointer(pointer, "casts_shadow"),
                    "true, false or \"directional\"");
  } else {
    result.castsShadow = reader.readOptionalBool(entity, "casts_shadow", pointer, true);
  }
  if (entity.contains("mover") && entity.contains("interactable")) {
    reader.failKey(pointer, "interactable",
                   "an entity is a mover or interactable, not both; remove \"mover\" or "
                   "\"interactable\"");
  }
  if (entity.contains("mover")) {
    result.mover = readMover(reader, entity["mover"], childPointer(pointer, "mover"), result);
  }
  if (entity.contains("interactable")) {
    result.interactable =
        readInteractable(reader, entity["interactable"], childPointer(pointer, "interactable"));
  }
  return result;
}

}  // namespace game::level_format
