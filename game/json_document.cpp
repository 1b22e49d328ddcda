#include "game/json_document.hpp"

#include <nlohmann/json.hpp>

namespace game {

namespace {

// Accepts every value and keeps the first error with the byte where it was found.
struct FirstErrorSax : nlohmann::json_sax<nlohmann::json> {
  using Base = nlohmann::json_sax<nlohmann::json>;
  JsonSyntaxError error;

  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(Base::number_integer_t) override { return true; }
  bool number_unsigned(Base::number_unsigned_t) override { return true; }
  bool number_float(Base::number_float_t, const Base::string_t&) override { return true; }
  bool string(Base::string_t&) override { return true; }
  bool binary(Base::binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(Base::string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }

  bool parse_error(std::size_t position, const std::string& lastToken,
                   const nlohmann::detail::exception& exception) override {
    error.bytesRead = position;
    error.lastToken = lastToken;
    // The error comes after the token was read.
    error.tokenOffset = position >= lastToken.size() ? position - lastToken.size() : 0;
    error.numberTooLarge =
        dynamic_cast<const nlohmann::detail::parse_error*>(&exception) == nullptr;
    // what() reads "[json.exception.parse_error.101] parse error at line 1, column 7: <reason>".
    std::string reason = exception.what();
    if (const std::size_t prefixEnd = reason.find("] "); prefixEnd != std::string::npos) {
      reason.erase(0, prefixEnd + 2);
    }
    if (reason.rfind("parse error", 0) == 0) {
      if (const std::size_t colon = reason.find(": "); colon != std::string::npos) {
        reason.erase(0, colon + 2);
      }
    }
    error.reason = std::move(reason);
    return false;
  }
};

}  // namespace

JsonSyntaxError firstJsonSyntaxError(std::string_view text) {
  FirstErrorSax sax;
  nlohmann::json::sax_parse(text, &sax);
  JsonSyntaxError& error = sax.error;
  error.errorOffset = error.bytesRead == 0 ? 0 : error.bytesRead - 1;
  // nlohmann says "unexpected '}'; expected string literal" for {"a": 1,}: name the comma.
  const std::size_t at = error.errorOffset;
  if (!error.numberTooLarge && at < text.size() && (text[at] == '}' || text[at] == ']')) {
    std::size_t before = at;
    while (before > 0 && (text[before - 1] == ' ' || text[before - 1] == '\t' ||
                          text[before - 1] == '\n' || text[before - 1] == '\r')) {
      --before;
    }
    if (before > 0 && text[before - 1] == ',') {
      error.errorOffset = before - 1;
      error.reason = std::string("trailing comma before '") + text[at] + "'; JSON allows none";
    }
  }
  return error;
}

std::string fileLineColumn(const std::filesystem::path& file, SourcePosition at) {
  return file.string() + ":" + std::to_string(at.line) + ":" + std::to_string(at.column);
}

std::string placeInFile(const std::filesystem::path& file, SourcePosition at,
                        const std::string& path) {
  return fileLineColumn(file, at) + ": " + (path.empty() ? "" : path + ": ");
}

std::string readAtMostPastLimit(std::istream& stream, std::size_t maxBytes) {
  std::string text;
  char chunk[1 << 14];
  while (text.size() <= maxBytes && (stream.read(chunk, sizeof chunk) || stream.gcount() > 0)) {
    text.append(chunk, static_cast<std::size_t>(stream.gcount()));
  }
  return text;
}

}  // namespace game
