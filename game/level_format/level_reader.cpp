#include "game/level_format/level_reader.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "scene/color.hpp"

namespace game::level_format {

namespace {

namespace fs = std::filesystem;

constexpr std::array<IdKind, 5> kIdKinds{IdKind::Material, IdKind::Mesh, IdKind::Entity,
                                         IdKind::Light, IdKind::Rule};

bool isValidId(const std::string& id) {
  return !id.empty() && std::all_of(id.begin(), id.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  });
}

bool isHexDigit(char c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

}  // namespace

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
    case IdKind::Rule:
      return "rule";
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
    case IdKind::Rule:
      return "rules";
  }
  return "";
}

const char* sectionOf(IdKind kind) {
  return kind == IdKind::Rule ? "logic" : pluralOf(kind);
}

std::string withArticle(const std::string& noun) {
  return (noun.front() == 'e' ? "an " : "a ") + noun;
}

LevelReader::LevelReader(const std::string& text, const fs::path& file,
                         const LevelLoadOptions& options)
    : JsonReader(text, file),
      options_(options),
      levelDirectory_(file.parent_path().empty() ? fs::path(".") : file.parent_path()) {}

void LevelReader::declareIds(const OrderedJson& section, const std::string& pointer, IdKind kind) {
  const std::string noun = nounOf(kind);
  const std::string plural = pluralOf(kind);
  if (!section.is_object()) expected(section, pointer, "an object mapping ids to " + plural);
  const std::map<IdKind, std::size_t> limits{{IdKind::Material, kMaxMaterials},
                                             {IdKind::Mesh, kMaxMeshes},
                                             {IdKind::Entity, kMaxEntities},
                                             {IdKind::Light, kMaxLights},
                                             {IdKind::Rule, kMaxRules}};
  const std::size_t limit = limits.at(kind);
  if (section.size() > limit) {
    failValue(pointer, std::to_string(section.size()) + " " + plural + ", more than the limit of " +
                           std::to_string(limit));
  }
  if (section.empty() && kind != IdKind::Light && kind != IdKind::Rule) {
    failValue(pointer, "a level needs at least one " + noun + ", got {}");
  }
  for (const auto& item : section.items()) {
    if (!isValidId(item.key()) || characterCount(item.key()) > kMaxStringCharacters) {
      failKey(pointer, item.key(),
              "invalid " + noun + " id \"" + item.key() +
                  "\": ids are non-empty and use only letters, digits, '_' and '-'");
    }
  }
  for (const auto& item : section.items()) ids_[kind].push_back(item.key());
}

const std::vector<std::string>& LevelReader::idsOf(IdKind kind) const {
  static const std::vector<std::string> kNone;
  const auto found = ids_.find(kind);
  return found == ids_.end() ? kNone : found->second;
}

