#pragma once
// What every reader of a JSON file (level, replay, settings, progress) does the same way before
// and around its own fields: reading the text with a size cap, finding where a document that
// does not parse went wrong, and placing a message at "<file>:<line>:<column>: <path>: ".
#include <cstddef>
#include <filesystem>
#include <istream>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "game/json_positions.hpp"

namespace game {

// The first error in JSON text that nlohmann refuses: a syntax error, or a number too large
// for a double (which Json::parse reports without a position).
struct JsonSyntaxError {
  std::size_t bytesRead = 0;    // as nlohmann counts them: up to and including the offending byte
  std::size_t errorOffset = 0;  // the byte to point at: the offending one, or a trailing comma
  std::size_t tokenOffset = 0;  // where the last token read starts
  std::string lastToken;
  // nlohmann's message without its "[json.exception...] parse error ...: ", or "trailing comma
  // before '}'" (or ']') when that is the mistake.
  std::string reason;
  bool numberTooLarge = false;  // the text is valid JSON up to a number no double can hold
};

// Arrays and objects may nest at most this deep in every JSON file Sightline reads (levels,
// replays, settings, progress, glTF): no format needs more (a level with conditions nested to
// their limit about 25), and a reader checks it before building a tree, so deep nesting cannot
// cost more than linear time.
inline constexpr std::size_t kMaxJsonNesting = 64;
// And there may be at most this many values in one file, counted as its arrays, objects and
// commas: each value costs 30 to 130 bytes once read (16 MiB of "[[[]]]" took a gigabyte, a
// 64 MiB glTF of numbers 2.2 GB), while a level needs some hundred thousand, an hour's replay
// about a million and a large glTF scene's JSON a few hundred thousand.
inline constexpr std::size_t kMaxJsonValues = 4'000'000;

// Where a JSON text goes past one of the limits above, and what it says.
struct JsonShapeProblem {
  std::size_t offset = 0;  // the '[' or '{' too deep, or the '[', '{' or ',' one too many
  std::string message;     // "arrays and objects nest more than 64 deep here, the limit"
};

// The first place `text` goes past `maxNesting` or `maxValues`, if it does. One pass,
// skipping strings; `text` need not be valid JSON.
std::optional<JsonShapeProblem> jsonShapeProblem(std::string_view text,
                                                 std::size_t maxNesting = kMaxJsonNesting,
                                                 std::size_t maxValues = kMaxJsonValues);

// `text` parsed into an ordered_json (members in file order), in time linear in its size
// (nlohmann's own parse looks each key up in the object's members so far, quadratic in their
// number); a repeated key keeps its first place and its last value, as nlohmann does. Nothing
// when `text` is not valid JSON (firstJsonSyntaxError says why).
std::optional<nlohmann::ordered_json> parseOrderedJson(std::string_view text);

// Runs a SAX pass over `text`, which must fail to parse, and says where and why it fails.
JsonSyntaxError firstJsonSyntaxError(std::string_view text);

// "<file>:<line>:<column>".
std::string fileLineColumn(const std::filesystem::path& file, SourcePosition at);

// "<file>:<line>:<column>: " followed by "<path>: " when `path` is not empty.
std::string placeInFile(const std::filesystem::path& file, SourcePosition at,
                        const std::string& path = "");

// Up to `maxBytes` + 1 bytes of `stream` (so a caller can tell the file is over its limit),
// read in chunks so that a huge file is never held in memory whole.
std::string readAtMostPastLimit(std::istream& stream, std::size_t maxBytes);

}  // namespace game
