// Fuzz target for the player's settings file (README.md, "Settings and progress"): any bytes in
// settings.json must load without an exception, each message one line naming the file; what
// loads, saved and loaded again, must come back equal with no message. Anything else (an
// exception, a crash, a sanitizer report, a hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <string>

#include "game/settings.hpp"
#include "user_file_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::filesystem::path file = fuzz::writeInput("settings.json", data, size);
  game::SettingsLoad load;
  try {
    load = game::loadSettings(file);
  } catch (const std::exception& error) {
    fuzz::die("loadSettings threw", error.what());
  }
  fuzz::checkMessages(load.messages, file);
  const std::filesystem::path again = file.parent_path() / "saved_settings.json";
  game::saveSettings(load.settings, again);
  const game::SettingsLoad reloaded = game::loadSettings(again);
  if (!reloaded.messages.empty())
    fuzz::die("saved settings load with a message", reloaded.messages[0]);
  if (!(reloaded.settings == load.settings)) fuzz::die("settings changed in a save and load", "");
  return 0;
}
