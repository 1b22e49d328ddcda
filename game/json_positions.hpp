#pragma once
// nlohmann::json keeps no source positions, so error messages would have none. This scanner
// walks JSON text that has already parsed successfully and remembers where every value (and
// every object key) starts, indexed by JSON pointer.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace game {

struct SourcePosition {
  int line = 1;    // 1-based
  int column = 1;  // 1-based, counted in bytes of the line
};

class JsonPositions {
 public:
  // `text` must be valid JSON (parse it with nlohmann first); malformed text gives partial results.
  static JsonPositions scan(std::string_view text);

  // Where the value at `pointer` starts ("" is the root, "/materials/glass/ior" a member). Falls
  // back to the nearest enclosing value that was recorded, then to 1:1.
  SourcePosition valueAt(const std::string& pointer) const;

  // Where the key of the object member at `pointer` starts; the value's position if none.
  SourcePosition keyAt(const std::string& pointer) const;

  // The first member whose key repeats an earlier key in the same object, if any (nlohmann
  // silently keeps only one of them).
  struct DuplicateKey {
    std::string pointer;
    SourcePosition position;  // of the repeated key
  };
  const std::optional<DuplicateKey>& firstDuplicateKey() const { return firstDuplicateKey_; }

  // The pointer of the value that starts at `position`, if one does (used to name a number
  // nlohmann could not represent, which it reports by offset only).
  std::optional<std::string> pointerOfValueAt(SourcePosition position) const;

 private:
  // Every value read, as a tree: each node knows its parent and its pointer token (an object
  // key, kept in `keys_`, or an array index), and is found from them through one open-addressing
  // table, so time and memory stay linear in the text however deep, wide or long-keyed it is.
  struct Node {
    uint32_t parent = 0;
    uint32_t keyStart = 0;  // object members: the escaped key at keys_[keyStart, +keySize)
    uint32_t keySize = 0;
    uint32_t index = 0;    // array elements: the index
    SourcePosition value;  // where the value starts
    SourcePosition key;    // where its key starts (object members)
    bool isKey = false;    // an object member (else an array element or the root)
    bool valueRecorded = false;
  };

  // Records a child of `parent`: the member `key` (escaped) or element `index`; a repeated key
  // gives the node the first one made.
  uint32_t child(uint32_t parent, bool isKey, std::string_view key, uint32_t index,
                 SourcePosition keyPosition);
  std::string_view keyOf(const Node& node) const;
  // The child of `parent` with `token` (a pointer token: a key, or an index of an array).
  std::optional<uint32_t> findChild(uint32_t parent, std::string_view token) const;
  static std::size_t hashOf(uint32_t parent, bool isKey, std::string_view key, uint32_t index);
  void grow();
  std::string pointerOf(uint32_t node) const;
  std::pair<uint32_t, bool> find(const std::string& pointer) const;

  std::vector<Node> nodes_;      // node 0 is the root
  std::string keys_;             // every member's escaped key, end to end
  std::vector<uint64_t> slots_;  // node id + 1 and half its hash (0: empty); at most half full
  std::optional<DuplicateKey> firstDuplicateKey_;
};

// Escapes one reference token for a JSON pointer ("~" -> "~0", "/" -> "~1").
std::string escapeJsonPointerToken(std::string_view token);

// Undoes escapeJsonPointerToken.
std::string unescapeJsonPointerToken(std::string_view token);

// `text` with its control characters written as escapes ("\n", "\t", "\u001b"), so that a
// message quoting what a file holds (a key, a name, a path) stays on one line.
std::string escapeControlCharacters(std::string_view text);

// Line and column of the byte at zero-based `offset` (clamped to the end of the text).
SourcePosition positionOfOffset(std::string_view text, std::size_t offset);

}  // namespace game