uint32_t LevelReader::readReference(const OrderedJson& value, const std::string& pointer,
                                    IdKind kind) const {
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

void LevelReader::failDuplicateKey(const JsonPositions::DuplicateKey& duplicate) const {
  const std::size_t slash = duplicate.pointer.rfind('/');
  const std::string objectPointer = duplicate.pointer.substr(0, slash);
  const std::string key = duplicate.pointer.substr(slash + 1);
  std::string what = "duplicate key";
  for (const IdKind kind : kIdKinds) {
    if (objectPointer == std::string("/") + sectionOf(kind)) {
      what = std::string("duplicate ") + nounOf(kind) + " id";
    }
  }
  failAt(duplicate.position, objectPointer, what + " \"" + unescapeJsonPointerToken(key) + "\"");
}

int LevelReader::readFormat(const OrderedJson& value) const {
  if (!value.is_number_integer()) expected(value, "/format", "the integer 1");
  if (value.is_number_unsigned() ? value.get<uint64_t>() != kSupportedFormat
                                 : value.get<int64_t>() != kSupportedFormat) {
    failValue("/format", "unsupported format " + describeValue(value) +
                             "; this version reads format " + std::to_string(kSupportedFormat));
  }
  return kSupportedFormat;
}

std::string LevelReader::readName(const OrderedJson& value, const std::string& pointer) const {
  return readString(value, pointer, 1, kMaxNameCharacters);
}

std::string LevelReader::readOptionalString(const OrderedJson& object, const char* key,
                                            const std::string& pointer) const {
  return object.contains(key)
             ? readString(object[key], childPointer(pointer, key), 0, kMaxStringCharacters)
             : std::string();
}

std::string LevelReader::readOptionalLabel(const OrderedJson& object,
                                           const std::string& pointer) const {
  return object.contains("label")
             ? readString(object["label"], childPointer(pointer, "label"), 1, kMaxNameCharacters)
             : std::string();
}

glm::vec3 LevelReader::readTint(const OrderedJson& value, const std::string& pointer) const {
  const auto numbers = readNumbers<3>(value, pointer, kUnitInterval, "3 numbers in [0, 1]");
  return {numbers[0], numbers[1], numbers[2]};
}

glm::vec3 LevelReader::readDirection(const OrderedJson& value, const std::string& pointer) const {
  const glm::dvec3 direction(readVec3(value, pointer, kCoordinate));
  const double length = glm::length(direction);
  if (!(length > 0.0)) expected(value, pointer, "a non-zero direction [x, y, z]");
  return glm::vec3(direction / length);
}

glm::vec3 LevelReader::readColor(const OrderedJson& value, const std::string& pointer) const {
  static const std::string kWhat =
      "a colour: [r, g, b] with components in [0, 1] or a string \"#rrggbb\"";
  if (value.is_array() && value.size() == 3) {
    glm::vec3 encoded;
    for (std::size_t i = 0; i < 3; ++i) {
      encoded[static_cast<glm::length_t>(i)] =
          readNumber(value[i], childPointer(pointer, i), kUnitInterval);
    }
    return scene::srgbToLinear(encoded);
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
      return scene::srgbToLinear(encoded);
    }
  }
  expected(value, pointer, kWhat);
}

glm::vec3 LevelReader::readOptionalColor(const OrderedJson& object, const char* key,
                                         const std::string& pointer,
                                         const glm::vec3& fallback) const {
  return object.contains(key) ? readColor(object[key], childPointer(pointer, key)) : fallback;
}

scene::ExposureChannel LevelReader::readSensorColor(const OrderedJson& object,
                                                    const std::string& pointer) const {
  return static_cast<scene::ExposureChannel>(
      readOptionalChoice(object, "color", pointer, {"any", "red", "green", "blue"}, 0));
}

glm::vec2 LevelReader::readOptionalRegion(const OrderedJson& object, const std::string& pointer,
                                          const glm::vec2& fallback) const {
  if (!object.contains("region")) return fallback;
  return readVec2(object["region"], childPointer(pointer, "region"), kUnitFraction,
                  "an array of 2 numbers [width, height] in (0, 1]");
}

void LevelReader::readBox(const OrderedJson& object, const std::string& pointer, glm::vec3& min,
                          glm::vec3& max) const {
  min = readVec3(object["min"], childPointer(pointer, "min"), kCoordinate);
  const std::string maxPointer = childPointer(pointer, "max");
  max = readVec3(object["max"], maxPointer, kCoordinate);
  for (glm::length_t axis = 0; axis < 3; ++axis) {
    if (!(max[axis] > min[axis])) {
      const auto index = static_cast<std::size_t>(axis);
      failValue(childPointer(maxPointer, index),
                "expected a number > min[" + std::to_string(index) + "] (" +
                    formatNumber(min[axis]) + "), got " + describeValue(object["max"][index]));
    }
  }
}

std::pair<float, float> LevelReader::readOrderedPair(const OrderedJson& object,
                                                     const std::string& pointer, const char* minKey,
                                                     const char* maxKey,
                                                     const NumberRule& rule) const {
  const float low = readNumber(object[minKey], childPointer(pointer, minKey), rule);
  const std::string maxPointer = childPointer(pointer, maxKey);
  const float high = readNumber(object[maxKey], maxPointer, rule);
  if (high < low) {
    failValue(maxPointer, std::string("expected a number >= ") + minKey + " (" + formatNumber(low) +
                              "), got " + describeValue(object[maxKey]));
  }
  return {low, high};
}

void LevelReader::addTriangles(std::size_t triangles, const std::string& pointer) {
  if (triangles > kMaxTriangles - totalTriangles_) {
    failValue(pointer, "this mesh brings the level to " +
                           std::to_string(totalTriangles_ + triangles) +
                           " triangles, more than the limit of " + std::to_string(kMaxTriangles));
  }
  totalTriangles_ += triangles;
}

}  // namespace game::level_format
