#include "game/replay.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "game/json_document.hpp"
#include "game/json_positions.hpp"

namespace game {
namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

constexpr uint64_t kMaxTicks = 60ull * 60 * 60;  // an hour of play
constexpr size_t kMaxReplayBytes = 16u << 20;
// The player's field of view in a replay: the range a level's camera may have.
constexpr float kMinVerticalFovDegrees = 1.0f;
constexpr float kMaxVerticalFovDegrees = 179.0f;

class ReplayParser {
 public:
  ReplayParser(const std::string& text, fs::path file) : text_(text), file_(std::move(file)) {}

  Replay parse() {
    if (text_.size() > kMaxReplayBytes)
      throw ReplayError(file_.string() + ": replay file is larger than the 16 MiB limit");
    if (const std::optional<JsonShapeProblem> problem = jsonShapeProblem(text_)) {
      throw ReplayError(placeInFile(file_, positionOfOffset(text_, problem->offset)) +
                        problem->message);
    }
    Json root;
    try {
      root = Json::parse(text_);
    } catch (const Json::exception&) {
      failInvalidJson();
    }
    positions_ = JsonPositions::scan(text_);
    if (!root.is_object()) fail("", "expected an object");
    checkKeys(root, "",
              {"replay", "level", "size", "seed", "vertical_fov_degrees", "probe_every_ticks",
               "probe_latency", "ticks", "input", "expect"});
    require(root, "", "replay");
    if (!root["replay"].is_number_integer() || root["replay"].get<int64_t>() != 1)
      fail("/replay", "unsupported replay format " + root["replay"].dump() +
                          "; this version reads replay format 1");
    Replay replay;
    replay.file = file_;
    require(root, "", "level");
    if (!root["level"].is_string() || root["level"].get<std::string>().empty())
      fail("/level", "expected a path to a level file");
    replay.level = (file_.parent_path() / root["level"].get<std::string>()).lexically_normal();
    replay.levelPlace = fileLineColumn(file_, positions_.valueAt("/level"));
    if (root.contains("size")) {
      const Json& size = root["size"];
      if (!size.is_array() || size.size() != 2) fail("/size", "expected [width, height]");
      replay.width = uint32_t(readInteger(size[0], "/size/0", 1, 4096));
      replay.height = uint32_t(readInteger(size[1], "/size/1", 1, 4096));
    }
    if (root.contains("seed"))
      replay.seed = uint32_t(readInteger(root["seed"], "/seed", 0, 1u << 31));
    if (root.contains("vertical_fov_degrees"))
      replay.verticalFovDegrees = readNumber(root["vertical_fov_degrees"], "/vertical_fov_degrees",
                                             kMinVerticalFovDegrees, kMaxVerticalFovDegrees);
    if (root.contains("probe_every_ticks"))
      replay.probeEveryTicks =
          uint32_t(readInteger(root["probe_every_ticks"], "/probe_every_ticks", 1, 60));
    if (root.contains("probe_latency"))
      replay.probeLatency = uint32_t(readInteger(root["probe_latency"], "/probe_latency", 0, 8));
    require(root, "", "ticks");
    replay.ticks = uint64_t(readInteger(root["ticks"], "/ticks", 1, int64_t(kMaxTicks)));
    if (root.contains("input")) readInput(root["input"], replay);
    if (root.contains("expect")) readExpectations(root["expect"], replay);
    return replay;
  }

 private:
  // Json::parse reports a number too large for a double (1e400) as out_of_range, without a
  // position; a SAX pass finds it, and where a syntax error is.
  [[noreturn]] void failInvalidJson() const {
    const JsonSyntaxError error = firstJsonSyntaxError(text_);
    if (error.numberTooLarge) {
      throw ReplayError(placeInFile(file_, positionOfOffset(text_, error.tokenOffset)) +
                        "invalid JSON: the number " + error.lastToken +
                        " is too large to represent");
    }
    const SourcePosition at = positionOfOffset(text_, error.errorOffset);
    throw ReplayError(placeInFile(file_, at) + "invalid JSON");
  }

