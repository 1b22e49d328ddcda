// Fuzz target for the player's progress file (README.md, "Settings and progress"): any bytes in
// progress.json must load without an exception, each message one line naming the file; what
// loads, saved and loaded again, must come back equal with no message. Anything else is a
// finding.
#include <cstddef>
#include <cstdint>

#include "game/progress.hpp"
#include "user_file_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::checkUserFile(
      "progress.json", data, size, [](const auto& path) { return game::loadProgress(path); },
      [](const game::ProgressLoad& load) { return load.progress; }, game::saveProgress);
  return 0;
}
