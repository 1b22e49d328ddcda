#include "game/level_loader.hpp"
#include "game/json_error_sax.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <initializer_list>
#include <map>
#include <optional>
#include <utility>

#include <nlohmann/json.hpp>

#include "game/gltf_mesh.hpp"
#include "game/json_positions.hpp"
#include "game/primitives.hpp"
#include "game/texture_file.hpp"
#include "render/color.hpp"

namespace game {

namespace {

namespace fs = std::filesystem;
// Ordered so ids keep the order the author wrote them in.
using Json = nlohmann::ordered_json;

// ----- limits (docs/LEVELS.md, "Limits") -----

constexpr std::size_t kMaxLevelFileBytes = 16u << 20;
constexpr int kSupportedFormat = 1;
constexpr std::size_t kMaxEntities = 4096;
constexpr std::size_t kMaxMeshes = 1024;
constexpr std::size_t kMaxLights = 64;
constexpr std::size_t kMaxMaterials = 256;
constexpr std::size_t kMaxTextures = 64;
constexpr std::size_t kMaxTriangles = 2'000'000;
constexpr std::size_t kMinKeyframes = 2;
constexpr std::size_t kMaxKeyframes = 256;
constexpr std::size_t kMaxGoalChildren = 16;
// Not in the format's limits: keeps the recursive goal reader off deep stacks.
constexpr int kMaxGoalDepth = 8;
constexpr std::size_t kMaxNameCharacters = 80;
constexpr std::size_t kMaxStringCharacters = 2000;
constexpr double kMaxCoordinate = 100000.0;
constexpr double kMaxIntensity = 1e9;
// Bounds on tessellation so a typo cannot allocate gigabytes.
constexpr int64_t kMaxSegments = 4096;
constexpr int64_t kMaxRings = 2048;
constexpr int64_t kMaxMirrorBounces = 31;

// ----- text helpers -----

// Integers exactly, everything else in the shortest form that reads back the same.
std::string formatNumber(double value) {
  if (std::abs(value) < 1e15 && value == std::floor(value)) {
    return std::to_string(static_cast<int64_t>(value));
  }
  char buffer[32];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  return buffer;
}

// A short rendering of what the author wrote, for "got ..." in messages. Never recurses into
// nested containers, which may be arbitrarily deep.
std::string describe(const Json& value) {
  auto dump = [](const Json& json) {
    return json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  };
  constexpr std::size_t kMaxShown = 40;
  if (value.is_object()) return value.empty() ? "{}" : "an object";
  if (value.is_array()) {
    const bool flat = std::none_of(value.begin(), value.end(),
                                   [](const Json& item) { return item.is_structured(); });
    if (flat && value.size() <= 8) {
      const std::string text = dump(value);
      if (text.size() <= kMaxShown) return text;
    }
    return "an array of " + std::to_string(value.size()) + " elements";
  }
  if (value.is_string()) {
    const auto& text = value.get_ref<const std::string&>();
    if (text.size() > kMaxShown) return dump(Json(text.substr(0, kMaxShown))) + "...";
  }
  if (value.is_number_float()) return formatNumber(value.get<double>());
  return dump(value);
}

std::string joinQuoted(const std::vector<std::string>& items) {
  constexpr std::size_t kMaxListed = 20;
  if (items.empty()) return "(none)";
  std::string joined;
  for (std::size_t i = 0; i < items.size() && i < kMaxListed; ++i) {
    if (i > 0) joined += ", ";
    joined += "\"" + items[i] + "\"";
  }
  if (items.size() > kMaxListed) joined += ", ... (" + std::to_string(items.size()) + " in all)";
  return joined;
}

bool isValidId(const std::string& id) {
  return !id.empty() && std::all_of(id.begin(), id.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  });
}

bool isHexDigit(char c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

std::string toLower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// Characters as a reader counts them: UTF-8 code points (nlohmann has checked the encoding).
std::size_t characterCount(const std::string& text) {
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }));
}

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

// Case, '_' and '-' differences are the commonest slips ("Position", "castsShadow").
std::string foldedName(const std::string& name) {
  std::string folded;
  for (const char c : name) {
    if (c != '_' && c != '-')
      folded.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  }
  return folded;
}

// The candidate `word` was most likely meant to be, if any is close: the same name up to case
// and '_'/'-', or at most two edits away (and fewer edits than the word has letters).
std::optional<std::string> nearMiss(const std::string& word,
                                    const std::vector<std::string>& candidates) {
  constexpr std::size_t kMaxEdits = 2;
  std::optional<std::string> best;
  std::size_t bestDistance = kMaxEdits + 1;
  for (const std::string& candidate : candidates) {
    const std::size_t distance =
        foldedName(candidate) == foldedName(word) ? 0 : editDistance(word, candidate);
    if (distance < bestDistance && distance < word.size()) {
      best = candidate;
      bestDistance = distance;
    }
  }
  return best;
}

std::string didYouMean(const std::optional<std::string>& suggestion) {
  return suggestion ? "; did you mean \"" + *suggestion + "\"?" : "";
}

// Which end of a range a number may not cross, whether touching it is allowed, and (for the
// format's limits) what to say when a number goes past the limit.
struct NumberRule {
  double min = -FLT_MAX;
  bool minInclusive = true;
  double max = FLT_MAX;
  bool maxInclusive = true;
  const char* limit = nullptr;  // the format's limit this rule enforces, if any

  bool accepts(double value) const {
    return (minInclusive ? value >= min : value > min) &&
           (maxInclusive ? value <= max : value < max);
  }

  // Past the cap rather than the natural bound (a length of 200000 m, not one of -1 m).
  bool beyondLimit(double value) const { return value > max || (min == -max && value < min); }

  std::string describe() const {
    const bool bounded = max < FLT_MAX;
    if (min <= -FLT_MAX && !bounded) return "a number";
    if (!bounded)
      return std::string("a number ") + (minInclusive ? ">= " : "> ") + formatNumber(min);
    if (min <= -FLT_MAX) {
      return std::string("a number ") + (maxInclusive ? "<= " : "< ") + formatNumber(max);
    }
    return std::string("a number in ") + (minInclusive ? "[" : "(") + formatNumber(min) + ", " +
           formatNumber(max) + (maxInclusive ? "]" : ")");
  }
};

const char* const kFloatLimit = "numbers are stored as 32-bit floats, within ±3.4e38";
const char* const kCoordinateLimit = "positions and sizes are limited to ±100000 m";
const char* const kIntensityLimit = "intensities are limited to 1e9";

const NumberRule kAnyNumber{};
const NumberRule kPositiveNumber{0.0, false};
const NumberRule kNonNegativeNumber{0.0, true};
const NumberRule kUnitInterval{0.0, true, 1.0, true};
const NumberRule kUnitFraction{0.0, false, 1.0, true};
const NumberRule kCoordinate{-kMaxCoordinate, true, kMaxCoordinate, true, kCoordinateLimit};
const NumberRule kLength{0.0, false, kMaxCoordinate, true, kCoordinateLimit};
const NumberRule kIntensity{0.0, true, kMaxIntensity, true, kIntensityLimit};

// The kinds of id a level declares; references name one of them.
enum class IdKind { Material, Mesh, Entity, Light };
constexpr std::array<IdKind, 4> kIdKinds{IdKind::Material, IdKind::Mesh, IdKind::Entity,
                                         IdKind::Light};

const char* nounOf(IdKind kind) {
  switch (kind) {
    case IdKind::Material:
      return "material";
    case IdKind::Mesh:
      return "mesh";
    case IdKind::Entity:
      return "entity";
    case IdKind::Light:
      return "light";
  }
  return "";
}

