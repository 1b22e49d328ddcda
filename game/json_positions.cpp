#include "game/json_positions.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace game {

namespace {

// Walks valid JSON byte by byte while tracking line and column.
class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {
    // nlohmann accepts (and skips) a UTF-8 byte order mark, so do the same.
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") {
      offset_ = 3;
      column_ = 4;
    }
  }

  bool atEnd() const { return offset_ >= text_.size(); }
  char peek() const { return atEnd() ? '\0' : text_[offset_]; }
  SourcePosition position() const { return {line_, column_}; }

  void advance() {
    if (atEnd()) return;
    if (text_[offset_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    ++offset_;
  }

  void skipWhitespace() {
    while (!atEnd()) {
      const char c = peek();
      if (c != ' ' && c != '\t' && c != '\n' && c != '\r') return;
      advance();
    }
  }

  // Reads a string token and returns its decoded content (keys are needed for pointers).
  std::string readString() {
    std::string decoded;
    advance();  // opening quote
    while (!atEnd() && peek() != '"') {
      if (peek() != '\\') {
        decoded.push_back(peek());
        advance();
        continue;
      }
      advance();
      const char escaped = peek();
      advance();
      switch (escaped) {
        case 'b':
          decoded.push_back('\b');
          break;
        case 'f':
          decoded.push_back('\f');
          break;
        case 'n':
          decoded.push_back('\n');
          break;
        case 'r':
          decoded.push_back('\r');
          break;
        case 't':
          decoded.push_back('\t');
          break;
        case 'u':
          appendUtf8(decoded, readUnicodeEscape());
          break;
        default:
          decoded.push_back(escaped);
          break;  // '"', '\\', '/'
      }
    }
    advance();  // closing quote
    return decoded;
  }

  // Skips a number or literal (true, false, null); strings go through readString.
  void skipScalar() {
    while (!atEnd()) {
      const char c = peek();
      if (c == ',' || c == '}' || c == ']' || c == ' ' || c == '\t' || c == '\n' || c == '\r') {
        return;
      }
      advance();
    }
  }

 private:
  uint32_t readHex4() {
    uint32_t value = 0;
    for (int i = 0; i < 4 && !atEnd(); ++i) {
      const char c = peek();
      uint32_t digit = 0;
      if (c >= '0' && c <= '9') digit = static_cast<uint32_t>(c - '0');
      if (c >= 'a' && c <= 'f') digit = static_cast<uint32_t>(c - 'a' + 10);
      if (c >= 'A' && c <= 'F') digit = static_cast<uint32_t>(c - 'A' + 10);
      value = value * 16 + digit;
      advance();
    }
    return value;
  }

  // Handles surrogate pairs, which valid JSON spells as two consecutive \u escapes.
  uint32_t readUnicodeEscape() {
    const uint32_t first = readHex4();
    if (first >= 0xD800 && first <= 0xDBFF && text_.substr(offset_, 2) == "\\u") {
      advance();
      advance();
      const uint32_t second = readHex4();
      return 0x10000 + ((first - 0xD800) << 10) + (second - 0xDC00);
    }
    return first;
  }

  static void appendUtf8(std::string& out, uint32_t codePoint) {
    auto byte = [](uint32_t bits) { return static_cast<char>(static_cast<unsigned char>(bits)); };
    if (codePoint < 0x80) {
      out.push_back(byte(codePoint));
    } else if (codePoint < 0x800) {
      out.push_back(byte(0xC0 | (codePoint >> 6)));
      out.push_back(byte(0x80 | (codePoint & 0x3F)));
    } else if (codePoint < 0x10000) {
      out.push_back(byte(0xE0 | (codePoint >> 12)));
      out.push_back(byte(0x80 | ((codePoint >> 6) & 0x3F)));
      out.push_back(byte(0x80 | (codePoint & 0x3F)));
    } else {
      out.push_back(byte(0xF0 | (codePoint >> 18)));
      out.push_back(byte(0x80 | ((codePoint >> 12) & 0x3F)));
      out.push_back(byte(0x80 | ((codePoint >> 6) & 0x3F)));
      out.push_back(byte(0x80 | (codePoint & 0x3F)));
    }
  }

  std::string_view text_;
  std::size_t offset_ = 0;
  int line_ = 1;
  int column_ = 1;
};

// An array or object being walked; kept on an explicit stack so deep nesting cannot overflow
// the call stack.
struct OpenContainer {
  bool isArray = false;
  std::size_t nextIndex = 0;
  std::string pointer;
};

SourcePosition lookup(const std::unordered_map<std::string, SourcePosition>& positions,
                      std::string pointer) {
  while (true) {
    if (auto found = positions.find(pointer); found != positions.end()) return found->second;
    if (pointer.empty()) return {};
    pointer.erase(pointer.rfind('/'));
  }
}

}  // namespace