  [[noreturn]] void fail(const std::string& pointer, const std::string& message) const {
    // One line whatever the file holds: keys and values are quoted in messages.
    throw ReplayError(escapeControlCharacters(
        placeInFile(file_, positions_.valueAt(pointer), pointer) + message));
  }

  void require(const Json& object, const std::string& pointer, const std::string& key) const {
    if (!object.contains(key)) fail(pointer, "missing required key \"" + key + "\"");
  }

  void checkKeys(const Json& object, const std::string& pointer,
                 const std::vector<std::string>& allowed) const {
    for (const auto& item : object.items()) {
      if (std::find(allowed.begin(), allowed.end(), item.key()) != allowed.end()) continue;
      std::string list;
      for (const std::string& key : allowed) list += (list.empty() ? "\"" : ", \"") + key + "\"";
      const std::string member = pointer + "/" + escapeJsonPointerToken(item.key());
      throw ReplayError(
          escapeControlCharacters(placeInFile(file_, positions_.keyAt(member), pointer) +
                                  "unknown key \"" + item.key() + "\"; allowed keys: " + list));
    }
  }

  int64_t readInteger(const Json& value, const std::string& pointer, int64_t min,
                      int64_t max) const {
    const std::string range =
        "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
    if (!value.is_number_integer()) fail(pointer, "expected " + range + ", got " + value.dump());
    const int64_t number = value.is_number_unsigned() && value.get<uint64_t>() > uint64_t(max)
                               ? max + 1
                               : value.get<int64_t>();
    if (number < min || number > max) fail(pointer, "expected " + range + ", got " + value.dump());
    return number;
  }

  float readNumber(const Json& value, const std::string& pointer, float min, float max) const {
    if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() < min ||
        value.get<double>() > max) {
      std::ostringstream range;
      range << "expected a number in [" << min << ", " << max << "], got " << value.dump();
      fail(pointer, range.str());
    }
    return value.get<float>();
  }

  glm::vec2 readVec2(const Json& value, const std::string& pointer, float min, float max) const {
    if (!value.is_array() || value.size() != 2) fail(pointer, "expected 2 numbers");
    return {readNumber(value[0], pointer + "/0", min, max),
            readNumber(value[1], pointer + "/1", min, max)};
  }

  glm::vec3 readVec3(const Json& value, const std::string& pointer) const {
    if (!value.is_array() || value.size() != 3) fail(pointer, "expected 3 numbers");
    return {readNumber(value[0], pointer + "/0", -1e5f, 1e5f),
            readNumber(value[1], pointer + "/1", -1e5f, 1e5f),
            readNumber(value[2], pointer + "/2", -1e5f, 1e5f)};
  }

  bool readBool(const Json& value, const std::string& pointer) const {
    if (!value.is_boolean()) fail(pointer, "expected true or false, got " + value.dump());
    return value.get<bool>();
  }

  void readInput(const Json& input, Replay& replay) const {
    if (!input.is_array()) fail("/input", "expected an array of input events");
    uint64_t previousTick = 0;
    for (size_t i = 0; i < input.size(); ++i) {
      const std::string pointer = "/input/" + std::to_string(i);
      const Json& event = input[i];
      if (!event.is_object()) fail(pointer, "expected an input event object");
      checkKeys(event, pointer, {"tick", "hold", "move", "look", "jump", "interact", "adjust"});
      require(event, pointer, "tick");
      InputEvent parsed;
      parsed.tick = uint64_t(readInteger(event["tick"], pointer + "/tick", 0, int64_t(kMaxTicks)));
      if (parsed.tick < previousTick)
        fail(pointer + "/tick", "events must be in tick order; tick " +
                                    std::to_string(parsed.tick) + " comes after tick " +
                                    std::to_string(previousTick));
      if (parsed.tick >= replay.ticks)
        fail(pointer + "/tick",
             "tick " + std::to_string(parsed.tick) +
                 " is past the end of the replay (ticks: " + std::to_string(replay.ticks) + ")");
      previousTick = parsed.tick;
      if (event.contains("hold"))
        parsed.hold =
            uint32_t(readInteger(event["hold"], pointer + "/hold", 1, int64_t(kMaxTicks)));
      if (event.contains("move")) parsed.move = readVec2(event["move"], pointer + "/move", -1, 1);
      if (event.contains("look"))
        parsed.lookDegrees = readVec2(event["look"], pointer + "/look", -3600, 3600);
      if (event.contains("jump")) parsed.jump = readBool(event["jump"], pointer + "/jump");
      if (event.contains("interact"))
        parsed.interact = readBool(event["interact"], pointer + "/interact");
      if (event.contains("adjust"))
        parsed.adjust = readNumber(event["adjust"], pointer + "/adjust", -1, 1);
      replay.events.push_back(parsed);
    }
  }