const char* pluralOf(IdKind kind) {
  switch (kind) {
    case IdKind::Material:
      return "materials";
    case IdKind::Mesh:
      return "meshes";
    case IdKind::Entity:
      return "entities";
    case IdKind::Light:
      return "lights";
  }
  return "";
}

std::string withArticle(const std::string& noun) {
  return (noun.front() == 'e' ? "an " : "a ") + noun;
}

// A file a level names, found and checked against the path rules.
struct ResolvedFile {
  fs::path path;         // as opened and shown in messages (lexically normal)
  fs::path allowedRoot;  // the directory it lies in (the level's or the asset root), canonical
};

class LevelParser {
 public:
  LevelParser(const std::string& text, const fs::path& file, const LevelLoadOptions& options)
      : text_(text),
        file_(file),
        options_(options),
        levelDirectory_(file.parent_path().empty() ? fs::path(".") : file.parent_path()) {}

  Level parse() {
    if (text_.size() > kMaxLevelFileBytes) {
      throw LevelError(file_.string() + ": level file is larger than the 16 MiB limit");
    }
    Json root;
    try {
      root = Json::parse(text_);
    } catch (const Json::exception&) {
      failInvalidJson();
    }
    positions_ = JsonPositions::scan(text_);
    if (const auto& duplicate = positions_.firstDuplicateKey()) failDuplicateKey(*duplicate);

    Level level;
    level.file = file_;
    level.sourceFiles.push_back(file_);
    if (!root.is_object()) expected(root, "", "an object");
    // The format decides what every other key means, so it is checked before them.
    if (!root.contains("format")) failMissing("", "format");
    level.format = readFormat(root["format"]);
    checkKeys(root, "",
              {"format", "name", "description", "author", "hint", "camera", "environment",
               "rendering", "materials", "meshes", "entities", "lights", "goal", "lose"},
              {"name", "camera", "materials", "meshes", "entities"});
    level.name = readName(root["name"], "/name");
    level.description = readOptionalString(root, "description", "");
    level.author = readOptionalString(root, "author", "");
    level.hint = readOptionalString(root, "hint", "");
    level.camera = readCamera(root["camera"], "/camera");
    if (root.contains("environment")) {
      level.environment = readEnvironment(root["environment"], "/environment");
    }
    if (root.contains("rendering")) {
      level.maxMirrorBounces = readRendering(root["rendering"], "/rendering");
    }

    // Every id is known before any reference is read, so a reference can say what an id of the
    // wrong kind is.
    const std::map<IdKind, const char*> sectionKeys{{IdKind::Material, "materials"},
                                                    {IdKind::Mesh, "meshes"},
                                                    {IdKind::Entity, "entities"},
                                                    {IdKind::Light, "lights"}};
    for (const auto& [kind, key] : sectionKeys) {
      if (!root.contains(key)) continue;
      const Json& section = root[key];
      checkSection(section, std::string("/") + key, kind);
      for (const auto& item : section.items()) ids_[kind].push_back(item.key());
    }

    forEachEntry(root["materials"], "/materials",
                 [&](const std::string& id, const Json& value, const std::string& pointer) {
                   level.materialIds.push_back(id);
                   level.materials.push_back(readMaterial(value, pointer, level));
                 });
    forEachEntry(root["meshes"], "/meshes",
                 [&](const std::string& id, const Json& value, const std::string& pointer) {
                   level.meshIds.push_back(id);
                   level.meshes.push_back(readMesh(value, pointer, level));
                   level.meshes.back().name = id;
                 });
    if (root.contains("lights")) {
      forEachEntry(root["lights"], "/lights",
                   [&](const std::string& id, const Json& value, const std::string& pointer) {
                     level.lightIds.push_back(id);
                     level.lights.push_back(readLight(value, pointer));
                   });
    }
    forEachEntry(root["entities"], "/entities",
                 [&](const std::string& id, const Json& value, const std::string& pointer) {
                   level.entities.push_back(readEntity(id, value, pointer, level));
                 });
    if (root.contains("goal")) level.goal = readGoal(root["goal"], "/goal", 1);
    if (root.contains("lose")) level.lose = readLoseConditions(root["lose"], "/lose");
    return level;
  }

 private:
  // ----- messages -----

  // Collects the first error of a SAX parse. Json::parse throws parse_error for syntax errors,
  // which carries a position, but out_of_range (a number too large) without one; the SAX
  // interface reports both with a position.
  struct FirstJsonError : JsonErrorOnlySax<Json> {
    std::size_t bytesRead = 0;
    std::string lastToken;
    std::string what;
    bool isSyntaxError = true;

    bool parse_error(std::size_t position, const std::string& token,
                     const nlohmann::detail::exception& error) override {
      bytesRead = position;
      lastToken = token;
      what = error.what();
      isSyntaxError = dynamic_cast<const nlohmann::detail::parse_error*>(&error) != nullptr;
      return false;
    }
  };

  [[noreturn]] void failInvalidJson() {
    FirstJsonError error;
    Json::sax_parse(text_, &error);
    if (!error.isSyntaxError) {
      // A number too large for a double (1e999): the text is valid JSON up to there, so the
      // value can be named by its path. The error comes after the token was read.
      const std::size_t tokenStart =
          error.bytesRead >= error.lastToken.size() ? error.bytesRead - error.lastToken.size() : 0;
      const SourcePosition at = positionOfOffset(text_, tokenStart);
      positions_ = JsonPositions::scan(text_);
      const std::string pointer = positions_.pointerOfValueAt(at).value_or("");
      failAt(
          at, pointer,
          "expected a finite number, got " + error.lastToken + ", which is too large to represent");
    }
    // what() reads "[json.exception.parse_error.101] parse error at line 1, column 7: <reason>".
    std::string reason = error.what;
    if (const std::size_t prefixEnd = reason.find("] "); prefixEnd != std::string::npos) {
      reason.erase(0, prefixEnd + 2);
    }
    if (reason.rfind("parse error", 0) == 0) {
      if (const std::size_t colon = reason.find(": "); colon != std::string::npos) {
        reason.erase(0, colon + 2);
      }
    }
    const SourcePosition at = positionOfParseError(text_, error.bytesRead);
    throw LevelError(file_.string() + ":" + std::to_string(at.line) + ":" +
                     std::to_string(at.column) + ": invalid JSON: " + reason);
  }

  [[noreturn]] void failAt(SourcePosition at, const std::string& pointer,
                           const std::string& message) const {
    const std::string path = positions_.dottedPath(pointer);
    // One line whatever the file holds: keys, ids and paths are quoted in messages.
    throw LevelError(escapeControlCharacters(file_.string() + ":" + std::to_string(at.line) + ":" +
                                             std::to_string(at.column) + ": " +
                                             (path.empty() ? "" : path + ": ") + message));
  }

  [[noreturn]] void failValue(const std::string& pointer, const std::string& message) const {
    failAt(positions_.valueAt(pointer), pointer, message);
  }

  // At the key of `pointer`'s member `key`, naming the object that holds it.
  [[noreturn]] void failKey(const std::string& pointer, const std::string& key,
                            const std::string& message) const {
    failAt(positions_.keyAt(child(pointer, key)), pointer, message);
  }

  [[noreturn]] void expected(const Json& value, const std::string& pointer,
                             const std::string& what) const {
    failValue(pointer, "expected " + what + ", got " + describe(value));
  }

  [[noreturn]] void failMissing(const std::string& objectPointer, const std::string& key,
                                const std::string& why = "") const {
    failValue(objectPointer, "missing required key \"" + key + "\"" + why);
  }

