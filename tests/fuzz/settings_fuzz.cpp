// Fuzz target for the player's settings file (README.md, "Settings and progress"): any bytes in
// settings.json must load without an exception, each message one line naming the file; what
// loads, saved and loaded again, must come back equal with no message. Anything else (an
// exception, a crash, a sanitizer report, a hang) is a finding.
#include <cstddef>
#include <cstdint>

#include "game/settings.hpp"
#include "user_file_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::checkUserFile(
      "settings.json", data, size, [](const auto& path) { return game::loadSettings(path); },
      [](const game::SettingsLoad& load) { return load.settings; }, game::saveSettings);
  return 0;
}
