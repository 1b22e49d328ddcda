#include "game/gltf_unsupported.hpp"

#include <set>

#include "game/gltf_checks.hpp"

namespace game::gltf {

namespace {

std::string counted(std::size_t count, const std::string& what) {
  return std::to_string(count) + " " + what + (count == 1 ? "" : "s");
}

std::string joined(const std::set<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

void checkUnsupportedFeatures(const tinygltf::Model& model, const std::filesystem::path& file,
                              std::vector<std::string>& warnings) {
  const std::set<std::string> supported = {"KHR_materials_emissive_strength",
                                           "KHR_texture_transform"};
  for (const std::string& required : model.extensionsRequired) {
    if (!supported.count(required))
      fail(file, "requires the extension " + required +
                     ", which Sightline cannot honour (it supports " + joined(supported) + ")");
  }
  auto warn = [&](const std::string& text) { warnings.push_back(file.string() + ": " + text); };
  std::set<std::string> used;
  for (const std::string& extension : model.extensionsUsed)
    if (!supported.count(extension)) used.insert(extension);
  if (!used.empty()) {
    warn("uses " + std::string(used.size() == 1 ? "the extension " : "the extensions ") +
         joined(used) + ", which Sightline does not support: ignored");
  }
  if (!model.skins.empty())
    warn("has " + counted(model.skins.size(), "skin") +
         ": skinning is not supported; the meshes are drawn in their bind pose");
  if (!model.animations.empty())
    warn("has " + counted(model.animations.size(), "animation") +
         ": not supported; the model is drawn as it stands (give the entity a mover instead)");
  if (!model.cameras.empty())
    warn("has " + counted(model.cameras.size(), "camera") +
         ": ignored (the level's camera is used)");
  bool morphTargets = false;
  for (const tinygltf::Mesh& mesh : model.meshes) {
    for (const tinygltf::Primitive& primitive : mesh.primitives) {
      morphTargets = morphTargets || !primitive.targets.empty();
    }
  }
  if (morphTargets) warn("has morph targets: not supported; drawn without them");
  std::set<std::string> wrapModes;
  for (const tinygltf::Sampler& sampler : model.samplers) {
    for (const int wrap : {sampler.wrapS, sampler.wrapT}) {
      if (wrap == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) wrapModes.insert("CLAMP_TO_EDGE");
      if (wrap == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) wrapModes.insert("MIRRORED_REPEAT");
    }
  }
  if (!wrapModes.empty()) {
    warn("has texture samplers that wrap with " + joined(wrapModes) +
         ": not supported; every texture repeats (REPEAT)");
  }
}

}  // namespace game::gltf
