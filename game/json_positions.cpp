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
  uint32_t node = 0;
};

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

std::size_t JsonPositions::hashOf(uint32_t parent, bool isKey, std::string_view key,
                                  uint32_t index) {
  const std::size_t token =
      isKey ? std::hash<std::string_view>()(key) : index * 0x9E3779B97F4A7C15u;
  return (token ^ (std::size_t(parent) * 0xC2B2AE3D27D4EB4Fu)) + (isKey ? 1 : 0);
}

std::string_view JsonPositions::keyOf(const Node& node) const {
  return std::string_view(keys_).substr(node.keyStart, node.keySize);
}

// A slot holds the node id + 1 in its low half (0: empty) and the upper half of the node's hash
// in its high half, so a probe passes other nodes without reading them.
namespace {
uint64_t slotOf(std::size_t hash, uint32_t id) {
  return (uint64_t(hash >> 32) << 32) | (uint64_t(id) + 1);
}
bool hashMatches(uint64_t slot, std::size_t hash) {
  return (slot >> 32) == (uint64_t(hash) >> 32);
}
uint32_t idOf(uint64_t slot) {
  return uint32_t(slot & 0xFFFFFFFFu) - 1;
}
}  // namespace

void JsonPositions::grow() {
  std::vector<uint64_t> slots(std::max<std::size_t>(64, slots_.size() * 2), 0);
  const std::size_t mask = slots.size() - 1;
  for (uint32_t id = 1; id < nodes_.size(); ++id) {
    const Node& node = nodes_[id];
    const std::size_t hash = hashOf(node.parent, node.isKey, keyOf(node), node.index);
    std::size_t at = hash & mask;
    while (slots[at] != 0) at = (at + 1) & mask;
    slots[at] = slotOf(hash, id);
  }
  slots_ = std::move(slots);
}

uint32_t JsonPositions::child(uint32_t parent, bool isKey, std::string_view key, uint32_t index,
                              SourcePosition keyPosition) {
  if ((nodes_.size() + 1) * 2 > slots_.size()) grow();
  const std::size_t mask = slots_.size() - 1;
  const std::size_t hash = hashOf(parent, isKey, key, index);
  std::size_t at = hash & mask;
  for (; slots_[at] != 0; at = (at + 1) & mask) {
    if (!hashMatches(slots_[at], hash)) continue;
    const uint32_t id = idOf(slots_[at]);
    const Node& existing = nodes_[id];
    if (existing.parent != parent || existing.isKey != isKey) continue;
    if (isKey ? keyOf(existing) != key : existing.index != index) continue;
    // A repeated key: its positions stay those of the first.
    if (isKey && !firstDuplicateKey_) firstDuplicateKey_ = DuplicateKey{pointerOf(id), keyPosition};
    return id;
  }
  Node node;
  node.parent = parent;
  node.isKey = isKey;
  node.index = index;
  node.key = keyPosition;
  if (isKey) {
    node.keyStart = static_cast<uint32_t>(keys_.size());
    node.keySize = static_cast<uint32_t>(key.size());
    keys_ += key;
  }
  nodes_.push_back(node);
  slots_[at] = slotOf(hash, static_cast<uint32_t>(nodes_.size() - 1));
  return static_cast<uint32_t>(nodes_.size() - 1);
}

std::optional<uint32_t> JsonPositions::findChild(uint32_t parent, std::string_view token) const {
  if (slots_.empty()) return std::nullopt;
  const std::size_t mask = slots_.size() - 1;
  // A token of digits may name an array element or an object member.
  uint32_t index = 0;
  bool isIndex = !token.empty() && token.size() <= 9;
  for (const char c : token) {
    if (c < '0' || c > '9') isIndex = false;
    if (isIndex) index = index * 10 + uint32_t(c - '0');
  }
  for (const bool isKey : {true, false}) {
    if (!isKey && !isIndex) break;
    const std::size_t hash = hashOf(parent, isKey, token, index);
    for (std::size_t at = hash & mask; slots_[at] != 0; at = (at + 1) & mask) {
      if (!hashMatches(slots_[at], hash)) continue;
      const Node& node = nodes_[idOf(slots_[at])];
      if (node.parent == parent && node.isKey == isKey &&
          (isKey ? keyOf(node) == token : node.index == index))
        return idOf(slots_[at]);
    }
  }
  return std::nullopt;
}

std::string JsonPositions::pointerOf(uint32_t node) const {
  std::vector<uint32_t> path;
  for (uint32_t at = node; at != 0; at = nodes_[at].parent) path.push_back(at);
  std::string pointer;
  for (auto at = path.rbegin(); at != path.rend(); ++at) {
    const Node& step = nodes_[*at];
    pointer += "/";
    pointer += step.isKey ? std::string(keyOf(step)) : std::to_string(step.index);
  }
  return pointer;
}

// The deepest recorded node on the way to `pointer`, and whether it is the pointer's own.
std::pair<uint32_t, bool> JsonPositions::find(const std::string& pointer) const {
  uint32_t node = 0;
  std::size_t start = 0;
  while (start < pointer.size()) {
    const std::size_t end = std::min(pointer.find('/', start + 1), pointer.size());
    const std::optional<uint32_t> found =
        findChild(node, std::string_view(pointer).substr(start + 1, end - start - 1));
    if (!found) return {node, false};
    node = *found;
    start = end;
  }
  return {node, true};
}

JsonPositions JsonPositions::scan(std::string_view text) {
  JsonPositions result;
  if (text.empty()) return result;
  result.nodes_.emplace_back();  // the root
  Scanner scanner(text);
  std::vector<OpenContainer> open;
  uint32_t node = 0;  // of the value about to be read

  // Reads an object member's key and leaves the scanner at the start of its value.
  auto readMemberKey = [&]() {
    const SourcePosition keyPosition = scanner.position();
    const std::string key = escapeJsonPointerToken(scanner.readString());
    node = result.child(open.back().node, true, key, 0, keyPosition);
    scanner.skipWhitespace();
    scanner.advance();  // ':'
    scanner.skipWhitespace();
  };

  scanner.skipWhitespace();
  bool expectingValue = true;
  while (!scanner.atEnd()) {
    if (expectingValue) {
      Node& current = result.nodes_[node];
      if (!current.valueRecorded) {
        current.value = scanner.position();
        current.valueRecorded = true;
      }
      const char c = scanner.peek();
      if (c == '{' || c == '[') {
        scanner.advance();
        scanner.skipWhitespace();
        open.push_back({c == '[', 0, node});
        const char closing = c == '[' ? ']' : '}';
        if (scanner.peek() == closing) {
          scanner.advance();
          open.pop_back();
          expectingValue = false;
        } else if (c == '[') {
          node = result.child(open.back().node, false, {}, 0, {});
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
        node = result.child(container.node, false, {}, static_cast<uint32_t>(container.nextIndex++),
                            {});
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
  if (nodes_.empty()) return {};
  return nodes_[find(pointer).first].value;
}

std::optional<std::string> JsonPositions::pointerOfValueAt(SourcePosition position) const {
  for (uint32_t node = 0; node < nodes_.size(); ++node) {
    const SourcePosition start = nodes_[node].value;
    if (nodes_[node].valueRecorded && start.line == position.line &&
        start.column == position.column)
      return pointerOf(node);
  }
  return std::nullopt;
}

SourcePosition JsonPositions::keyAt(const std::string& pointer) const {
  if (nodes_.empty()) return {};
  const auto [node, exact] = find(pointer);
  if (exact && nodes_[node].isKey) return nodes_[node].key;
  return nodes_[node].value;
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
