#pragma once
// How the player's own JSON files (settings.json, progress.json) are read: forgivingly.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "game/json_positions.hpp"

namespace game {

// A JSON user file read so that no mistake in it costs the player more than the field it is in:
// every problem becomes a message "<file>:<line>:<column>: <field>: <problem>" and the caller
// keeps that field's default.
class UserJsonFile {
 public:
  // Parses `file`. std::nullopt means the caller should use its defaults for everything: with no
  // message when the file does not exist (the first run), with one message appended to
  // `messages` when it cannot be read, is not JSON, is not an object, or its version (the number
  // under `versionKey`) is not `version`. `whenIgnored` ends that message ("using the default
  // settings"). Never throws for anything in the file.
  static std::optional<UserJsonFile> open(const std::filesystem::path& file,
                                          const std::string& versionKey, int version,
                                          const std::string& whenIgnored,
                                          std::vector<std::string>& messages);

  const nlohmann::ordered_json& root() const { return root_; }

  // A message at the start of the value `pointer` (a JSON pointer) names.
  void reportValue(const std::string& pointer, const std::string& problem);
  // A message at the key of the member `pointer` names (for unknown keys).
  void reportKey(const std::string& pointer, const std::string& problem);
  // Reports every member of the object at `pointer` whose key is not in `known`.
  void reportUnknownKeys(const std::string& pointer, const std::vector<std::string>& known,
                         const std::string& what = "unknown key");

 private:
  UserJsonFile(std::filesystem::path file, nlohmann::ordered_json root, JsonPositions positions,
               std::vector<std::string>& messages)
      : file_(std::move(file)),
        root_(std::move(root)),
        positions_(std::move(positions)),
        messages_(&messages) {}
  void reportAt(SourcePosition at, const std::string& pointer, const std::string& problem);

  std::filesystem::path file_;
  nlohmann::ordered_json root_;
  JsonPositions positions_;
  std::vector<std::string>* messages_;
};

// What the player wrote, shortened for "got ..." in messages.
std::string describeJson(const nlohmann::ordered_json& value);

}  // namespace game
