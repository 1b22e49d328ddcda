// Fuzz target for the player's progress file (README.md, "Settings and progress"): any bytes in
// progress.json must load without an exception, each message one line naming the file; what
// loads, saved and loaded again, must come back equal with no message. Anything else is a
// finding.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <string>

#include "game/progress.hpp"
#include "user_file_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::filesystem::path file = fuzz::writeInput("progress.json", data, size);
  game::ProgressLoad load;
  try {
    load = game::loadProgress(file);
  } catch (const std::exception& error) {
    fuzz::die("loadProgress threw", error.what());
  }
  fuzz::checkMessages(load.messages, file);
  const std::filesystem::path again = file.parent_path() / "saved_progress.json";
  game::saveProgress(load.progress, again);
  const game::ProgressLoad reloaded = game::loadProgress(again);
  if (!reloaded.messages.empty())
    fuzz::die("saved progress loads with a message", reloaded.messages[0]);
  if (!(reloaded.progress == load.progress)) fuzz::die("progress changed in a save and load", "");
  return 0;
}
