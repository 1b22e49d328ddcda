#include "game/json_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "game/json_document.hpp"

namespace game {

namespace {

const char* const kFloatLimit = "numbers are stored as 32-bit floats, within ±3.4e38";

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

}  // namespace

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

std::string describeValue(const OrderedJson& value) {
  auto dump = [](const OrderedJson& json) {
    return json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  };
  constexpr std::size_t kMaxShown = 40;
  if (value.is_object()) return value.empty() ? "{}" : "an object";
  if (value.is_array()) {
    const bool flat = std::none_of(value.begin(), value.end(),
                                   [](const OrderedJson& item) { return item.is_structured(); });
    if (flat && value.size() <= 8) {
      const std::string text = dump(value);
      if (text.size() <= kMaxShown) return text;
    }
    return "an array of " + std::to_string(value.size()) + " elements";
  }
  if (value.is_string()) {
    const auto& text = value.get_ref<const std::string&>();
    if (text.size() > kMaxShown) return dump(OrderedJson(text.substr(0, kMaxShown))) + "...";
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

std::string toLower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::size_t characterCount(const std::string& text) {
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }));
}

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

std::string childPointer(const std::string& pointer, const std::string& key) {
  return pointer + "/" + escapeJsonPointerToken(key);
}

std::string childPointer(const std::string& pointer, std::size_t index) {
  return pointer + "/" + std::to_string(index);
}

std::string NumberRule::describe() const {
  const bool bounded = max < FLT_MAX;
  if (min <= -FLT_MAX && !bounded) return "a number";
  if (!bounded) return std::string("a number ") + (minInclusive ? ">= " : "> ") + formatNumber(min);
  if (min <= -FLT_MAX) {
    return std::string("a number ") + (maxInclusive ? "<= " : "< ") + formatNumber(max);
  }
  return std::string("a number in ") + (minInclusive ? "[" : "(") + formatNumber(min) + ", " +
         formatNumber(max) + (maxInclusive ? "]" : ")");
}

OrderedJson JsonReader::parse() {
  if (const std::optional<JsonShapeProblem> problem = jsonShapeProblem(text_)) {
    throw JsonInputError(placeInFile(file_, positionOfOffset(text_, problem->offset)) +
                         problem->message);
  }
  std::optional<OrderedJson> root = parseOrderedJson(text_);
  if (!root) failInvalidJson();
  positions_ = JsonPositions::scan(text_);
  return std::move(*root);
}

void JsonReader::failInvalidJson() {
  const JsonSyntaxError error = firstJsonSyntaxError(text_);
  if (error.numberTooLarge) {
    // A number too large for a double (1e999): the text is valid JSON up to there, so the value
    // can be named by its path.
    const SourcePosition at = positionOfOffset(text_, error.tokenOffset);
    positions_ = JsonPositions::scan(text_);
    const std::string pointer = positions_.pointerOfValueAt(at).value_or("");
    failAt(
        at, pointer,
        "expected a finite number, got " + error.lastToken + ", which is too large to represent");
  }
  throw JsonInputError(placeInFile(file_, positionOfOffset(text_, error.errorOffset)) +
                       "invalid JSON: " + error.reason);
}

std::string JsonReader::placeOf(const std::string& pointer) const {
  return escapeControlCharacters(placeInFile(file_, positions_.valueAt(pointer), pointer));
}

void JsonReader::failAt(SourcePosition at, const std::string& pointer,
                        const std::string& message) const {
  // One line whatever the file holds: keys, ids and paths are quoted in messages.
  throw JsonInputError(escapeControlCharacters(placeInFile(file_, at, pointer) + message));
}

void JsonReader::failValue(const std::string& pointer, const std::string& message) const {
  failAt(positions_.valueAt(pointer), pointer, message);
}

void JsonReader::failKey(const std::string& pointer, const std::string& key,
                         const std::string& message) const {
  failAt(positions_.keyAt(childPointer(pointer, key)), pointer, message);
}

void JsonReader::expected(const OrderedJson& value, const std::string& pointer,
                          const std::string& what) const {
  failValue(pointer, "expected " + what + ", got " + describeValue(value));
}

void JsonReader::failMissing(const std::string& objectPointer, const std::string& key,
                             const std::string& why) const {
  failValue(objectPointer, "missing required key \"" + key + "\"" + why);
}

void JsonReader::requireObject(const OrderedJson& value, const std::string& pointer) const {
  if (!value.is_object()) expected(value, pointer, "an object");
}