  [[noreturn]] void failDuplicateKey(const JsonPositions::DuplicateKey& duplicate) const {
    const std::size_t slash = duplicate.pointer.rfind('/');
    const std::string objectPointer = duplicate.pointer.substr(0, slash);
    const std::string key = duplicate.pointer.substr(slash + 1);
    std::string what = "duplicate key";
    for (const IdKind kind : kIdKinds) {
      if (objectPointer == std::string("/") + pluralOf(kind)) {
        what = std::string("duplicate ") + nounOf(kind) + " id";
      }
    }
    failAt(duplicate.position, objectPointer, what + " \"" + unescapeJsonPointerToken(key) + "\"");
  }

  // ----- structure -----

  static std::string child(const std::string& pointer, const std::string& key) {
    return pointer + "/" + escapeJsonPointerToken(key);
  }

  static std::string child(const std::string& pointer, std::size_t index) {
    return pointer + "/" + std::to_string(index);
  }

  void requireObject(const Json& value, const std::string& pointer) const {
    if (!value.is_object()) expected(value, pointer, "an object");
  }

  // Unknown keys are reported first (they are often misspelt required ones), then missing ones.
  // `what` names the kind of object when the allowed keys depend on its type.
  void checkKeys(const Json& object, const std::string& pointer,
                 std::initializer_list<const char*> allowed,
                 std::initializer_list<const char*> required, const std::string& what = "") const {
    requireObject(object, pointer);
    const std::vector<std::string> allowedKeys(allowed.begin(), allowed.end());
    for (const auto& item : object.items()) {
      const std::string& key = item.key();
      if (std::find(allowedKeys.begin(), allowedKeys.end(), key) != allowedKeys.end()) continue;
      const std::string unknown =
          "unknown key \"" + key + "\"" + (what.empty() ? "" : " for " + what);
      if (const auto suggestion = nearMiss(key, allowedKeys)) {
        failKey(pointer, key, unknown + didYouMean(suggestion));
      }
      failKey(pointer, key, unknown + "; allowed keys: " + joinQuoted(allowedKeys));
    }
    for (const char* name : required) {
      if (!object.contains(name)) failMissing(pointer, name);
    }
  }

  // The ids of one section: an object of valid ids, at most the limit, at least one where the
  // level needs one.
  void checkSection(const Json& section, const std::string& pointer, IdKind kind) const {
    const std::string noun = nounOf(kind);
    const std::string plural = pluralOf(kind);
    if (!section.is_object()) expected(section, pointer, "an object mapping ids to " + plural);
    const std::map<IdKind, std::size_t> limits{{IdKind::Material, kMaxMaterials},
                                               {IdKind::Mesh, kMaxMeshes},
                                               {IdKind::Entity, kMaxEntities},
                                               {IdKind::Light, kMaxLights}};
    const std::size_t limit = limits.at(kind);
    if (section.size() > limit) {
      failValue(pointer, std::to_string(section.size()) + " " + plural +
                             ", more than the limit of " + std::to_string(limit));
    }
    if (section.empty() && kind != IdKind::Light) {
      failValue(pointer, "a level needs at least one " + noun + ", got {}");
    }
    for (const auto& item : section.items()) {
      if (!isValidId(item.key()) || characterCount(item.key()) > kMaxStringCharacters) {
        failKey(pointer, item.key(),
                "invalid " + noun + " id \"" + item.key() +
                    "\": ids are non-empty and use only letters, digits, '_' and '-'");
      }
    }
  }

  template <typename ReadEntry>
  void forEachEntry(const Json& section, const std::string& pointer, ReadEntry readEntry) const {
    for (const auto& item : section.items()) {
      readEntry(item.key(), item.value(), child(pointer, item.key()));
    }
  }

  // ----- scalars -----

  int readFormat(const Json& value) const {
    if (!value.is_number_integer()) expected(value, "/format", "the integer 1");
    if (value.is_number_unsigned() ? value.get<uint64_t>() != kSupportedFormat
                                   : value.get<int64_t>() != kSupportedFormat) {
      failValue("/format", "unsupported format " + describe(value) +
                               "; this version reads format " + std::to_string(kSupportedFormat));
    }
    return kSupportedFormat;
  }

  const std::string& readString(const Json& value, const std::string& pointer,
                                std::size_t minCharacters, std::size_t maxCharacters) const {
    const std::string what = "a string of " + std::to_string(minCharacters) + " to " +
                             std::to_string(maxCharacters) + " characters";
    if (!value.is_string()) expected(value, pointer, what);
    const auto& text = value.get_ref<const std::string&>();
    const std::size_t characters = characterCount(text);
    if (characters < minCharacters) expected(value, pointer, what);
    if (characters > maxCharacters) {
      failValue(pointer,
                "expected " + what + ", got " + std::to_string(characters) + " characters");
    }
    return text;
  }

  std::string readName(const Json& value, const std::string& pointer) const {
    return readString(value, pointer, 1, kMaxNameCharacters);
  }

  std::string readOptionalString(const Json& object, const char* key,
                                 const std::string& pointer) const {
    return object.contains(key)
               ? readString(object[key], child(pointer, key), 0, kMaxStringCharacters)
               : std::string();
  }

  float readNumber(const Json& value, const std::string& pointer, const NumberRule& rule) const {
    if (!value.is_number()) expected(value, pointer, rule.describe());
    const double number = value.get<double>();
    if (!rule.accepts(number)) {
      const char* limit = rule.limit != nullptr && rule.beyondLimit(number) ? rule.limit
                          : std::abs(number) > FLT_MAX                      ? kFloatLimit
                                                                            : nullptr;
      failValue(pointer, "expected " + rule.describe() + ", got " + describe(value) +
                             (limit != nullptr ? std::string("; ") + limit : ""));
    }
    return static_cast<float>(number);
  }

  float readOptionalNumber(const Json& object, const char* key, const std::string& pointer,
                           const NumberRule& rule, float fallback) const {
    return object.contains(key) ? readNumber(object[key], child(pointer, key), rule) : fallback;
  }

