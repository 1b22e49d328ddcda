// Every level in tests/invalid_levels/ is refused with exactly the message recorded for it in
// tests/invalid_levels/expected_messages.txt (one line per file: "name.json:line:col: text",
// with paths relative to that folder).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "game/level_loader.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path kInvalidLevels = fs::path(SIGHTLINE_SOURCE_DIR) / "tests" / "invalid_levels";

std::map<std::string, std::string> expectedMessages() {
  std::map<std::string, std::string> messages;
  std::ifstream in(kInvalidLevels / "expected_messages.txt");
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t end = line.find(".json:");
    if (end == std::string::npos) continue;
    messages[line.substr(0, end + 5)] = line;
  }
  return messages;
}

std::string withoutFolder(std::string message, const std::string& folder) {
  for (std::size_t at = message.find(folder); at != std::string::npos; at = message.find(folder))
    message.erase(at, folder.size());
  return message;
}

TEST(InvalidLevels, each_is_refused_with_its_recorded_message) {
  const std::map<std::string, std::string> expected = expectedMessages();
  std::size_t checked = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(kInvalidLevels)) {
    if (entry.path().extension() != ".json") continue;
    const std::string name = entry.path().filename().string();
    const auto message = expected.find(name);
    ASSERT_NE(message, expected.end()) << name << " has no line in expected_messages.txt";
    try {
      game::loadLevel(entry.path());
      ADD_FAILURE() << name << " loaded; expected: " << message->second;
    } catch (const game::LevelError& error) {
      EXPECT_EQ(withoutFolder(error.what(), kInvalidLevels.string() + "/"), message->second);
    }
    ++checked;
  }
  EXPECT_EQ(checked, expected.size()) << "expected_messages.txt names files that do not exist";
  EXPECT_GE(checked, 30u);
}

}  // namespace
