#pragma once
// Goals and lose conditions, evaluated once per tick from the world and the latest probe readings.
//
// Choices (all counted in ticks so replays are exact):
// - Focus: the score rises by rise_per_second / 60 on each tick whose coverage ≥ the goal's
//   coverage and falls by fall_per_second / 60 otherwise, clamped to [0, 1]. The goal is met on
//   every tick its score is 1 (within 1e-9, then snapped to 1); it is NOT latched: losing the
//   orb lowers the score and unmeets it. Only the level outcome latches.
// - Lit: met on every tick that ends a run of max(1, ceil(hold_seconds × 60)) consecutive ticks
//   with exposure ≥ threshold.
// - Reach: met while the player's feet are inside [min, max] (inclusive); its progress is the
//   share of the distance to the box covered since the first update.
// - All / Any: every / at least one child met on the same tick.
// - Stealth: lost on the tick that ends a run of max(1, ceil(seconds × 60)) consecutive ticks with
//   exposure > exposure_limit. Fall: lost on the first tick with feet y < below.
// - Won on the first tick the root goal is met; lost takes precedence on the same tick. After
//   either, update() changes nothing. A level without a goal never wins.
// - Before any readings arrive, coverage and exposure read as 0.
// (ceil uses a 1e-4 tolerance, so 0.1 s is 6 ticks despite float rounding.)
#include <cstdint>
#include <string>
#include <vector>

#include "game/level.hpp"
#include "game/probes.hpp"

namespace game {

class World;

enum class Outcome { Playing, Won, Lost };

struct GoalProgress {
  std::string label;      // the goal's "label", else "Hold \"orb\" in view", "All 3 of these", ...
  float progress = 0.0f;  // [0, 1]
  bool met = false;
  int32_t orb = -1;  // a focus goal's orb (index into Level::entities), else -1
};

class Rules {
 public:
  static constexpr double TICK_SECONDS = 1.0 / 60.0;

  // Throws std::invalid_argument if `layout` is not probeLayout(level)'s shape.
  Rules(const Level& level, const ProbeLayout& layout);

  // Call once per tick after the world's step; `latest` is the newest readings consumed this
  // tick, or nullptr to keep using the previous ones.
  void update(uint64_t tick, const World& world, const ProbeReadings* latest);

  // An outcome decided on `tick` elsewhere (a level logic's win or lose action), after update():
  // a loss wins over a goal met on the same tick; nothing changes an earlier outcome.
  void decide(Outcome outcome, uint64_t tick, const std::string& reason);

  Outcome outcome() const { return outcome_; }
  uint64_t outcomeTick() const { return outcomeTick_; }  // valid unless Playing
  // The lose condition's label (else "Fell", "Seen by \"lamp\""), or the goal's label + ": met".
  const std::string& reason() const { return reason_; }
  // Every goal node depth first, parents before children (the replay's progress indices).
  const std::vector<GoalProgress>& progress() const { return progress_; }
  bool sandbox() const { return nodes_.empty(); }

 private:
  struct Node {
    Goal goal;  // children are ignored here; see `children`
    std::vector<uint32_t> children;
    int32_t probe = -1;           // Focus: focus index; Lit: exposure index
    uint32_t needTicks = 0;       // Lit
    double score = 0.0;           // Focus
    uint32_t runTicks = 0;        // Lit
    float startDistance = -1.0f;  // Reach: metres from the box at the first update
  };
  struct Loss {
    LoseCondition condition;
    std::string watcher;  // the light's id
    int32_t probe = -1;
    uint32_t needTicks = 0;
    uint32_t runTicks = 0;
  };
  uint32_t addNode(const Goal& goal, const Level& level, uint32_t& focusCount,
                   uint32_t& exposureCount);
  bool evaluate(uint32_t node, const glm::vec3& feet);  // updates progress_, returns met

  std::vector<Node> nodes_;  // depth first; nodes_[0] is the root
  std::vector<Loss> losses_;
  std::vector<GoalProgress> progress_;
  std::vector<float> coverage_, exposure_;
  Outcome outcome_ = Outcome::Playing;
  uint64_t outcomeTick_ = 0;
  std::string reason_;
};

const char* outcomeName(Outcome outcome);  // "playing", "won", "lost"

}  // namespace game