std::string unescapeJsonPointerToken(std::string_view token) {
  std::string unescaped;
  for (std::size_t i = 0; i < token.size(); ++i) {
    if (token[i] == '~' && i + 1 < token.size()) {
      unescaped.push_back(token[i + 1] == '1' ? '/' : '~');
      ++i;
    } else {
      unescaped.push_back(token[i]);
    }
  }
  return unescaped;
}

std::string escapeControlCharacters(std::string_view text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7f) {
      escaped.push_back(c);
    } else if (c == '\n') {
      escaped += "\\n";
    } else if (c == '\r') {
      escaped += "\\r";
    } else if (c == '\t') {
      escaped += "\\t";
    } else {
      char code[8];
      std::snprintf(code, sizeof code, "\\u%04x", byte);
      escaped += code;
    }
  }
  return escaped;
}

std::string escapeJsonPointerToken(std::string_view token) {
  std::string escaped;
  escaped.reserve(token.size());
  for (const char c : token) {
    if (c == '~') {
      escaped += "~0";
    } else if (c == '/') {
      escaped += "~1";
    } else {
      escaped.push_back(c);
    }
  }
  return escaped;
}

JsonPositions JsonPositions::scan(std::string_view text) {
  JsonPositions result;
  Scanner scanner(text);
  std::vector<OpenContainer> open;
  std::string pointer;  // of the value about to be read

  // Reads an object member's key and leaves the scanner at the start of its value.
  auto readMemberKey = [&]() {
    const SourcePosition keyPosition = scanner.position();
    const std::string key = scanner.readString();
    pointer = open.back().pointer + "/" + escapeJsonPointerToken(key);
    if (!result.keys_.emplace(pointer, keyPosition).second && !result.firstDuplicateKey_) {
      result.firstDuplicateKey_ = DuplicateKey{pointer, keyPosition};
    }
    scanner.skipWhitespace();
    scanner.advance();  // ':'
    scanner.skipWhitespace();
  };

  scanner.skipWhitespace();
  bool expectingValue = true;
  while (!scanner.atEnd()) {
    if (expectingValue) {
      result.values_.emplace(pointer, scanner.position());
      const char c = scanner.peek();
      if (c == '{' || c == '[') {
        scanner.advance();
        scanner.skipWhitespace();
        open.push_back({c == '[', 0, pointer});
        const char closing = c == '[' ? ']' : '}';
        if (scanner.peek() == closing) {
          scanner.advance();
          open.pop_back();
          expectingValue = false;
        } else if (c == '[') {
          pointer = open.back().pointer + "/0";
          open.back().nextIndex = 1;
        } else {
          readMemberKey();
        }
        continue;
      }
      if (c == '"') {
        scanner.readString();
      } else {
        scanner.skipScalar();
      }
      expectingValue = false;
      continue;
    }

    // After a value: a separator, the end of its container, or the end of the document.
    if (open.empty()) break;
    scanner.skipWhitespace();
    const char c = scanner.peek();
    scanner.advance();
    if (c == ',') {
      scanner.skipWhitespace();
      OpenContainer& container = open.back();
      if (container.isArray) {
        pointer = container.pointer + "/" + std::to_string(container.nextIndex++);
      } else {
        readMemberKey();
      }
      expectingValue = true;
    } else {
      open.pop_back();  // '}' or ']'
    }
  }
  return result;
}

SourcePosition JsonPositions::valueAt(const std::string& pointer) const {
  return lookup(values_, pointer);
}

std::optional<std::string> JsonPositions::pointerOfValueAt(SourcePosition position) const {
  for (const auto& [pointer, start] : values_) {
    if (start.line == position.line && start.column == position.column) return pointer;
  }
  return std::nullopt;
}

SourcePosition JsonPositions::keyAt(const std::string& pointer) const {
  if (auto found = keys_.find(pointer); found != keys_.end()) return found->second;
  return valueAt(pointer);
}

SourcePosition positionOfOffset(std::string_view text, std::size_t offset) {
  SourcePosition position;
  const std::size_t end = offset < text.size() ? offset : text.size();
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++position.line;
      position.column = 1;
    } else {
      ++position.column;
    }
  }
  return position;
}

}  // namespace game
