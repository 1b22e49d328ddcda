#include "game/solution_steps.hpp"

#include <algorithm>

#include "game/collision.hpp"

namespace game {

namespace {

bool readsTheWorld(const Condition& condition) {
  switch (condition.type) {
    case Condition::Type::Timer:
    case Condition::Type::Fired:
      return false;
    case Condition::Type::All:
    case Condition::Type::Any:
    case Condition::Type::Not:
      return std::any_of(condition.children.begin(), condition.children.end(), readsTheWorld);
    default:
      return true;
  }
}

void collectReachBoxes(const Goal& goal, std::vector<const Goal*>& boxes) {
  if (goal.type == Goal::Type::Reach) boxes.push_back(&goal);
  for (const Goal& child : goal.children) collectReachBoxes(child, boxes);
}

const char* verbFor(Interactable::Type type) {
  switch (type) {
    case Interactable::Type::Rotate:
      return "turn ";
    case Interactable::Type::Slide:
      return "slide ";
    case Interactable::Type::Switch:
      break;
  }
  return "switch ";
}

}  // namespace

bool SolutionSteps::ruleIsAStep(const Rule& rule) {
  const bool changesTheWorld =
      std::any_of(rule.actions.begin(), rule.actions.end(), [](const Action& action) {
        return action.type != Action::Type::Message && action.type != Action::Type::Win;
      });
  const bool wins = std::any_of(rule.actions.begin(), rule.actions.end(), [](const Action& action) {
    return action.type == Action::Type::Win;
  });
  return changesTheWorld && !wins && readsTheWorld(rule.condition);
}

SolutionSteps::SolutionSteps(const Level& level, const World& world)
    : level_(level),
      startValues_(level.entities.size(), 0.0f),
      startSwitches_(level.entities.size(), 0),
      interactableDone_(level.entities.size(), 0),
      ruleDone_(level.rules.size(), 0) {
  for (uint32_t e = 0; e < level.entities.size(); ++e) {
    if (!level.entities[e].interactable) continue;
    startValues_[e] = world.interactableValue(e);
    startSwitches_[e] = world.switchOn(e) ? 1 : 0;
  }
  if (level.goal) collectReachBoxes(*level.goal, reachBoxes_);
  reachDone_.assign(reachBoxes_.size(), 0);
}

void SolutionSteps::record(uint64_t tick, std::string what) {
  steps_.push_back({tick, std::move(what)});
}

void SolutionSteps::observe(const World& world, const Logic& logic) {
  const uint64_t tick = world.tick();
  for (uint32_t e = 0; e < level_.entities.size(); ++e) {
    const std::optional<Interactable>& it = level_.entities[e].interactable;
    if (!it || interactableDone_[e]) continue;
    const bool changed = it->type == Interactable::Type::Switch
                             ? (world.switchOn(e) ? 1 : 0) != startSwitches_[e]
                             : world.interactableValue(e) != startValues_[e];
    if (!changed) continue;
    interactableDone_[e] = 1;
    record(tick, verbFor(it->type) + level_.entities[e].id);
  }
  for (size_t r = 0; r < level_.rules.size() && r < logic.ruleCount(); ++r) {
    const std::vector<uint64_t>& firings = logic.firings(r);
    if (ruleDone_[r] || !ruleIsAStep(level_.rules[r])) continue;
    const auto fired =
        std::find_if(firings.begin(), firings.end(), [](uint64_t firedOn) { return firedOn > 0; });
    if (fired == firings.end()) continue;
    ruleDone_[r] = 1;
    record(*fired, "rule " + level_.rules[r].id);
  }
  for (size_t b = 0; b < reachBoxes_.size(); ++b) {
    const Aabb box{reachBoxes_[b]->min, reachBoxes_[b]->max};
    if (reachDone_[b] || !box.contains(world.feetPosition())) continue;
    reachDone_[b] = 1;
    record(tick, "reach goal box " + std::to_string(b + 1));
  }
}

}  // namespace game
