// validate, info and devices: look at levels and devices without rendering.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "app/commands.hpp"
#include "app/data_paths.hpp"
#include "app/level_summary.hpp"
#include "app/session.hpp"
#include "game/level.hpp"
#include "game/level_loader.hpp"
#include "render/image_io.hpp"
#include "render/renderer.hpp"

namespace app {

int commandValidate(const Options& options) {
  if (options.positional.empty()) throw UsageError("validate: expected level files");
  int failures = 0;
  for (const std::string& file : options.positional) {
    // `sightline validate levels/*.json` also matches the editor schema, which is no level.
    if (file.ends_with(".schema.json")) {
      std::printf("%s: skipped (a JSON schema for editors, not a level)\n", file.c_str());
      continue;
    }
    try {
      const game::Level level = game::loadLevel(file, levelLoadOptions());
      std::printf("%s: ok (%s, %s, %s)\n", file.c_str(),
                  counted(level.entities.size(), "entity", "entities").c_str(),
                  counted(level.meshes.size(), "mesh", "meshes").c_str(),
                  counted(level.lights.size(), "light").c_str());
      for (const std::string& warning : level.warnings)
        std::fprintf(stderr, "warning: %s\n", warning.c_str());
    } catch (const game::LevelError& error) {
      std::fprintf(stderr, "%s\n", error.what());
      ++failures;
    }
  }
  return failures ? 1 : 0;
}

int commandVersion() {
  std::printf("sightline %s\n", SIGHTLINE_VERSION);
  try {
    render::Context context(render::ContextOptions{});
    const render::DeviceInfo& device = context.deviceInfo();
    std::printf("Vulkan device: %s [%s] %s\n", device.name.c_str(),
                render::deviceTypeName(device.type), device.driver.c_str());
  } catch (const std::exception& error) {
    std::printf("Vulkan device: none usable (%s)\n", error.what());
  }
  return 0;
}

int commandDevices() {
  const auto devices = render::Context::listDevices();
  if (devices.empty()) std::printf("no Vulkan devices found\n");
  for (const auto& device : devices) {
    std::printf("%u: %s [%s] %s — %s\n", device.index, device.name.c_str(),
                render::deviceTypeName(device.type), device.driver.c_str(),
                device.missingExtensions.empty()
                    ? "ray tracing: yes"
                    : render::describeMissingRayTracing(device).c_str());
  }
  return 0;
}

}  // namespace app

namespace app {

int commandInfo(const Options& options) {
  if (options.positional.size() != 1) throw UsageError("info: expected one level file");
  const game::Level level = game::loadLevel(options.positional[0], levelLoadOptions());
  const game::LevelFeatures features = game::levelFeatures(level);
  std::printf("%s (%s)\n", level.name.c_str(), level.file.c_str());
  if (!level.author.empty()) std::printf("  author: %s\n", level.author.c_str());
  std::printf("  triangles: %zu in %zu instances of %zu meshes\n", features.triangles,
              features.instances, level.meshes.size());
  std::printf("  %s, %s, %s\n", counted(features.lights, "light").c_str(),
              counted(level.materials.size(), "material").c_str(),
              counted(level.textures.size(), "texture").c_str());
  for (std::size_t mesh = 0; mesh < level.meshes.size(); ++mesh) {
    const std::vector<std::string>& names = level.meshMaterialNames[mesh];
    if (names.empty()) continue;
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "\"" : ", \"") + name + "\"";
    std::printf("  mesh \"%s\": glTF, %s: %s\n", level.meshIds[mesh].c_str(),
                counted(names.size(), "material").c_str(), list.c_str());
  }
  std::printf("  glass: %s\n", features.glass ? "yes" : "no");
  if (features.mirrors) {
    std::printf("  mirrors: yes, up to %u bounces\n", features.mirrorBounces);
    std::printf("  light via mirrors: %s\n",
                features.lightViaMirrors ? "yes (flat mirror faces send lights' light on)" : "no");
  } else {
    std::printf("  mirrors: no\n");
  }
  std::printf("  area lights (soft shadows): %s\n", features.areaLights ? "yes" : "no");
  std::printf("  textures: %s\n", features.textures ? "yes" : "no");
  std::printf("  movers: %s, interactables: %s\n", features.movers ? "yes" : "no",
              features.interactables ? "yes" : "no");
  const bool rulesCanEnd =
      std::any_of(level.rules.begin(), level.rules.end(), [](const auto& rule) {
        return std::any_of(rule.actions.begin(), rule.actions.end(),
                           [](const game::Action& action) {
                             return action.type == game::Action::Type::Win ||
                                    action.type == game::Action::Type::Lose;
                           });
      });
  std::printf("  goal: %s\n", level.goal    ? describeGoal(level, *level.goal).c_str()
                              : rulesCanEnd ? "none (its rules win or lose it)"
                                            : "none (sandbox)");
  for (const game::LoseCondition& lose : level.lose)
    std::printf("  lost by %s\n", describeLoss(level, lose).c_str());
  if (!level.rules.empty()) {
    std::printf("  logic: %zu rule%s:", level.rules.size(), level.rules.size() == 1 ? "" : "s");
    for (const game::Rule& rule : level.rules) std::printf(" %s", rule.id.c_str());
    std::printf("\n");
  }
  for (const std::string& warning : level.warnings) std::printf("  warning: %s\n", warning.c_str());
  return 0;
}

}  // namespace app
