// Fuzz target for the level loader: any text must either load or be rejected with a
// game::LevelError whose message follows the documented one-line form. Anything else (another
// exception, a crash, a sanitizer report, a hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "game/level_loader.hpp"

namespace {

// Has no directory on disk, so model paths resolve to nothing and the run reads no files.
constexpr std::string_view kFuzzLevelPath = "<fuzz>/level.json";

[[noreturn]] void reportBadMessage(const char* problem, const std::string& message) {
  std::fprintf(stderr, "level_loader_fuzz: LevelError message %s: %s\n", problem, message.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    game::parseLevel(text, std::string(kFuzzLevelPath));
  } catch (const game::LevelError& error) {
    // Editors and `sightline validate` show the message as "<file>:...": it must name the file
    // and stay on one line.
    const std::string message = error.what();
    if (message.rfind(kFuzzLevelPath, 0) != 0) {
      reportBadMessage("does not start with the file", message);
    }
    if (message.find('\n') != std::string::npos) reportBadMessage("spans several lines", message);
  }
  return 0;
}