  uint64_t readTick(const Json& object, const std::string& pointer, const Replay& replay) const {
    require(object, pointer, "tick");
    const uint64_t tick =
        uint64_t(readInteger(object["tick"], pointer + "/tick", 0, int64_t(replay.ticks) - 1));
    return tick;
  }

  void readFiredExpectations(const Json& fired, Replay& replay) const {
    if (!fired.is_array()) fail("/expect/fired", "expected an array");
    const int64_t last = int64_t(replay.ticks);
    for (size_t i = 0; i < fired.size(); ++i) {
      const std::string pointer = "/expect/fired/" + std::to_string(i);
      const Json& entry = fired[i];
      if (!entry.is_object()) fail(pointer, "expected an object");
      checkKeys(entry, pointer, {"rule", "between", "never"});
      FiredExpectation parsed;
      parsed.place = pointer;
      require(entry, pointer, "rule");
      if (!entry["rule"].is_string() || entry["rule"].get<std::string>().empty())
        fail(pointer + "/rule", "expected a rule id");
      parsed.rule = entry["rule"].get<std::string>();
      parsed.ruleAt = fileLineColumn(file_, positions_.valueAt(pointer + "/rule"));
      if (entry.contains("between") == entry.contains("never"))
        fail(pointer, "expected exactly one of \"between\" and \"never\"");
      if (entry.contains("never")) {
        if (!readBool(entry["never"], pointer + "/never"))
          fail(pointer + "/never", "expected true (leave \"never\" out to expect a firing)");
        parsed.never = true;
      } else {
        const Json& between = entry["between"];
        if (!between.is_array() || between.size() != 2)
          fail(pointer + "/between", "expected [first tick, last tick]");
        parsed.firstTick = uint64_t(readInteger(between[0], pointer + "/between/0", 0, last));
        parsed.lastTick = uint64_t(
            readInteger(between[1], pointer + "/between/1", int64_t(parsed.firstTick), last));
      }
      replay.fired.push_back(std::move(parsed));
    }
  }

