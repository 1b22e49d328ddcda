#pragma once
// Replays: a level, the probe rules, input by tick and what must happen (docs/REPLAYS.md).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace game {

class ReplayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What the player does on one tick.
struct TickInput {
  glm::vec2 move{0.0f};  // x: strafe right, y: forward, each in [-1, 1]
  float yawDeltaDegrees = 0.0f;
  float pitchDeltaDegrees = 0.0f;
  bool jump = false;
  bool interact = false;  // held: a rotate/slide interactable follows `adjust`
  float adjust = 0.0f;    // [-1, 1]
  bool operator==(const TickInput&) const = default;
};

// One input event: from `tick`, for `hold` ticks. Look deltas are totals, spread evenly.
struct InputEvent {
  uint64_t tick = 0;
  uint32_t hold = 1;
  std::optional<glm::vec2> move;
  glm::vec2 lookDegrees{0.0f};  // yaw, pitch
  bool jump = false;
  bool interact = false;
  float adjust = 0.0f;
};

enum class ReplayOutcome { Playing, Won, Lost };
const char* outcomeName(ReplayOutcome outcome);  // "none", "won", "lost"

struct OutcomeExpectation {
  ReplayOutcome outcome = ReplayOutcome::Playing;  // Playing: neither won nor lost by the end
  uint64_t firstTick = 0, lastTick = 0;            // inclusive; only for won and lost
};

// A probe reading or a goal's progress at a tick must lie in [min, max].
struct ValueExpectation {
  enum class Kind { Focus, Exposure, Progress };
  Kind kind = Kind::Focus;
  uint64_t tick = 0;
  uint32_t index = 0;  // probe index (ProbeLayout order) or goal index (Rules progress order)
  float min = 0.0f, max = 1.0f;
  std::string place;  // "expect.values[2]", for reports
};

struct PlayerExpectation {
  uint64_t tick = 0;
  glm::vec3 feet{0.0f};
  float tolerance = 0.05f;  // metres, per axis
  std::string place;
};

struct ImageCheckpoint {
  uint64_t tick = 0;
  std::filesystem::path png;         // stored image, relative to the replay file
  float maxDifferentShare = 0.005f;  // share of pixels allowed to differ by more than 2/255
  std::string place;
};

// A level-logic rule fired at least once within [firstTick, lastTick], or never did.
struct FiredExpectation {
  std::string rule;    // the rule's id, checked against the level before the replay runs
  std::string ruleAt;  // "file:line:col" of the id, for that check's message
  bool never = false;
  uint64_t firstTick = 0, lastTick = 0;  // inclusive; unless never
  std::string place;
};

struct Replay {
  std::filesystem::path file;
  std::filesystem::path level;  // resolved against the replay's directory
  std::string levelPlace;       // "file:line:col" of the level path, for errors about it
  uint32_t width = 64, height = 36;
  uint32_t seed = 0;
  // The player's field of view when it differs from the level's camera (a play setting).
  std::optional<float> verticalFovDegrees;
  uint32_t probeEveryTicks = 4;    // k: a probe frame after every k-th tick
  uint32_t probeLatency = 2;       // L: its readings reach the rules L probe frames later
  uint64_t ticks = 600;            // how long it runs
  std::vector<InputEvent> events;  // by tick
  OutcomeExpectation outcome;
  std::vector<ValueExpectation> values;
  std::vector<PlayerExpectation> players;
  std::vector<ImageCheckpoint> images;
  std::vector<FiredExpectation> fired;

  TickInput inputAt(uint64_t tick) const;
};

// Recording: appends the input of the next tick (tick = replay.ticks, which grows by one).
// Runs of identical input without look share one event; looking makes one event a tick, so
// the recorded deltas come back exactly.
void appendTickInput(Replay& replay, const TickInput& input);

Replay loadReplay(const std::filesystem::path& file);
Replay parseReplay(const std::string& text, const std::filesystem::path& file);
// Writes a replay (input and outcome) as format-1 JSON; recording uses it.
std::string replayToJson(const Replay& replay);

}  // namespace game
