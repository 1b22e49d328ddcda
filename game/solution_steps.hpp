#pragma once
// The steps a run of a level took, counted from the run itself: each interactable whose state
// changed (turned, slid, switched), each rule that fired on what the player did to the world,
// and each reach box of the goal the player entered. The campaign's figures (docs/LEVELS.md,
// "How to design a puzzle") and `sightline campaign` come from these.
#include <cstdint>
#include <string>
#include <vector>

#include "game/level.hpp"
#include "game/logic.hpp"
#include "game/world.hpp"

namespace game {

struct SolutionStep {
  uint64_t tick = 0;  // when it first happened
  std::string what;   // "turn mirror", "slide red_pane", "switch lever", "rule gate_open",
                      // "reach goal box 1"
};

class SolutionSteps {
 public:
  // Reads the interactables' starting states from `world` (before the first step).
  SolutionSteps(const Level& level, const World& world);

  // After each tick's world and logic update.
  void observe(const World& world, const Logic& logic);

  // Distinct steps, in the order they first happened.
  const std::vector<SolutionStep>& steps() const { return steps_; }

  // Whether a rule counts as a step when it fires: its condition reads the world (not only
  // timers and other rules), and it does more than show a message or win.
  static bool ruleIsAStep(const Rule& rule);

 private:
  void record(uint64_t tick, std::string what);

  const Level& level_;
  std::vector<float> startValues_;         // per entity: a rotate's angle, a slide's offset
  std::vector<uint8_t> startSwitches_;     // per entity: a switch's state
  std::vector<uint8_t> interactableDone_;  // per entity
  std::vector<uint8_t> ruleDone_;          // per rule
  std::vector<const Goal*> reachBoxes_;    // the goal's reach boxes, in file order
  std::vector<uint8_t> reachDone_;         // per reach box
  std::vector<SolutionStep> steps_;
};

}  // namespace game