  void readExpectations(const Json& expect, Replay& replay) const {
    if (!expect.is_object()) fail("/expect", "expected an object");
    checkKeys(expect, "/expect", {"outcome", "between", "values", "player", "images", "fired"});
    if (expect.contains("outcome")) {
      const Json& outcome = expect["outcome"];
      const std::string word = outcome.is_string() ? outcome.get<std::string>() : "";
      if (word == "won")
        replay.outcome.outcome = ReplayOutcome::Won;
      else if (word == "lost")
        replay.outcome.outcome = ReplayOutcome::Lost;
      else if (word == "none")
        replay.outcome.outcome = ReplayOutcome::Playing;
      else
        fail("/expect/outcome",
             "expected one of \"won\", \"lost\", \"none\", got " + outcome.dump());
    }
    // The last step reaches tick `ticks`, so an outcome may come on any tick up to it.
    replay.outcome.firstTick = 0;
    replay.outcome.lastTick = replay.ticks;
    if (expect.contains("between")) {
      const Json& between = expect["between"];
      if (!between.is_array() || between.size() != 2)
        fail("/expect/between", "expected [first tick, last tick]");
      const int64_t last = int64_t(replay.ticks);
      replay.outcome.firstTick = uint64_t(readInteger(between[0], "/expect/between/0", 0, last));
      replay.outcome.lastTick = uint64_t(
          readInteger(between[1], "/expect/between/1", int64_t(replay.outcome.firstTick), last));
    }
    if (expect.contains("values")) {
      const Json& values = expect["values"];
      if (!values.is_array()) fail("/expect/values", "expected an array");
      for (size_t i = 0; i < values.size(); ++i) {
        const std::string pointer = "/expect/values/" + std::to_string(i);
        const Json& value = values[i];
        if (!value.is_object()) fail(pointer, "expected an object");
        checkKeys(value, pointer, {"tick", "focus", "exposure", "progress", "range"});
        ValueExpectation parsed;
        parsed.place = pointer;
        parsed.tick = readTick(value, pointer, replay);
        int kinds = 0;
        for (const auto& [key, kind] : {std::pair{"focus", ValueExpectation::Kind::Focus},
                                        std::pair{"exposure", ValueExpectation::Kind::Exposure},
                                        std::pair{"progress", ValueExpectation::Kind::Progress}}) {
          if (!value.contains(key)) continue;
          ++kinds;
          parsed.kind = kind;
          parsed.index = uint32_t(readInteger(value[key], pointer + "/" + key, 0, 63));
        }
        if (kinds != 1)
          fail(pointer, "expected exactly one of \"focus\", \"exposure\", \"progress\" (an index)");
        require(value, pointer, "range");
        const glm::vec2 range = readVec2(value["range"], pointer + "/range", 0, 1);
        if (range.x > range.y) fail(pointer + "/range", "expected [min, max] with min <= max");
        parsed.min = range.x;
        parsed.max = range.y;
        replay.values.push_back(parsed);
      }
    }
    if (expect.contains("player")) {
      const Json& players = expect["player"];
      if (!players.is_array()) fail("/expect/player", "expected an array");
      for (size_t i = 0; i < players.size(); ++i) {
        const std::string pointer = "/expect/player/" + std::to_string(i);
        const Json& player = players[i];
        if (!player.is_object()) fail(pointer, "expected an object");
        checkKeys(player, pointer, {"tick", "feet", "tolerance"});
        PlayerExpectation parsed;
        parsed.place = pointer;
        parsed.tick = readTick(player, pointer, replay);
        require(player, pointer, "feet");
        parsed.feet = readVec3(player["feet"], pointer + "/feet");
        if (player.contains("tolerance"))
          parsed.tolerance = readNumber(player["tolerance"], pointer + "/tolerance", 0, 100);
        replay.players.push_back(parsed);
      }
    }
    if (expect.contains("fired")) readFiredExpectations(expect["fired"], replay);
    if (expect.contains("images")) {
      const Json& images = expect["images"];
      if (!images.is_array()) fail("/expect/images", "expected an array");
      for (size_t i = 0; i < images.size(); ++i) {
        const std::string pointer = "/expect/images/" + std::to_string(i);
        const Json& image = images[i];
        if (!image.is_object()) fail(pointer, "expected an object");
        checkKeys(image, pointer, {"tick", "png", "max_different_share"});
        ImageCheckpoint parsed;
        parsed.place = pointer;
        parsed.tick = readTick(image, pointer, replay);
        require(image, pointer, "png");
        const std::string png = image["png"].is_string() ? image["png"].get<std::string>() : "";
        if (png.empty() || png.find("..") != std::string::npos || png.front() == '/' ||
            !png.ends_with(".png"))
          fail(pointer + "/png", "expected a .png path inside the replay's directory");
        parsed.png = file_.parent_path() / png;
        if (image.contains("max_different_share"))
          parsed.maxDifferentShare =
              readNumber(image["max_different_share"], pointer + "/max_different_share", 0, 1);
        replay.images.push_back(parsed);
      }
    }
  }

