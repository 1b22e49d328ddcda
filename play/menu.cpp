#include "play/menu.hpp"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "game/level_loader.hpp"
#include "game/user_paths.hpp"
#include "play/level_flow.hpp"
#include "play/level_list.hpp"
#include "render/presenter.hpp"
#include "render/renderer.hpp"

namespace play {
namespace fs = std::filesystem;

namespace {

void drawLevelList(Menu& menu, const fs::path& playedFile, const std::vector<fs::path>& levels) {
  const std::vector<LevelListEntry> entries =
      levelListEntries(menu.progress, levels, menu.levelNames, menu.levelChapters, playedFile);
  for (size_t i = 0; i < entries.size(); ++i) {
    if (!entries[i].chapter.empty()) {
      if (i > 0) ImGui::Spacing();
      ImGui::TextDisabled("%s", entries[i].chapter.c_str());
      ImGui::Separator();
    }
    ImGui::BeginDisabled(!entries[i].selectable);
    if (ImGui::Selectable(entries[i].label.c_str(), entries[i].current))
      menu.pendingLevel = levels[i];
    ImGui::EndDisabled();
  }
  if (!menu.confirmReset) {
    if (ImGui::Button("Reset progress...")) menu.confirmReset = true;
  } else {
    ImGui::TextUnformatted("Forget every win and lock all but the first level?");
    if (ImGui::Button("Yes, reset")) {
      menu.progress = {};
      try {
        game::saveProgress(menu.progress, game::progressFile());
        std::printf("progress reset\n");
      } catch (const std::exception& error) {
        std::fprintf(stderr, "progress not reset: %s\n", error.what());
      }
      menu.confirmReset = false;
    }
    ImGui::SameLine();
    if (ImGui::Button("Keep it")) menu.confirmReset = false;
  }
}

void drawSettings(Menu& menu, const PlayedLevel& played, game::Settings& settings,
                  KeyCodes& keyCodes, render::Presenter& presenter) {
  ImGui::SliderFloat("Mouse sensitivity", &settings.mouseSensitivity, 0.01f, 1.0f,
                     "%.2f degrees per pixel");
  ImGui::Checkbox("Invert mouse Y", &settings.invertY);
  bool levelFov = !settings.fieldOfViewDegrees;
  if (ImGui::Checkbox("Each level's own field of view", &levelFov))
    settings.fieldOfViewDegrees =
        levelFov ? std::nullopt : std::optional<float>(played.level->camera.verticalFovDegrees);
  if (settings.fieldOfViewDegrees)
    ImGui::SliderFloat("Field of view", &*settings.fieldOfViewDegrees, game::kMinFieldOfViewDegrees,
                       game::kMaxFieldOfViewDegrees, "%.0f degrees (vertical)");
  ImGui::SliderFloat("Render scale", &settings.renderScale, 0.1f, 1.0f, "%.2f");
  settings.renderScale = std::clamp(settings.renderScale, 0.1f, 1.0f);
  if (ImGui::Checkbox("Vsync (V)", &settings.vsync)) presenter.setVsync(settings.vsync);
  ImGui::Checkbox("Hold 30 fps (fewer pixels while frames run long)", &settings.dynamicRenderScale);
  if (settings.fieldOfViewDegrees != played.activeFov ||
      settings.renderScale != played.activeScale) {
    ImGui::TextUnformatted("Field of view and render scale apply when a level starts.");
    if (ImGui::Button("Apply now (restarts the level)")) menu.pendingLevel = played.file;
  }
  const render::Renderer& renderer = played.simulation->renderer();
  if (played.outputWidth > 0) {
    ImGui::Text("Picture: %ux%u of %ux%u, upscaled to %ux%u, scaled to the window",
                renderer.pictureWidth(), renderer.pictureHeight(), played.renderWidth,
                played.renderHeight, played.outputWidth, played.outputHeight);
  } else {
    ImGui::Text("Picture: %ux%u of %ux%u, scaled to the window", renderer.pictureWidth(),
                renderer.pictureHeight(), played.renderWidth, played.renderHeight);
  }

  ImGui::Separator();
  ImGui::TextUnformatted("Keys");
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_SizingFixedFit)) {
    for (const auto& [action, key] : settings.keyBindings) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(action.c_str());
      ImGui::TableNextColumn();
      const bool waiting = menu.rebinding && *menu.rebinding == action;
      const std::string label =
          (waiting ? std::string("press a key (Esc keeps it)") : key) + "##" + action;
      if (ImGui::Button(label.c_str())) menu.rebinding = action;
    }
    ImGui::EndTable();
  }
  if (ImGui::Button("Default keys")) {
    settings.keyBindings = game::Settings::defaultKeyBindings();
    keyCodes = keyCodesFor(settings);
  }
}

}  // namespace