  uint32_t readCount(const Json& value, const std::string& pointer, int64_t min,
                     int64_t max) const {
    if (!value.is_number_integer() ||
        (value.is_number_unsigned() && value.get<uint64_t>() > static_cast<uint64_t>(max)) ||
        value.get<int64_t>() < min || value.get<int64_t>() > max) {
      expected(value, pointer,
               "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
    }
    return static_cast<uint32_t>(value.get<int64_t>());
  }

  uint32_t readOptionalCount(const Json& object, const char* key, const std::string& pointer,
                             int64_t min, int64_t max, uint32_t fallback) const {
    return object.contains(key) ? readCount(object[key], child(pointer, key), min, max) : fallback;
  }

  bool readOptionalBool(const Json& object, const char* key, const std::string& pointer,
                        bool fallback) const {
    if (!object.contains(key)) return fallback;
    const Json& value = object[key];
    if (!value.is_boolean()) expected(value, child(pointer, key), "true or false");
    return value.get<bool>();
  }

  // Which of `names` the string at `pointer` is.
  std::size_t readChoice(const Json& value, const std::string& pointer,
                         const std::vector<std::string>& names) const {
    if (value.is_string()) {
      const auto& text = value.get_ref<const std::string&>();
      const auto found = std::find(names.begin(), names.end(), text);
      if (found != names.end()) return static_cast<std::size_t>(found - names.begin());
      failValue(pointer, "expected one of " + joinQuoted(names) + ", got " + describe(value) +
                             didYouMean(nearMiss(text, names)));
    }
    expected(value, pointer, "one of " + joinQuoted(names));
  }

  std::size_t readOptionalChoice(const Json& object, const char* key, const std::string& pointer,
                                 const std::vector<std::string>& names,
                                 std::size_t fallback) const {
    return object.contains(key) ? readChoice(object[key], child(pointer, key), names) : fallback;
  }

  // The "type" of an object whose other keys depend on it.
  std::size_t readType(const Json& object, const std::string& pointer,
                       const std::vector<std::string>& types) const {
    requireObject(object, pointer);
    if (!object.contains("type")) failMissing(pointer, "type");
    return readChoice(object["type"], child(pointer, "type"), types);
  }

  template <std::size_t N>
  std::array<float, N> readNumbers(const Json& value, const std::string& pointer,
                                   const NumberRule& rule, const std::string& what) const {
    if (!value.is_array() || value.size() != N) expected(value, pointer, what);
    std::array<float, N> numbers{};
    for (std::size_t i = 0; i < N; ++i) numbers[i] = readNumber(value[i], child(pointer, i), rule);
    return numbers;
  }

  glm::vec3 readVec3(const Json& value, const std::string& pointer, const NumberRule& rule) const {
    const auto numbers = readNumbers<3>(value, pointer, rule, "an array of 3 numbers [x, y, z]");
    return {numbers[0], numbers[1], numbers[2]};
  }

  glm::vec2 readVec2(const Json& value, const std::string& pointer, const NumberRule& rule,
                     const std::string& what) const {
    const auto numbers = readNumbers<2>(value, pointer, rule, what);
    return {numbers[0], numbers[1]};
  }

  // Linear multipliers, not colours: no sRGB conversion.
  glm::vec3 readTint(const Json& value, const std::string& pointer) const {
    const auto numbers = readNumbers<3>(value, pointer, kUnitInterval, "3 numbers in [0, 1]");
    return {numbers[0], numbers[1], numbers[2]};
  }

  glm::vec3 readDirection(const Json& value, const std::string& pointer) const {
    const glm::dvec3 direction(readVec3(value, pointer, kCoordinate));
    const double length = glm::length(direction);
    if (!(length > 0.0)) expected(value, pointer, "a non-zero direction [x, y, z]");
    return glm::vec3(direction / length);
  }

  // Authored in sRGB, returned linear.
  glm::vec3 readColor(const Json& value, const std::string& pointer) const {
    static const std::string kWhat =
        "a colour: [r, g, b] with components in [0, 1] or a string \"#rrggbb\"";
    if (value.is_array() && value.size() == 3) {
      glm::vec3 encoded;
      for (std::size_t i = 0; i < 3; ++i) {
        encoded[static_cast<glm::length_t>(i)] =
            readNumber(value[i], child(pointer, i), kUnitInterval);
      }
      return render::srgbToLinear(encoded);
    }
    if (value.is_string()) {
      const auto& text = value.get_ref<const std::string&>();
      if (text.size() == 7 && text[0] == '#' &&
          std::all_of(text.begin() + 1, text.end(), isHexDigit)) {
        glm::vec3 encoded;
        for (int i = 0; i < 3; ++i) {
          encoded[i] = static_cast<float>(std::stoi(
                           text.substr(1 + 2 * static_cast<std::size_t>(i), 2), nullptr, 16)) /
                       255.0f;
        }
        return render::srgbToLinear(encoded);
      }
    }
    expected(value, pointer, kWhat);
  }

  glm::vec3 readOptionalColor(const Json& object, const char* key, const std::string& pointer,
                              const glm::vec3& fallback) const {
    return object.contains(key) ? readColor(object[key], child(pointer, key)) : fallback;
  }

  // The index of the `kind` id named at `pointer`; otherwise says what the name is instead.
  uint32_t readReference(const Json& value, const std::string& pointer, IdKind kind) const {
    const std::string noun = nounOf(kind);
    if (!value.is_string()) expected(value, pointer, withArticle(noun) + " id (a string)");
    const auto& id = value.get_ref<const std::string&>();
    const std::vector<std::string>& known = idsOf(kind);
    const auto found = std::find(known.begin(), known.end(), id);
    if (found != known.end()) return static_cast<uint32_t>(found - known.begin());

    std::vector<std::string> otherKinds;
    for (const IdKind other : kIdKinds) {
      const std::vector<std::string>& ids = idsOf(other);
      if (other != kind && std::find(ids.begin(), ids.end(), id) != ids.end()) {
        otherKinds.push_back(withArticle(nounOf(other)));
      }
    }
    if (!otherKinds.empty()) {
      std::string kinds;
      for (std::size_t i = 0; i < otherKinds.size(); ++i) {
        kinds += (i == 0 ? "" : i + 1 == otherKinds.size() ? " and " : ", ") + otherKinds[i];
      }
      failValue(pointer, "\"" + id + "\" is " + kinds + ", expected " + withArticle(noun) + " id");
    }
    const std::string unknown = "unknown " + noun + " \"" + id + "\"";
    if (const auto suggestion = nearMiss(id, known)) {
      failValue(pointer, unknown + didYouMean(suggestion));
    }
    if (known.empty()) failValue(pointer, unknown + "; the level has no " + pluralOf(kind));
    failValue(pointer, unknown + "; known " + pluralOf(kind) + ": " + joinQuoted(known));
  }

  const std::vector<std::string>& idsOf(IdKind kind) const {
    static const std::vector<std::string> kNone;
    const auto found = ids_.find(kind);
    return found == ids_.end() ? kNone : found->second;
  }

  // ----- files -----

  // The asset root: the first existing directory of options_.assetRoots, or by default the
  // "assets" directory beside the level's directory (levels/x.json -> assets/).
  std::optional<fs::path> assetRoot() const {
    std::vector<fs::path> candidates = options_.assetRoots;
    if (candidates.empty()) candidates.push_back(levelDirectory_ / ".." / "assets");
    for (const fs::path& candidate : candidates) {
      std::error_code error;
      if (fs::is_directory(candidate, error)) return candidate.lexically_normal();
    }
    return std::nullopt;
  }

  static bool isInside(const fs::path& file, const fs::path& directory) {
    const fs::path relative = file.lexically_relative(directory);
    return !relative.empty() && *relative.begin() != ".." && relative != ".";
  }

  // Applies the path rules of docs/LEVELS.md ("Paths") to the string at `pointer`: relative to
  // the level file or starting with "assets/", and after following symbolic links still inside
  // the level's directory or the asset root.
  ResolvedFile resolveFile(const Json& value, const std::string& pointer, const std::string& kind,
                           const std::vector<std::string>& extensions) const {
    const std::string& text = readString(value, pointer, 1, kMaxStringCharacters);
    const std::string quotedText = "\"" + text + "\"";
    if (text.find('%') != std::string::npos) {
      failValue(pointer, kind + " path " + quotedText +
                             " contains '%': percent-encoding is not supported; write the file "
                             "name as it is on disk");
    }
    if (text.find('\\') != std::string::npos) {
      failValue(pointer, kind + " path " + quotedText +
                             " contains a backslash; separate directories with '/'");
    }
    const bool driveLetter =
        text.size() >= 2 && std::isalpha(static_cast<unsigned char>(text[0])) && text[1] == ':';
    if (text.front() == '/' || driveLetter || fs::path(text).has_root_path()) {
      failValue(pointer, kind + " path " + quotedText +
                             " is absolute; write it relative to the level file or starting "
                             "with \"assets/\"");
    }
    const std::optional<fs::path> assets = assetRoot();
    const std::string assetPrefix = "assets/";
    fs::path base = levelDirectory_;
    std::string relative = text;
    if (text.rfind(assetPrefix, 0) == 0) {
      if (!assets) {
        failValue(pointer, kind + " path " + quotedText +
                               " names the asset directory, but there is none (looked for " +
                               describeAssetRootCandidates() + ")");
      }
      base = *assets;
      relative = text.substr(assetPrefix.size());
    }
    const fs::path lexical = (base / relative).lexically_normal();

    // Canonical forms follow symbolic links; a file is allowed in either directory tree. Both
    // sides are made absolute first: weakly_canonical keeps a path relative when no prefix of
    // it exists, while the roots always exist.
    std::error_code error;
    const fs::path canonicalFile = fs::weakly_canonical(fs::absolute(lexical), error);
    std::vector<fs::path> allowedRoots;
    if (!error) {
      for (const auto& directory : {std::optional<fs::path>(levelDirectory_), assets}) {
        if (!directory) continue;
        std::error_code rootError;
        const fs::path canonicalRoot = fs::weakly_canonical(fs::absolute(*directory), rootError);
        if (!rootError) allowedRoots.push_back(canonicalRoot);
      }
    }
    const auto root = std::find_if(allowedRoots.begin(), allowedRoots.end(),
                                   [&](const fs::path& r) { return isInside(canonicalFile, r); });
    if (error || root == allowedRoots.end()) {
      const bool lexicallyInside =
          isInside(lexical, base.lexically_normal()) ||
          (base.lexically_normal() == "." && !lexical.empty() && *lexical.begin() != "..");
      failValue(pointer, kind + " path " + quotedText +
                             (lexicallyInside ? " leads outside the level's directory and the "
                                                "asset directory through a symbolic link"
                                              : " leaves the level's directory and the asset "
                                                "directory"));
    }
    const std::string extension = toLower(fs::path(text).extension().string());
    if (std::find(extensions.begin(), extensions.end(), extension) == extensions.end()) {
      std::string list;
      for (std::size_t i = 0; i < extensions.size(); ++i) {
        list += (i == 0 ? "" : i + 1 == extensions.size() ? " or " : ", ") + extensions[i];
      }
      expected(value, pointer, "a path to a " + list + " file");
    }

    std::error_code existsError;
    if (!fs::is_regular_file(canonicalFile, existsError)) {
      failValue(pointer,
                kind + " file " + quotedText + " not found (looked for " + lexical.string() + ")");
    }
    return {lexical, *root};
  }

  std::string describeAssetRootCandidates() const {
    std::vector<std::string> names;
    if (options_.assetRoots.empty()) {
      names.push_back((levelDirectory_ / ".." / "assets").lexically_normal().string());
    }
    for (const fs::path& candidate : options_.assetRoots) names.push_back(candidate.string());
    return joinQuoted(names);
  }

  void addSourceFile(Level& level, const fs::path& file) const {
    if (std::find(level.sourceFiles.begin(), level.sourceFiles.end(), file) ==
        level.sourceFiles.end()) {
      level.sourceFiles.push_back(file);
    }
  }

  // The index in level.textures of the texture at `pointer`, loading each file once.
  int32_t readTexture(const Json& value, const std::string& pointer, bool srgb, Level& level) {
    const ResolvedFile file = resolveFile(value, pointer, "texture", {".png", ".jpg", ".jpeg"});
    std::error_code error;
    const std::pair<fs::path, bool> key{fs::weakly_canonical(file.path, error), srgb};
    if (const auto found = textureIndices_.find(key); found != textureIndices_.end()) {
      return found->second;
    }
    if (level.textures.size() >= kMaxTextures) {
      failValue(pointer,
                "more than " + std::to_string(kMaxTextures) + " textures, the limit per level");
    }
    try {
      level.textures.push_back(loadTextureFile(file.path, srgb));
    } catch (const LevelError& problem) {
      failValue(pointer, problem.what());
    }
    addSourceFile(level, file.path);
    const auto index = static_cast<int32_t>(level.textures.size() - 1);
    textureIndices_.emplace(key, index);
    return index;
  }

  // A texture a glTF model brought, shared with an identical one already in the level (the
  // same image file named by a material, or by another model).
  int32_t addModelTexture(render::TextureDesc texture, const std::string& pointer, Level& level) {
    for (std::size_t i = 0; i < level.textures.size(); ++i) {
      const render::TextureDesc& existing = level.textures[i];
      if (existing.srgb == texture.srgb && existing.width == texture.width &&
          existing.height == texture.height && existing.rgba == texture.rgba) {
        return static_cast<int32_t>(i);
      }
    }
    if (level.textures.size() >= kMaxTextures) {
      failValue(pointer, "the model's texture \"" + texture.name + "\" makes more than " +
                             std::to_string(kMaxTextures) + " textures, the limit per level");
    }
    level.textures.push_back(std::move(texture));
    return static_cast<int32_t>(level.textures.size() - 1);
  }

  // ----- sections -----

  render::CameraDesc readCamera(const Json& camera, const std::string& pointer) const {
    checkKeys(camera, pointer, {"position", "yaw_degrees", "pitch_degrees", "fov_degrees"},
              {"position"});
    render::CameraDesc desc;
    desc.position = readVec3(camera["position"], child(pointer, "position"), kCoordinate);
    desc.yawDegrees = readOptionalNumber(camera, "yaw_degrees", pointer, kAnyNumber, 0.0f);
    desc.pitchDegrees = readOptionalNumber(camera, "pitch_degrees", pointer,
                                           NumberRule{-90.0, true, 90.0, true}, 0.0f);
    desc.verticalFovDegrees = readOptionalNumber(camera, "fov_degrees", pointer,
                                                 NumberRule{0.0, false, 179.0, true}, 60.0f);
    return desc;
  }

  render::EnvironmentDesc readEnvironment(const Json& environment,
                                          const std::string& pointer) const {
    checkKeys(environment, pointer, {"sky_zenith", "sky_horizon", "sky_intensity", "ambient"}, {});
    render::EnvironmentDesc desc;
    const float skyIntensity =
        readOptionalNumber(environment, "sky_intensity", pointer, kIntensity, 1.0f);
    desc.skyZenith =
        readOptionalColor(environment, "sky_zenith", pointer, glm::vec3(0.0f)) * skyIntensity;
    desc.skyHorizon =
        readOptionalColor(environment, "sky_horizon", pointer, glm::vec3(0.0f)) * skyIntensity;
    desc.ambient = readOptionalColor(environment, "ambient", pointer, glm::vec3(0.0f));
    return desc;
  }

  uint32_t readRendering(const Json& rendering, const std::string& pointer) const {
    checkKeys(rendering, pointer, {"max_mirror_bounces"}, {});
    return readOptionalCount(rendering, "max_mirror_bounces", pointer, 0, kMaxMirrorBounces, 4);
  }

  render::MaterialDesc readMaterial(const Json& material, const std::string& pointer,
                                    Level& level) {
    checkKeys(material, pointer,
              {"color", "specular", "roughness", "emissive", "emissive_strength", "texture",
               "normal_map", "mirror", "glass"},
              {});
    render::MaterialDesc desc;
    desc.baseColor = readOptionalColor(material, "color", pointer, glm::vec3(1.0f));
    desc.specular = readOptionalNumber(material, "specular", pointer, kUnitInterval, 0.0f);
    desc.roughness = readOptionalNumber(material, "roughness", pointer, kUnitFraction, 0.5f);
    const glm::vec3 emissive = readOptionalColor(material, "emissive", pointer, glm::vec3(0.0f));
    desc.emissive =
        emissive * readOptionalNumber(material, "emissive_strength", pointer, kIntensity, 1.0f);
    if (material.contains("mirror") && material.contains("glass")) {
      failKey(pointer, "glass",
              "a material is a mirror or glass, not both; remove \"mirror\" or \"glass\"");
    }
    if (material.contains("mirror")) {
      const std::string mirrorPointer = child(pointer, "mirror");
      const Json& mirror = material["mirror"];
      checkKeys(mirror, mirrorPointer, {"reflectance", "tint"}, {});
      const float reflectance =
          readOptionalNumber(mirror, "reflectance", mirrorPointer, kUnitInterval, 1.0f);
      const glm::vec3 tint = mirror.contains("tint")
                                 ? readTint(mirror["tint"], child(mirrorPointer, "tint"))
                                 : glm::vec3(1.0f);
      desc.kind = render::MaterialKind::Mirror;
      desc.mirrorTint = reflectance * tint;
    }
    if (material.contains("glass")) {
      const std::string glassPointer = child(pointer, "glass");
      const Json& glass = material["glass"];
      checkKeys(glass, glassPointer, {"tint"}, {"tint"});
      desc.kind = render::MaterialKind::Glass;
      desc.glassTint = readTint(glass["tint"], child(glassPointer, "tint"));
    }
    if (material.contains("texture")) {
      desc.colorTexture = readTexture(material["texture"], child(pointer, "texture"), true, level);
    }
    if (material.contains("normal_map")) {
      desc.normalTexture =
          readTexture(material["normal_map"], child(pointer, "normal_map"), false, level);
    }
    return desc;
  }

  // Refuses a mesh that would take the level past the triangle limit, before it is built.
  void addTriangles(std::size_t triangles, const std::string& pointer) {
    if (triangles > kMaxTriangles - totalTriangles_) {
      failValue(pointer, "this mesh brings the level to " +
                             std::to_string(totalTriangles_ + triangles) +
                             " triangles, more than the limit of " + std::to_string(kMaxTriangles));
    }
    totalTriangles_ += triangles;
  }

  render::MeshData readMesh(const Json& mesh, const std::string& pointer, Level& level) {
    checkKeys(mesh, pointer, {"box", "sphere", "plane", "cylinder", "gltf", "node", "mesh"}, {});
    std::vector<std::string> shapes;
    for (const char* shape : {"box", "sphere", "plane", "cylinder", "gltf"}) {
      if (mesh.contains(shape)) shapes.push_back(shape);
    }
    if (shapes.size() != 1) {
      failValue(pointer,
                "expected exactly one of \"box\", \"sphere\", \"plane\", \"cylinder\", "
                "\"gltf\", got " +
                    (shapes.empty() ? std::string("none") : joinQuoted(shapes)));
    }
    const std::string& shape = shapes.front();
    for (const char* selector : {"node", "mesh"}) {
      if (shape != "gltf" && mesh.contains(selector)) {
        failKey(pointer, selector,
                std::string("\"") + selector + "\" picks part of a glTF model and needs \"gltf\"");
      }
    }
    // Parallel to level.meshes; the material is filled in for glTF models that bring one.
    gltfMaterials_.emplace_back();
    meshIsGltf_.push_back(shape == "gltf");
    const Json& params = mesh[shape];
    const std::string paramsPointer = child(pointer, shape);
    if (shape == "box") {
      checkKeys(params, paramsPointer, {"size"}, {"size"});
      const glm::vec3 size = readVec3(params["size"], child(paramsPointer, "size"), kLength);
      addTriangles(12, pointer);
      return primitives::box(size);
    }
    if (shape == "sphere") {
      checkKeys(params, paramsPointer, {"radius", "segments", "rings"}, {"radius"});
      const float radius = readNumber(params["radius"], child(paramsPointer, "radius"), kLength);
      const uint32_t segments =
          readOptionalCount(params, "segments", paramsPointer, 3, kMaxSegments, 32);
      const uint32_t rings = readOptionalCount(params, "rings", paramsPointer, 2, kMaxRings, 16);
      addTriangles(2 * std::size_t{segments} * (rings - 1), pointer);
      return primitives::sphere(radius, segments, rings);
    }
    if (shape == "plane") {
      checkKeys(params, paramsPointer, {"size"}, {"size"});
      const glm::vec2 size = readVec2(params["size"], child(paramsPointer, "size"), kLength,
                                      "an array of 2 numbers [width, depth]");
      addTriangles(2, pointer);
      return primitives::plane(size.x, size.y);
    }
    if (shape == "cylinder") {
      checkKeys(params, paramsPointer, {"radius", "height", "segments"}, {"radius", "height"});
      const float radius = readNumber(params["radius"], child(paramsPointer, "radius"), kLength);
      const float height = readNumber(params["height"], child(paramsPointer, "height"), kLength);
      const uint32_t segments =
          readOptionalCount(params, "segments", paramsPointer, 3, kMaxSegments, 32);
      addTriangles(4 * std::size_t{segments}, pointer);
      return primitives::cylinder(radius, height, segments);
    }
    return readGltf(mesh, pointer, level);
  }

  render::MeshData readGltf(const Json& mesh, const std::string& pointer, Level& level) {
    if (mesh.contains("node") && mesh.contains("mesh")) {
      failKey(pointer, "mesh", "\"node\" and \"mesh\" both pick part of the model; give only one");
    }
    GltfSelection selection;
    if (mesh.contains("node")) {
      selection.node = readString(mesh["node"], child(pointer, "node"), 1, kMaxStringCharacters);
    }
    if (mesh.contains("mesh")) {
      selection.mesh = readString(mesh["mesh"], child(pointer, "mesh"), 1, kMaxStringCharacters);
    }
    const std::string gltfPointer = child(pointer, "gltf");
    const ResolvedFile file = resolveFile(mesh["gltf"], gltfPointer, "model", {".gltf", ".glb"});
    GltfModel model;
    try {
      model = loadGltfModel(file.path, file.allowedRoot, selection);
    } catch (const LevelError& problem) {
      failValue(gltfPointer, problem.what());
    }
    addTriangles(model.mesh.indices.size() / 3, pointer);
    addSourceFile(level, file.path);
    for (const fs::path& read : model.filesRead) addSourceFile(level, read);
    level.warnings.insert(level.warnings.end(), model.warnings.begin(), model.warnings.end());
    gltfMaterials_.back() = std::move(model.material);
    return std::move(model.mesh);
  }

  render::LightDesc readLight(const Json& light, const std::string& pointer) const {
    static const std::vector<std::string> kTypes{"point", "directional", "sphere", "rectangle",
                                                 "disk"};
    const std::size_t type = readType(light, pointer, kTypes);
    const std::string what = withArticle(kTypes[type]) + " light";
    render::LightDesc desc;
    switch (type) {
      case 0:
        checkKeys(light, pointer, {"type", "position", "color", "intensity", "enabled"},
                  {"position", "intensity"}, what);
        desc.type = render::LightType::Point;
        break;
      case 1:
        checkKeys(
            light, pointer,
            {"type", "direction", "angular_diameter_degrees", "color", "intensity", "enabled"},
            {"direction", "intensity"}, what);
        desc.type = render::LightType::Directional;
        desc.angularDiameterRadians = glm::radians(readOptionalNumber(
            light, "angular_diameter_degrees", pointer, NumberRule{0.0, true, 30.0, true}, 0.0f));
        break;
      case 2:
        checkKeys(light, pointer, {"type", "position", "radius", "color", "intensity", "enabled"},
                  {"position", "radius", "intensity"}, what);
        desc.type = render::LightType::Sphere;
        desc.radius = readNumber(light["radius"], child(pointer, "radius"), kLength);
        break;
      case 3:
        checkKeys(light, pointer,
                  {"type", "position", "direction", "size", "color", "intensity", "enabled"},
                  {"position", "direction", "size", "intensity"}, what);
        desc.type = render::LightType::Rectangle;
        desc.size = readVec2(light["size"], child(pointer, "size"), kLength,
                             "an array of 2 numbers [width, height]");
        break;
      default:
        checkKeys(light, pointer,
                  {"type", "position", "direction", "radius", "color", "intensity", "enabled"},
                  {"position", "direction", "radius", "intensity"}, what);
        desc.type = render::LightType::Disk;
        desc.radius = readNumber(light["radius"], child(pointer, "radius"), kLength);
        break;
    }
    if (light.contains("position")) {
      desc.position = readVec3(light["position"], child(pointer, "position"), kCoordinate);
    }
    if (light.contains("direction")) {
      desc.direction = readDirection(light["direction"], child(pointer, "direction"));
    }
    desc.color = readOptionalColor(light, "color", pointer, glm::vec3(1.0f));
    desc.intensity = readNumber(light["intensity"], child(pointer, "intensity"), kIntensity);
    desc.enabled = readOptionalBool(light, "enabled", pointer, true);
    return desc;
  }

  Entity readEntity(const std::string& id, const Json& entity, const std::string& pointer,
                    Level& level) {
    checkKeys(entity, pointer,
              {"mesh", "material", "position", "rotation_degrees", "scale", "casts_shadow", "mover",
               "interactable"},
              {"mesh"});
    Entity result;
    result.id = id;
    result.mesh = readReference(entity["mesh"], child(pointer, "mesh"), IdKind::Mesh);
    if (entity.contains("material")) {
      result.material =
          readReference(entity["material"], child(pointer, "material"), IdKind::Material);
    } else {
      result.material = modelMaterial(result.mesh, pointer, level);
    }
    if (entity.contains("position")) {
      result.position = readVec3(entity["position"], child(pointer, "position"), kCoordinate);
    }
    if (entity.contains("rotation_degrees")) {
      // [pitch about X, yaw about Y, roll about Z], stored in that order.
      result.rotationDegrees =
          readVec3(entity["rotation_degrees"], child(pointer, "rotation_degrees"), kAnyNumber);
    }
    if (entity.contains("scale")) {
      const Json& scale = entity["scale"];
      const std::string scalePointer = child(pointer, "scale");
      if (scale.is_number()) {
        result.scale = glm::vec3(readNumber(scale, scalePointer, kLength));
      } else if (scale.is_array() && scale.size() == 3) {
        result.scale = readVec3(scale, scalePointer, kLength);
      } else {
        expected(scale, scalePointer, "a number > 0 or an array of 3 numbers > 0");
      }
    }
    result.castsShadow = readOptionalBool(entity, "casts_shadow", pointer, true);
    if (entity.contains("mover") && entity.contains("interactable")) {
      failKey(pointer, "interactable",
              "an entity is a mover or interactable, not both; remove \"mover\" or "
              "\"interactable\"");
    }
    if (entity.contains("mover")) {
      result.mover = readMover(entity["mover"], child(pointer, "mover"), result);
    }
    if (entity.contains("interactable")) {
      result.interactable =
          readInteractable(entity["interactable"], child(pointer, "interactable"));
    }
    return result;
  }

  // The material made from a glTF mesh's own, created on first use as "<mesh id>#gltf".
  uint32_t modelMaterial(uint32_t mesh, const std::string& entityPointer, Level& level) {
    const std::string& meshId = level.meshIds[mesh];
    if (!gltfMaterials_[mesh]) {
      failMissing(
          entityPointer, "material",
          " (mesh \"" + meshId + "\" " +
              (meshIsGltf_[mesh] ? "is a glTF model without a material" : "is not a glTF model") +
              ", so the entity must name one)");
    }
    const std::string materialId = meshId + "#gltf";
    const auto existing = std::find(level.materialIds.begin(), level.materialIds.end(), materialId);
    if (existing != level.materialIds.end()) {
      return static_cast<uint32_t>(existing - level.materialIds.begin());
    }
    if (level.materials.size() >= kMaxMaterials) {
      failValue(entityPointer, "the glTF material of mesh \"" + meshId + "\" makes more than " +
                                   std::to_string(kMaxMaterials) + " materials, the limit");
    }
    GltfMaterial& source = *gltfMaterials_[mesh];
    render::MaterialDesc desc;
    desc.baseColor = source.baseColor;
    desc.specular = source.specular;
    desc.roughness = source.roughness;
    desc.emissive = source.emissive;
    const std::string meshPointer = child("/meshes", meshId);
    if (source.colorTexture) {
      desc.colorTexture = addModelTexture(std::move(*source.colorTexture), meshPointer, level);
    }
    if (source.normalTexture) {
      desc.normalTexture = addModelTexture(std::move(*source.normalTexture), meshPointer, level);
    }
    level.materialIds.push_back(materialId);
    level.materials.push_back(desc);
    return static_cast<uint32_t>(level.materials.size() - 1);
  }

  Mover readMover(const Json& mover, const std::string& pointer, const Entity& entity) const {
    checkKeys(mover, pointer, {"duration_seconds", "repeat", "easing", "keyframes"}, {"keyframes"});
    Mover result;
    result.durationSeconds =
        readOptionalNumber(mover, "duration_seconds", pointer, kPositiveNumber, 1.0f);
    result.repeat = static_cast<Mover::Repeat>(
        readOptionalChoice(mover, "repeat", pointer, {"once", "loop", "ping_pong"}, 1));
    result.easing = static_cast<Mover::Easing>(readOptionalChoice(
        mover, "easing", pointer, {"linear", "smooth", "ease_in", "ease_out"}, 0));
    const Json& keyframes = mover["keyframes"];
    const std::string keyframesPointer = child(pointer, "keyframes");
    if (!keyframes.is_array()) {
      expected(keyframes, keyframesPointer, "an array of 2 to 256 keyframes");
    }
    if (keyframes.size() > kMaxKeyframes) {
      failValue(keyframesPointer, std::to_string(keyframes.size()) +
                                      " keyframes, more than the limit of " +
                                      std::to_string(kMaxKeyframes));
    }
    if (keyframes.size() < kMinKeyframes) {
      failValue(keyframesPointer,
                "expected 2 to 256 keyframes, got " + std::to_string(keyframes.size()));
    }
    for (std::size_t i = 0; i < keyframes.size(); ++i) {
      const std::string keyframePointer = child(keyframesPointer, i);
      const Json& keyframe = keyframes[i];
      checkKeys(keyframe, keyframePointer, {"position", "rotation_degrees"}, {});
      // A keyframe leaves out what does not change from the entity's own pose.
      Keyframe pose{entity.position, entity.rotationDegrees};
      if (keyframe.contains("position")) {
        pose.position =
            readVec3(keyframe["position"], child(keyframePointer, "position"), kCoordinate);
      }
      if (keyframe.contains("rotation_degrees")) {
        pose.rotationDegrees = readVec3(keyframe["rotation_degrees"],
                                        child(keyframePointer, "rotation_degrees"), kAnyNumber);
      }
      result.keyframes.push_back(pose);
    }
    return result;
  }

  // min <= start <= max, with start defaulting to 0 pulled into the range.
  void readRange(const Json& object, const std::string& pointer, const char* minKey,
                 const char* maxKey, const char* startKey, const NumberRule& rule,
                 Interactable& result) const {
    result.min = readNumber(object[minKey], child(pointer, minKey), rule);
    const std::string maxPointer = child(pointer, maxKey);
    result.max = readNumber(object[maxKey], maxPointer, rule);
    if (result.max < result.min) {
      failValue(maxPointer, std::string("expected a number >= ") + minKey + " (" +
                                formatNumber(result.min) + "), got " + describe(object[maxKey]));
    }
    result.start = std::clamp(0.0f, result.min, result.max);
    if (object.contains(startKey)) {
      const std::string startPointer = child(pointer, startKey);
      result.start = readNumber(object[startKey], startPointer, rule);
      if (result.start < result.min || result.start > result.max) {
        failValue(startPointer, std::string("expected a number from ") + minKey + " to " + maxKey +
                                    ", [" + formatNumber(result.min) + ", " +
                                    formatNumber(result.max) + "], got " +
                                    describe(object[startKey]));
      }
    }
  }

  Interactable readInteractable(const Json& interactable, const std::string& pointer) const {
    static const std::vector<std::string> kTypes{"rotate", "slide", "switch"};
    const std::size_t type = readType(interactable, pointer, kTypes);
    const std::string what = "a " + kTypes[type] + " interactable";
    Interactable result;
    result.type = static_cast<Interactable::Type>(type);
    if (result.type == Interactable::Type::Rotate) {
      checkKeys(interactable, pointer,
                {"type", "axis", "min_degrees", "max_degrees", "start_degrees"},
                {"min_degrees", "max_degrees"}, what);
      if (interactable.contains("axis")) {
        result.axis = readDirection(interactable["axis"], child(pointer, "axis"));
      }
      readRange(interactable, pointer, "min_degrees", "max_degrees", "start_degrees", kAnyNumber,
                result);
    } else if (result.type == Interactable::Type::Slide) {
      checkKeys(interactable, pointer, {"type", "axis", "min", "max", "start"},
                {"axis", "min", "max"}, what);
      result.axis = readDirection(interactable["axis"], child(pointer, "axis"));
      readRange(interactable, pointer, "min", "max", "start", kCoordinate, result);
    } else {
      checkKeys(interactable, pointer, {"type", "light", "starts_on"}, {"light"}, what);
      result.light = readReference(interactable["light"], child(pointer, "light"), IdKind::Light);
      result.startsOn = readOptionalBool(interactable, "starts_on", pointer, true);
    }
    return result;
  }

  Goal readGoal(const Json& goal, const std::string& pointer, int depth) const {
    static const std::vector<std::string> kTypes{"focus", "lit", "reach", "all", "any"};
    const std::size_t type = readType(goal, pointer, kTypes);
    const std::string what = withArticle(kTypes[type]) + " goal";
    Goal result;
    result.type = static_cast<Goal::Type>(type);
    switch (result.type) {
      case Goal::Type::Focus:
        checkKeys(goal, pointer,
                  {"type", "orb", "region", "coverage", "rise_per_second", "fall_per_second"},
                  {"orb"}, what);
        result.entity = readReference(goal["orb"], child(pointer, "orb"), IdKind::Entity);
        if (goal.contains("region")) {
          result.region = readVec2(goal["region"], child(pointer, "region"), kUnitFraction,
                                   "an array of 2 numbers [width, height] in (0, 1]");
        }
        result.coverage =
            readOptionalNumber(goal, "coverage", pointer, kUnitFraction, result.coverage);
        result.risePerSecond = readOptionalNumber(goal, "rise_per_second", pointer, kPositiveNumber,
                                                  result.risePerSecond);
        result.fallPerSecond = readOptionalNumber(goal, "fall_per_second", pointer,
                                                  kNonNegativeNumber, result.fallPerSecond);
        break;
      case Goal::Type::Lit:
        checkKeys(goal, pointer, {"type", "sensor", "light", "threshold", "hold_seconds"},
                  {"sensor", "light"}, what);
        result.entity = readReference(goal["sensor"], child(pointer, "sensor"), IdKind::Entity);
        result.light = readReference(goal["light"], child(pointer, "light"), IdKind::Light);
        result.threshold =
            readOptionalNumber(goal, "threshold", pointer, kUnitFraction, result.threshold);
        result.holdSeconds = readOptionalNumber(goal, "hold_seconds", pointer, kNonNegativeNumber,
                                                result.holdSeconds);
        break;
      case Goal::Type::Reach: {
        checkKeys(goal, pointer, {"type", "min", "max"}, {"min", "max"}, what);
        result.min = readVec3(goal["min"], child(pointer, "min"), kCoordinate);
        const std::string maxPointer = child(pointer, "max");
        result.max = readVec3(goal["max"], maxPointer, kCoordinate);
        for (glm::length_t axis = 0; axis < 3; ++axis) {
          if (!(result.max[axis] > result.min[axis])) {
            const auto index = static_cast<std::size_t>(axis);
            failValue(child(maxPointer, index), "expected a number > min[" + std::to_string(index) +
                                                    "] (" + formatNumber(result.min[axis]) +
                                                    "), got " + describe(goal["max"][index]));
          }
        }
        break;
      }
      case Goal::Type::All:
      case Goal::Type::Any: {
        checkKeys(goal, pointer, {"type", "of"}, {"of"}, what);
        const Json& children = goal["of"];
        const std::string ofPointer = child(pointer, "of");
        if (!children.is_array() || children.empty() || children.size() > kMaxGoalChildren) {
          expected(children, ofPointer, "an array of 1 to 16 goals");
        }
        if (depth >= kMaxGoalDepth) {
          failValue(ofPointer,
                    "goals nest more than " + std::to_string(kMaxGoalDepth) + " deep, the limit");
        }
        for (std::size_t i = 0; i < children.size(); ++i) {
          result.children.push_back(readGoal(children[i], child(ofPointer, i), depth + 1));
        }
        break;
      }
    }
    return result;
  }

  std::vector<LoseCondition> readLoseConditions(const Json& lose,
                                                const std::string& pointer) const {
    static const std::vector<std::string> kTypes{"stealth", "fall"};
    if (!lose.is_array()) expected(lose, pointer, "an array of lose conditions");
    std::vector<LoseCondition> conditions;
    for (std::size_t i = 0; i < lose.size(); ++i) {
      const Json& entry = lose[i];
      const std::string entryPointer = child(pointer, i);
      LoseCondition condition;
      if (readType(entry, entryPointer, kTypes) == 0) {
        checkKeys(entry, entryPointer, {"type", "watcher", "exposure_limit", "seconds"},
                  {"watcher"}, "a stealth condition");
        condition.type = LoseCondition::Type::Stealth;
        condition.light =
            readReference(entry["watcher"], child(entryPointer, "watcher"), IdKind::Light);
        condition.exposureLimit = readOptionalNumber(entry, "exposure_limit", entryPointer,
                                                     kUnitFraction, condition.exposureLimit);
        condition.seconds =
            readOptionalNumber(entry, "seconds", entryPointer, kPositiveNumber, condition.seconds);
      } else {
        checkKeys(entry, entryPointer, {"type", "below"}, {"below"}, "a fall condition");
        condition.type = LoseCondition::Type::Fall;
        condition.below = readNumber(entry["below"], child(entryPointer, "below"), kCoordinate);
      }
      conditions.push_back(condition);
    }
    return conditions;
  }

  const std::string& text_;
  const fs::path& file_;
  const LevelLoadOptions& options_;
  const fs::path levelDirectory_;
  JsonPositions positions_;
  std::map<IdKind, std::vector<std::string>> ids_;  // declared ids, in the order written
  std::size_t totalTriangles_ = 0;
  std::vector<std::optional<GltfMaterial>> gltfMaterials_;       // parallel to Level::meshes
  std::vector<bool> meshIsGltf_;                                 // parallel to Level::meshes
  std::map<std::pair<fs::path, bool>, int32_t> textureIndices_;  // (file, srgb) -> texture
};

}  // namespace

Level parseLevel(const std::string& text, const fs::path& file, const LevelLoadOptions& options) {
  return LevelParser(text, file, options).parse();
}

Level loadLevel(const fs::path& file, const LevelLoadOptions& options) {
  std::error_code error;
  std::ifstream stream;
  if (fs::is_regular_file(file, error)) stream.open(file, std::ios::binary);
  if (!stream.is_open()) throw LevelError(file.string() + ": cannot open level file");

  // Read in chunks and stop past the limit, so a huge file is never held in memory whole.
  std::string text;
  char chunk[1 << 16];
  while (text.size() <= kMaxLevelFileBytes &&
         (stream.read(chunk, sizeof chunk) || stream.gcount() > 0)) {
    text.append(chunk, static_cast<std::size_t>(stream.gcount()));
  }
  if (stream.bad()) throw LevelError(file.string() + ": cannot read level file");
  return parseLevel(text, file, options);
}

}  // namespace game