  const std::string& text_;
  fs::path file_;
  JsonPositions positions_;
};

}  // namespace

const char* outcomeName(ReplayOutcome outcome) {
  switch (outcome) {
    case ReplayOutcome::Won:
      return "won";
    case ReplayOutcome::Lost:
      return "lost";
    case ReplayOutcome::Playing:
      break;
  }
  return "none";
}

TickInput Replay::inputAt(uint64_t tick) const {
  TickInput input;
  for (const InputEvent& event : events) {
    if (event.tick > tick) break;
    if (tick >= event.tick + event.hold) continue;
    if (event.move) input.move = *event.move;
    input.yawDeltaDegrees += event.lookDegrees.x / float(event.hold);
    input.pitchDeltaDegrees += event.lookDegrees.y / float(event.hold);
    input.jump = input.jump || event.jump;
    input.interact = input.interact || event.interact;
    if (event.adjust != 0.0f) input.adjust = event.adjust;
  }
  return input;
}

void appendTickInput(Replay& replay, const TickInput& input) {
  const uint64_t tick = replay.ticks++;
  const bool looking = input.yawDeltaDegrees != 0.0f || input.pitchDeltaDegrees != 0.0f;
  if (input == TickInput{}) return;
  if (!looking && !replay.events.empty()) {
    InputEvent& last = replay.events.back();
    const bool continues = last.tick + last.hold == tick && last.lookDegrees == glm::vec2(0.0f);
    if (continues && replay.inputAt(last.tick) == input) {
      ++last.hold;
      return;
    }
  }
  InputEvent event;
  event.tick = tick;
  event.move = input.move;
  event.lookDegrees = {input.yawDeltaDegrees, input.pitchDeltaDegrees};
  event.jump = input.jump;
  event.interact = input.interact;
  event.adjust = input.adjust;
  replay.events.push_back(event);
}

Replay parseReplay(const std::string& text, const fs::path& file) {
  return ReplayParser(text, file).parse();
}

Replay loadReplay(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw ReplayError(file.string() + ": cannot open the replay file");
  return parseReplay(readAtMostPastLimit(in, kMaxReplayBytes), file);
}

std::string replayToJson(const Replay& replay) {
  Json root;
  root["replay"] = 1;
  // Relative to the replay where it can be; an absolute level path with a relative replay path
  // (or another root) has no relative form and stays absolute.
  const fs::path relativeLevel = replay.level.lexically_relative(replay.file.parent_path());
  root["level"] = (relativeLevel.empty() ? replay.level : relativeLevel).generic_string();
  root["size"] = {replay.width, replay.height};
  root["seed"] = replay.seed;
  if (replay.verticalFovDegrees) root["vertical_fov_degrees"] = *replay.verticalFovDegrees;
  root["probe_every_ticks"] = replay.probeEveryTicks;
  root["probe_latency"] = replay.probeLatency;
  root["ticks"] = replay.ticks;
  Json input = Json::array();
  for (const InputEvent& event : replay.events) {
    Json entry;
    entry["tick"] = event.tick;
    if (event.hold != 1) entry["hold"] = event.hold;
    if (event.move) entry["move"] = {event.move->x, event.move->y};
    if (event.lookDegrees != glm::vec2(0.0f))
      entry["look"] = {event.lookDegrees.x, event.lookDegrees.y};
    if (event.jump) entry["jump"] = true;
    if (event.interact) entry["interact"] = true;
    if (event.adjust != 0.0f) entry["adjust"] = event.adjust;
    input.push_back(entry);
  }
  root["input"] = input;
  Json expect;
  expect["outcome"] = outcomeName(replay.outcome.outcome);
  if (replay.outcome.outcome != ReplayOutcome::Playing)
    expect["between"] = {replay.outcome.firstTick, replay.outcome.lastTick};
  root["expect"] = expect;
  return root.dump(2) + "\n";
}

}  // namespace game
