#pragma once
// A level's rules at run time: once per tick, after the world's step and the probe readings due
// at that tick, each rule's condition is evaluated in file order and the actions of the rules
// that fire are applied to the world. Counted in ticks, with no wall-clock time, so play and
// replay agree tick for tick.
//
// Choices (docs/LEVELS.md, "Logic"):
// - A condition with hold_seconds h counts on the ticks that end a run of ceil(h × 60)
//   consecutive ticks on which it is true (h = 0: every tick it is true).
// - "once" fires on the first tick its condition counts; "repeat" on every tick it starts to
//   count again after not counting; "while" applies its actions on such a tick and undoes them
//   on the first tick it stops counting (mover play <-> reverse, show <-> hide, lock <-> unlock,
//   a light back to the state it had before).
// - "fired" reads whether the rule has fired on an earlier tick, or on this tick if it comes
//   earlier in the file. "timer" with "since" counts from the last tick the rule fired.
// - Focus, lit and seen conditions read the newest readings, 0 until the first arrive.
// - A win or lose action ends the level on its tick; lose wins over win, and over a goal met on
//   the same tick. With a respawn point set, a fall below a "fall" lose condition's height puts
//   the player there instead of losing the level.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "game/level.hpp"
#include "game/probes.hpp"
#include "game/rules.hpp"

namespace game {

class World;

class Logic {
 public:
  // `layout` is probeLayout(level); throws std::invalid_argument if it is another level's.
  Logic(const Level& level, const ProbeLayout& layout);

  // Call once per tick after the world's step, before Rules::update; `latest` as for Rules.
  void update(uint64_t tick, World& world, const ProbeReadings* latest);

  size_t ruleCount() const { return rules_.size(); }
  const std::string& ruleId(size_t rule) const { return rules_[rule].rule.id; }
  // Every tick the rule fired on (for "while": started to hold), ascending.
  const std::vector<uint64_t>& firings(size_t rule) const { return rules_[rule].firings; }
  // Whether the rule's condition counted on the last update.
  bool holding(size_t rule) const { return rules_[rule].holding; }

  // A win or lose action ran (the first in file order, lose before win on the same tick).
  std::optional<Outcome> outcome() const { return outcome_; }
  uint64_t outcomeTick() const { return outcomeTick_; }
  const std::string& reason() const { return reason_; }

  // The message a rule showed, while it lasts.
  std::optional<std::string> message(uint64_t tick) const;

 private:
  struct Node {
    Condition condition;  // children are ignored here; see `children`
    std::vector<uint32_t> children;
    int32_t probe = -1;      // Focus: focus index; Lit, Seen: exposure index
    uint32_t needTicks = 0;  // consecutive true ticks before it counts (0: none)
    uint32_t runTicks = 0;
    bool counts = false;  // on the last update
  };
  struct RuleState {
    Rule rule;
    uint32_t root = 0;  // index into nodes_
    bool holding = false;
    std::vector<uint64_t> firings;
    std::vector<uint8_t> lightsBefore;  // "while": per action, the light's state before it
  };
  uint32_t addNode(const Condition& condition, uint32_t& focus, uint32_t& exposure);
  bool evaluate(uint32_t node, uint64_t tick, const World& world);
  void apply(RuleState& state, uint64_t tick, World& world);
  void undo(RuleState& state, World& world);

  std::vector<Node> nodes_;
  std::vector<RuleState> rules_;
  std::vector<float> fallHeights_;  // of the level's fall lose conditions
  std::vector<float> coverage_, exposure_;
  size_t firstFocus_ = 0, firstExposure_ = 0;
  std::optional<Action> respawn_;
  std::string message_;
  uint64_t messageUntil_ = 0;  // the first tick it is no longer shown
  std::optional<Outcome> outcome_;
  uint64_t outcomeTick_ = 0;
  std::string reason_;
};

}  // namespace game
