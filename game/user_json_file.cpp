#include "game/user_json_file.hpp"

#include <algorithm>

#include "game/json_document.hpp"
#include "game/user_paths.hpp"

namespace game {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxUserFileBytes = 1u << 20;

}  // namespace

std::string describeJson(const nlohmann::ordered_json& value) {
  constexpr std::size_t kMaxShown = 40;
  std::string text = value.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  if (text.size() > kMaxShown) text = text.substr(0, kMaxShown - 3) + "...";
  return text;
}

std::optional<UserJsonFile> UserJsonFile::open(const fs::path& file, const std::string& versionKey,
                                               int version, const std::string& whenIgnored,
                                               std::vector<std::string>& messages) {
  std::optional<std::string> text;
  try {
    text = readUserFile(file, kMaxUserFileBytes);
  } catch (const UserFileError& error) {
    messages.push_back(error.what() + ("; " + whenIgnored));
    return std::nullopt;
  }
  if (!text) return std::nullopt;

  if (const std::optional<JsonShapeProblem> problem = jsonShapeProblem(*text)) {
    messages.push_back(placeInFile(file, positionOfOffset(*text, problem->offset)) +
                       problem->message + "; " + whenIgnored);
    return std::nullopt;
  }
  std::optional<nlohmann::ordered_json> parsed = parseOrderedJson(*text);
  if (!parsed) {
    const JsonSyntaxError error = firstJsonSyntaxError(*text);
    messages.push_back(placeInFile(file, positionOfOffset(*text, error.errorOffset)) +
                       "invalid JSON: " + error.reason + "; " + whenIgnored);
    return std::nullopt;
  }
  nlohmann::ordered_json root = std::move(*parsed);
  if (!root.is_object()) {
    messages.push_back(placeInFile(file, {}) + "expected an object, got " + describeJson(root) +
                       "; " + whenIgnored);
    return std::nullopt;
  }
  UserJsonFile opened(file, std::move(root), JsonPositions::scan(*text), messages);
  if (const auto& duplicate = opened.positions_.firstDuplicateKey()) {
    opened.reportAt(duplicate->position, duplicate->pointer, "duplicate key; the last one is used");
  }

  const std::string versionPointer = "/" + escapeJsonPointerToken(versionKey);
  const auto versionValue = opened.root_.find(versionKey);
  if (versionValue == opened.root_.end()) {
    // Older hand-written files may lack it; the fields still mean what version 1 says.
    opened.reportValue("", "missing \"" + versionKey + "\": " + std::to_string(version) +
                               "; reading the file as version " + std::to_string(version));
  } else if (!versionValue->is_number_integer() || versionValue->get<int64_t>() != version) {
    // A newer game wrote it (or it is damaged): its fields may mean something else.
    const SourcePosition at = opened.positions_.valueAt(versionPointer);
    messages.push_back(placeInFile(file, at, versionPointer) + "expected version " +
                       std::to_string(version) + ", got " + describeJson(*versionValue) + "; " +
                       whenIgnored);
    return std::nullopt;
  }
  return opened;
}

void UserJsonFile::reportAt(SourcePosition at, const std::string& pointer,
                            const std::string& problem) {
  messages_->push_back(placeInFile(file_, at, pointer) + problem);
}

void UserJsonFile::reportValue(const std::string& pointer, const std::string& problem) {
  reportAt(positions_.valueAt(pointer), pointer, problem);
}

void UserJsonFile::reportKey(const std::string& pointer, const std::string& problem) {
  reportAt(positions_.keyAt(pointer), pointer, problem);
}

void UserJsonFile::reportUnknownKeys(const std::string& pointer,
                                     const std::vector<std::string>& known,
                                     const std::string& what) {
  const nlohmann::ordered_json& object = root_.at(nlohmann::ordered_json::json_pointer(pointer));
  for (const auto& [key, value] : object.items()) {
    if (std::find(known.begin(), known.end(), key) == known.end())
      reportKey(pointer + "/" + escapeJsonPointerToken(key), what + "; ignored");
  }
}

}  // namespace game
