#pragma once
// What every reader of a JSON file (level, replay, settings, progress) does the same way before
// and around its own fields: reading the text with a size cap, finding where a document that
// does not parse went wrong, and placing a message at "<file>:<line>:<column>: <path>: ".
#include <cstddef>
#include <filesystem>
#include <istream>
#include <string>
#include <string_view>

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
