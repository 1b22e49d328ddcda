#pragma once
// Typed reads from a parsed JSON document that fail with one line naming the file, line, column
// and path of the value, and saying what was expected and what was found: the toolkit the level
// format's section readers are written with.
#include <array>
#include <cfloat>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "game/json_positions.hpp"

namespace game {

// Ordered, so ids keep the order the author wrote them in.
using OrderedJson = nlohmann::ordered_json;

// What JsonReader throws; what() is one line "<file>:<line>:<column>: <path>: <message>".
class JsonInputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// ----- text helpers for messages -----

// Integers exactly, everything else in the shortest form that reads back the same.
std::string formatNumber(double value);

// A short rendering of what the author wrote, for "got ..." in messages. Never recurses into
// nested containers, which may be arbitrarily deep.
std::string describeValue(const OrderedJson& value);

// "\"a\", \"b\"", at most 20 of them; "(none)" for none.
std::string joinQuoted(const std::vector<std::string>& items);

// Characters as a reader counts them: UTF-8 code points (nlohmann has checked the encoding).
std::size_t characterCount(const std::string& text);

std::string toLower(std::string text);

// The candidate `word` was most likely meant to be, if any is close: the same name up to case
// and '_'/'-', or at most two edits away (and fewer edits than the word has letters).
std::optional<std::string> nearMiss(const std::string& word,
                                    const std::vector<std::string>& candidates);

// "; did you mean \"x\"?" or nothing.
std::string didYouMean(const std::optional<std::string>& suggestion);

// The pointer of member `key` or element `index` of the value at `pointer`.
std::string childPointer(const std::string& pointer, const std::string& key);
std::string childPointer(const std::string& pointer, std::size_t index);

// ----- number rules -----

// Which end of a range a number may not cross, whether touching it is allowed, and (for a
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

  std::string describe() const;
};

inline constexpr NumberRule kAnyNumber{};
inline constexpr NumberRule kPositiveNumber{0.0, false};
inline constexpr NumberRule kNonNegativeNumber{0.0, true};
inline constexpr NumberRule kUnitInterval{0.0, true, 1.0, true};
inline constexpr NumberRule kUnitFraction{0.0, false, 1.0, true};

// ----- the reader -----

class JsonReader {
 public:
  // `text` and `file` must outlive the reader; `file` names the text in messages.
  JsonReader(const std::string& text, const std::filesystem::path& file)
      : text_(text), file_(file) {}

  // The document; text that is not JSON fails with the place and nlohmann's reason.
  OrderedJson parse();

  const std::filesystem::path& file() const { return file_; }
  const JsonPositions& positions() const { return positions_; }

  // ----- messages -----

  // "<file>:<line>:<column>: <pointer>: " for the value at `pointer` (warnings).
  std::string placeOf(const std::string& pointer) const;

  [[noreturn]] void failAt(SourcePosition at, const std::string& pointer,
                           const std::string& message) const;
  // At the start of the value at `pointer`.
  [[noreturn]] void failValue(const std::string& pointer, const std::string& message) const;
  // At the key of `pointer`'s member `key`, naming the object that holds it.
  [[noreturn]] void failKey(const std::string& pointer, const std::string& key,
                            const std::string& message) const;
  // "expected <what>, got <the value>".
  [[noreturn]] void expected(const OrderedJson& value, const std::string& pointer,
                             const std::string& what) const;
  [[noreturn]] void failMissing(const std::string& objectPointer, const std::string& key,
                                const std::string& why = "") const;

  // ----- structure -----

  void requireObject(const OrderedJson& value, const std::string& pointer) const;

  // Unknown keys are reported first (they are often misspelt required ones), then missing ones.
  // `what` names the kind of object when the allowed keys depend on its type.
  void checkKeys(const OrderedJson& object, const std::string& pointer,
                 std::initializer_list<const char*> allowed,
                 std::initializer_list<const char*> required, const std::string& what = "") const;

  // Calls readEntry(key, value, pointer) for each member, in the order written.
  template <typename ReadEntry>
  void forEachEntry(const OrderedJson& section, const std::string& pointer,
                    ReadEntry readEntry) const {
    for (const auto& item : section.items()) {
      readEntry(item.key(), item.value(), childPointer(pointer, item.key()));
    }
  }

  // ----- scalars -----

  const std::string& readString(const OrderedJson& value, const std::string& pointer,
                                std::size_t minCharacters, std::size_t maxCharacters) const;
  float readNumber(const OrderedJson& value, const std::string& pointer,
                   const NumberRule& rule) const;
  float readOptionalNumber(const OrderedJson& object, const char* key, const std::string& pointer,
                           const NumberRule& rule, float fallback) const;
  uint32_t readCount(const OrderedJson& value, const std::string& pointer, int64_t min,
                     int64_t max) const;
  uint32_t readOptionalCount(const OrderedJson& object, const char* key, const std::string& pointer,
                             int64_t min, int64_t max, uint32_t fallback) const;
  bool readOptionalBool(const OrderedJson& object, const char* key, const std::string& pointer,
                        bool fallback) const;

  // Which of `names` the string at `pointer` is.
  std::size_t readChoice(const OrderedJson& value, const std::string& pointer,
                         const std::vector<std::string>& names) const;
  std::size_t readOptionalChoice(const OrderedJson& object, const char* key,
                                 const std::string& pointer, const std::vector<std::string>& names,
                                 std::size_t fallback) const;
  // The "type" of an object whose other keys depend on it.
  std::size_t readType(const OrderedJson& object, const std::string& pointer,
                       const std::vector<std::string>& types) const;

  // ----- vectors -----

  template <std::size_t N>
  std::array<float, N> readNumbers(const OrderedJson& value, const std::string& pointer,
                                   const NumberRule& rule, const std::string& what) const {
    if (!value.is_array() || value.size() != N) expected(value, pointer, what);
    std::array<float, N> numbers{};
    for (std::size_t i = 0; i < N; ++i) {
      numbers[i] = readNumber(value[i], childPointer(pointer, i), rule);
    }
    return numbers;
  }
  glm::vec3 readVec3(const OrderedJson& value, const std::string& pointer,
                     const NumberRule& rule) const;
  glm::vec2 readVec2(const OrderedJson& value, const std::string& pointer, const NumberRule& rule,
                     const std::string& what) const;

 private:
  [[noreturn]] void failInvalidJson();

  const std::string& text_;
  const std::filesystem::path& file_;
  JsonPositions positions_;
};

}  // namespace game
