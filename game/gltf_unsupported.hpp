#pragma once
// What a glTF model holds that Sightline does not draw: one warning per feature, naming the
// file and the feature, so nothing an author exported is dropped silently; an extension the
// model requires and Sightline cannot honour is an error.
#include <filesystem>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace game::gltf {

// Throws game::LevelError for a required extension; appends the warnings.
void checkUnsupportedFeatures(const tinygltf::Model& model, const std::filesystem::path& file,
                              std::vector<std::string>& warnings);

}  // namespace game::gltf
