#include "game/json_document.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

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

// Builds an ordered_json from SAX events, appending object members without nlohmann's linear
// search for an existing key: the members of every object are found through one open-addressing
// table keyed by (object, key), so a file of many keys costs time linear in its size.
class OrderedJsonBuilder : public nlohmann::json_sax<nlohmann::ordered_json> {
 public:
  using Json = nlohmann::ordered_json;
  using Base = nlohmann::json_sax<Json>;

  Json root;

  bool null() override { return add(Json(nullptr)); }
  bool boolean(bool value) override { return add(Json(value)); }
  bool number_integer(Base::number_integer_t value) override { return add(Json(value)); }
  bool number_unsigned(Base::number_unsigned_t value) override { return add(Json(value)); }
  bool number_float(Base::number_float_t value, const Base::string_t&) override {
    return add(Json(value));
  }
  bool string(Base::string_t& value) override { return add(Json(std::move(value))); }
  bool binary(Base::binary_t& value) override { return add(Json::binary(std::move(value))); }
  bool start_object(std::size_t) override { return open(Json::object()); }
  bool key(Base::string_t& key) override {
    open_.back().key = std::move(key);
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(Json::array()); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    return false;
  }

 private:
  using Members = std::vector<std::pair<const std::string, Json>>;  // ordered_map's base

  struct Open {
    Json* value;
    uint32_t object;  // objects: its number, for the member table
    std::string key;  // objects: the member being read
  };

  // A member of an object: the object's number and the member's place in it (+ 1; 0: empty).
  struct Slot {
    std::size_t hash = 0;
    uint32_t object = 0;
    uint32_t member = 0;
  };

  static std::size_t hashOf(uint32_t object, const std::string& key) {
    return std::hash<std::string>()(key) ^ (std::size_t(object) * 0x9E3779B97F4A7C15u);
  }

  void grow() {
    std::vector<Slot> slots(std::max<std::size_t>(64, slots_.size() * 2));
    const std::size_t mask = slots.size() - 1;
    for (const Slot& slot : slots_) {
      if (slot.member == 0) continue;
      std::size_t at = slot.hash & mask;
      while (slots[at].member != 0) at = (at + 1) & mask;
      slots[at] = slot;
    }
    slots_ = std::move(slots);
  }

  // Places `value` in the open array or object (or as the root); returns where it now lives. A
  // repeated key keeps its first place and takes the new value, as nlohmann's parser does.
  Json* place(Json value) {
    if (open_.empty()) {
      root = std::move(value);
      return &root;
    }
    Open& parent = open_.back();
    if (parent.value->is_array()) {
      parent.value->get_ref<Json::array_t&>().push_back(std::move(value));
      return &parent.value->get_ref<Json::array_t&>().back();
    }
    Members& members = parent.value->get_ref<Json::object_t&>();
    if ((members_ + 1) * 2 > slots_.size()) grow();
    const std::size_t mask = slots_.size() - 1;
    const std::size_t hash = hashOf(parent.object, parent.key);
    std::size_t at = hash & mask;
    for (; slots_[at].member != 0; at = (at + 1) & mask) {
      const Slot& slot = slots_[at];
      if (slot.hash == hash && slot.object == parent.object &&
          members[slot.member - 1].first == parent.key) {
        members[slot.member - 1].second = std::move(value);
        return &members[slot.member - 1].second;
      }
    }
    members.emplace_back(parent.key, std::move(value));
    slots_[at] = {hash, parent.object, static_cast<uint32_t>(members.size())};
    ++members_;
    return &members.back().second;
  }

  bool add(Json value) {
    place(std::move(value));
    return true;
  }

  // A child's address stays valid while it is open: its parent grows only after it closes.
  bool open(Json container) {
    const bool object = container.is_object();
    open_.push_back({place(std::move(container)), object ? ++objects_ : 0u, {}});
    return true;
  }

  bool close() {
    open_.pop_back();
    return true;
  }

  std::vector<Open> open_;
  std::vector<Slot> slots_;  // every object's members; at most half full
  std::size_t members_ = 0;  // slots in use
  uint32_t objects_ = 0;     // objects opened so far
};

}  // namespace

std::optional<nlohmann::ordered_json> parseOrderedJson(std::string_view text) {
  OrderedJsonBuilder builder;
  if (!nlohmann::ordered_json::sax_parse(text, &builder)) return std::nullopt;
  return std::move(builder.root);
}

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

std::optional<JsonShapeProblem> jsonShapeProblem(std::string_view text, std::size_t maxNesting,
                                                 std::size_t maxValues) {
  std::size_t depth = 0, values = 0;
  bool inString = false;
  auto tooMany = [&](std::size_t at) -> std::optional<JsonShapeProblem> {
    if (++values <= maxValues) return std::nullopt;
    return JsonShapeProblem{at, "more than " + std::to_string(maxValues) +
                                    " values (arrays, objects and commas) in the file, the limit"};
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\') {
        ++i;  // the escaped character cannot end the string
      } else if (c == '"') {
        inString = false;
      }
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > maxNesting) {
        return JsonShapeProblem{i, "arrays and objects nest more than " +
                                       std::to_string(maxNesting) + " deep here, the limit"};
      }
      if (auto problem = tooMany(i)) return problem;
    } else if (c == ',') {
      if (auto problem = tooMany(i)) return problem;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return std::nullopt;
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
