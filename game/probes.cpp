#include "game/probes.hpp"

namespace game {

namespace {

// Depth first, parents before children, so probe indices follow the goal tree's file order.
void addGoalProbes(const Goal& goal, ProbeLayout& layout) {
  switch (goal.type) {
    case Goal::Type::Focus:
      layout.focus.push_back({goal.entity, goal.region});
      break;
    case Goal::Type::Lit:
      layout.exposure.push_back({ExposureProbe::Target::Entity, goal.entity, goal.light});
      break;
    case Goal::Type::Reach:
      break;
    case Goal::Type::All:
    case Goal::Type::Any:
      for (const Goal& child : goal.children) addGoalProbes(child, layout);
      break;
  }
}

// Same order as the logic's own walk over its conditions (game/logic.cpp).
void addConditionProbes(const Condition& condition, ProbeLayout& layout) {
  switch (condition.type) {
    case Condition::Type::Focus:
      layout.focus.push_back({condition.entity, condition.region});
      break;
    case Condition::Type::Lit:
      layout.exposure.push_back({ExposureProbe::Target::Entity, condition.entity, condition.light});
      break;
    case Condition::Type::Seen:
      layout.exposure.push_back({ExposureProbe::Target::Player, 0, condition.light});
      break;
    default:
      break;
  }
  for (const Condition& child : condition.children) addConditionProbes(child, layout);
}

}  // namespace

ProbeLayout probeLayout(const Level& level) {
  ProbeLayout layout;
  if (level.goal) addGoalProbes(*level.goal, layout);
  for (const LoseCondition& lose : level.lose) {
    if (lose.type == LoseCondition::Type::Stealth)
      layout.exposure.push_back({ExposureProbe::Target::Player, 0, lose.light});
  }
  layout.firstLogicFocus = layout.focus.size();
  layout.firstLogicExposure = layout.exposure.size();
  for (const Rule& rule : level.rules) addConditionProbes(rule.condition, layout);
  return layout;
}

}  // namespace game
