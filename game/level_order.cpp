#include "game/level_order.hpp"

#include <fstream>
#include <map>

namespace game {

namespace fs = std::filesystem;

namespace {

const std::string kChapterPrefix = "chapter:";

std::string trimmed(const std::string& text) {
  constexpr const char* kSpace = " \t\r\n\f\v";
  const std::size_t first = text.find_first_not_of(kSpace);
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(kSpace) - first + 1);
}

}  // namespace

std::vector<OrderedLevel> loadCampaign(const fs::path& levelsDirectory) {
  const fs::path file = levelsDirectory / "order.txt";
  std::ifstream stream;
  std::error_code error;
  if (fs::is_regular_file(file, error)) stream.open(file);
  if (!stream.is_open()) throw LevelError(file.string() + ": cannot open level order file");

  std::vector<OrderedLevel> order;
  std::map<std::string, int> lineOf;         // of each name, to point back at the first of two
  std::map<std::string, int> chapterLineOf;  // the same for chapters
  std::string chapter;
  int chapterLine = 0;
  size_t chapterStart = 0;  // the index of the chapter's first level
  auto failAt = [&](int lineNumber, const std::string& problem) {
    throw LevelError(file.string() + ":" + std::to_string(lineNumber) + ": " + problem);
  };
  auto closeChapter = [&] {
    if (chapterLine != 0 && order.size() == chapterStart)
      failAt(chapterLine, "chapter \"" + chapter + "\" lists no levels");
  };
  std::string line;
  for (int lineNumber = 1; std::getline(stream, line); ++lineNumber) {
    const std::string name = trimmed(line.substr(0, line.find('#')));
    if (name.empty()) continue;
    auto fail = [&](const std::string& problem) { failAt(lineNumber, problem); };
    if (name.starts_with(kChapterPrefix)) {
      closeChapter();
      chapter = trimmed(name.substr(kChapterPrefix.size()));
      if (chapter.empty()) fail("a chapter needs a name, as in \"chapter: Mirrors\"");
      if (const auto earlier = chapterLineOf.find(chapter); earlier != chapterLineOf.end())
        fail("chapter \"" + chapter + "\" is named twice (first on line " +
             std::to_string(earlier->second) + ")");
      chapterLineOf.emplace(chapter, lineNumber);
      chapterLine = lineNumber;
      chapterStart = order.size();
      continue;
    }
    // Names only: the order must not reach outside the levels directory.
    if (name.find('/') != std::string::npos || name == "." || name == "..")
      fail("\"" + name + "\" is a path; list level file names only");
    if (fs::path(name).extension() != ".json") fail("\"" + name + "\" is not a .json level file");
    if (!fs::is_regular_file(levelsDirectory / name, error))
      fail("\"" + name + "\" does not exist in " + levelsDirectory.string());
    if (const auto earlier = lineOf.find(name); earlier != lineOf.end())
      fail("\"" + name + "\" is listed twice (first on line " + std::to_string(earlier->second) +
           ")");
    lineOf.emplace(name, lineNumber);
    order.push_back({name, chapter});
  }
  closeChapter();
  if (stream.bad()) throw LevelError(file.string() + ": cannot read level order file");
  if (order.empty()) throw LevelError(file.string() + ": lists no levels");
  return order;
}

std::vector<std::string> loadLevelOrder(const fs::path& levelsDirectory) {
  std::vector<std::string> names;
  for (const OrderedLevel& level : loadCampaign(levelsDirectory)) names.push_back(level.file);
  return names;
}

}  // namespace game