void JsonReader::checkKeys(const OrderedJson& object, const std::string& pointer,
                           std::initializer_list<const char*> allowed,
                           std::initializer_list<const char*> required,
                           const std::string& what) const {
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

const std::string& JsonReader::readString(const OrderedJson& value, const std::string& pointer,
                                          std::size_t minCharacters,
                                          std::size_t maxCharacters) const {
  const std::string what = "a string of " + std::to_string(minCharacters) + " to " +
                           std::to_string(maxCharacters) + " characters";
  if (!value.is_string()) expected(value, pointer, what);
  const auto& text = value.get_ref<const std::string&>();
  const std::size_t characters = characterCount(text);
  if (characters < minCharacters) expected(value, pointer, what);
  if (characters > maxCharacters) {
    failValue(pointer, "expected " + what + ", got " + std::to_string(characters) + " characters");
  }
  return text;
}

float JsonReader::readNumber(const OrderedJson& value, const std::string& pointer,
                             const NumberRule& rule) const {
  if (!value.is_number()) expected(value, pointer, rule.describe());
  const double number = value.get<double>();
  if (!rule.accepts(number)) {
    const char* limit = rule.limit != nullptr && rule.beyondLimit(number) ? rule.limit
                        : std::abs(number) > FLT_MAX                      ? kFloatLimit
                                                                          : nullptr;
    failValue(pointer, "expected " + rule.describe() + ", got " + describeValue(value) +
                           (limit != nullptr ? std::string("; ") + limit : ""));
  }
  return static_cast<float>(number);
}

float JsonReader::readOptionalNumber(const OrderedJson& object, const char* key,
                                     const std::string& pointer, const NumberRule& rule,
                                     float fallback) const {
  return object.contains(key) ? readNumber(object[key], childPointer(pointer, key), rule)
                              : fallback;
}

uint32_t JsonReader::readCount(const OrderedJson& value, const std::string& pointer, int64_t min,
                               int64_t max) const {
  if (!value.is_number_integer() ||
      (value.is_number_unsigned() && value.get<uint64_t>() > static_cast<uint64_t>(max)) ||
      value.get<int64_t>() < min || value.get<int64_t>() > max) {
    expected(value, pointer,
             "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
  }
  return static_cast<uint32_t>(value.get<int64_t>());
}

uint32_t JsonReader::readOptionalCount(const OrderedJson& object, const char* key,
                                       const std::string& pointer, int64_t min, int64_t max,
                                       uint32_t fallback) const {
  return object.contains(key) ? readCount(object[key], childPointer(pointer, key), min, max)
                              : fallback;
}

bool JsonReader::readOptionalBool(const OrderedJson& object, const char* key,
                                  const std::string& pointer, bool fallback) const {
  if (!object.contains(key)) return fallback;
  const OrderedJson& value = object[key];
  if (!value.is_boolean()) expected(value, childPointer(pointer, key), "true or false");
  return value.get<bool>();
}

std::size_t JsonReader::readChoice(const OrderedJson& value, const std::string& pointer,
                                   const std::vector<std::string>& names) const {
  if (value.is_string()) {
    const auto& text = value.get_ref<const std::string&>();
    const auto found = std::find(names.begin(), names.end(), text);
    if (found != names.end()) return static_cast<std::size_t>(found - names.begin());
    failValue(pointer, "expected one of " + joinQuoted(names) + ", got " + describeValue(value) +
                           didYouMean(nearMiss(text, names)));
  }
  expected(value, pointer, "one of " + joinQuoted(names));
}

std::size_t JsonReader::readOptionalChoice(const OrderedJson& object, const char* key,
                                           const std::string& pointer,
                                           const std::vector<std::string>& names,
                                           std::size_t fallback) const {
  return object.contains(key) ? readChoice(object[key], childPointer(pointer, key), names)
                              : fallback;
}

std::size_t JsonReader::readType(const OrderedJson& object, const std::string& pointer,
                                 const std::vector<std::string>& types) const {
  requireObject(object, pointer);
  if (!object.contains("type")) failMissing(pointer, "type");
  return readChoice(object["type"], childPointer(pointer, "type"), types);
}

glm::vec3 JsonReader::readVec3(const OrderedJson& value, const std::string& pointer,
                               const NumberRule& rule) const {
  const auto numbers = readNumbers<3>(value, pointer, rule, "an array of 3 numbers [x, y, z]");
  return {numbers[0], numbers[1], numbers[2]};
}

glm::vec2 JsonReader::readVec2(const OrderedJson& value, const std::string& pointer,
                               const NumberRule& rule, const std::string& what) const {
  const auto numbers = readNumbers<2>(value, pointer, rule, what);
  return {numbers[0], numbers[1]};
}

}  // namespace game