std::vector<std::string> levelDisplayNames(const std::vector<fs::path>& levels,
                                           const game::LevelLoadOptions& loading) {
  std::vector<std::string> names;
  for (const fs::path& file : levels) {
    try {
      names.push_back(game::loadLevel(file, loading).name);
    } catch (const std::exception&) {
      names.push_back(file.stem().string());  // play says what is wrong with it when chosen
    }
  }
  return names;
}

void resetMenu(Menu& menu, bool opening) {
  menu.rebinding.reset();
  menu.confirmReset = false;
  if (!opening) return;
  const game::ProgressLoad loaded = game::loadProgress(game::progressFile());
  for (const std::string& message : loaded.messages) std::fprintf(stderr, "%s\n", message.c_str());
  menu.progress = loaded.progress;
}

void drawPauseMenu(Menu& menu, const PlayedLevel& played, const std::vector<fs::path>& levels,
                   game::Settings& settings, KeyCodes& keyCodes, render::Presenter& presenter) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x / 2, display.y / 2), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(display.x * 0.4f, 0.0f),
                                      ImVec2(display.x * 0.9f, display.y * 0.9f));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings;
  if (!ImGui::Begin("Paused", nullptr, flags)) {
    ImGui::End();
    return;
  }
  ImGui::Text("%s", played.level->name.c_str());
  if (ImGui::Button("Resume (Esc)")) menu.resumeRequested = true;
  ImGui::SameLine();
  if (ImGui::Button("Restart level")) menu.pendingLevel = played.file;
  ImGui::SameLine();
  if (ImGui::Button("Quit")) menu.quitRequested = true;

  if (ImGui::CollapsingHeader("Levels", ImGuiTreeNodeFlags_DefaultOpen))
    drawLevelList(menu, played.file, levels);
  if (ImGui::CollapsingHeader("Settings"))
    drawSettings(menu, played, settings, keyCodes, presenter);
  ImGui::End();
}

void drawEndScreen(Menu& menu, const std::vector<fs::path>& levels) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x / 2, display.y / 2), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings;
  if (!ImGui::Begin("The end", nullptr, flags)) {
    ImGui::End();
    return;
  }
  ImGui::TextUnformatted("Every line of sight found. Thank you for playing Sightline.");
  ImGui::Separator();
  uint64_t total = 0;
  bool everyTime = true;
  for (size_t i = 0; i < levels.size(); ++i) {
    const std::string file = levels[i].filename().string();
    const auto best = menu.progress.bestTicks.find(file);
    const std::string name = i < menu.levelNames.size() ? menu.levelNames[i] : file;
    if (best == menu.progress.bestTicks.end()) {
      everyTime = false;
      ImGui::Text("%zu. %s", i + 1, name.c_str());
      continue;
    }
    total += best->second;
    ImGui::Text("%zu. %s   %s", i + 1, name.c_str(), game::gameTimeText(best->second).c_str());
  }
  ImGui::Separator();
  if (everyTime) ImGui::Text("Best times together: %s", game::gameTimeText(total).c_str());
  if (ImGui::Button("Play again from the first level")) menu.pendingLevel = levels.front();
  ImGui::SameLine();
  if (ImGui::Button("Quit")) menu.quitRequested = true;
  ImGui::End();
}

void saveSettingsIfChanged(const game::Settings& settings, game::Settings& saved) {
  if (settings == saved) return;
  try {
    game::saveSettings(settings, game::settingsFile());
    saved = settings;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "settings not saved: %s\n", error.what());
  }
}

}  // namespace play
