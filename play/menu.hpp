#pragma once
// The pause menu (Esc): resume, restart, quit; the level list with a progress reset; the
// settings screen with the key bindings.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "game/level_loader.hpp"
#include "game/progress.hpp"
#include "game/settings.hpp"
#include "play/input.hpp"

namespace render {
class Presenter;
}

namespace play {

struct PlayedLevel;

struct Menu {
  std::vector<std::string> levelNames;     // of the shipped levels, for the list
  std::vector<std::string> levelChapters;  // parallel to levelNames
  game::Progress progress;                 // read when the menu opens
  std::optional<std::string> rebinding;    // the action waiting for its new key
  bool confirmReset = false;
  // What the player chose; the game does it before the next frame, when no frame is built.
  std::optional<std::filesystem::path> pendingLevel;
  bool resumeRequested = false;
  bool quitRequested = false;
};

// The names the level list shows: each level's own, else (it does not load) its file's stem.
std::vector<std::string> levelDisplayNames(const std::vector<std::filesystem::path>& levels,
                                           const game::LevelLoadOptions& loading);

// On pausing and on resuming: no key waits to be bound and no reset is asked; opening also
// reads the saved progress for the level list.
void resetMenu(Menu& menu, bool opening);

// Between UiLayer's beginFrame and endFrame. Changes the settings (the key codes follow the key
// bindings; vsync applies at once) and records the player's requests in `menu`.
void drawPauseMenu(Menu& menu, const PlayedLevel& played,
                   const std::vector<std::filesystem::path>& levels, game::Settings& settings,
                   KeyCodes& keyCodes, render::Presenter& presenter);

// Once the last level is won: the campaign's end, its best times, and what next (play again
// from the first level, or quit). Between UiLayer's beginFrame and endFrame.
void drawEndScreen(Menu& menu, const std::vector<std::filesystem::path>& levels);

// Writes settings.json when the settings changed since `saved`; a failed save is said, not fatal.
void saveSettingsIfChanged(const game::Settings& settings, game::Settings& saved);

}  // namespace play
