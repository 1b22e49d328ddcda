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

}  // namespace

ProbeLayout probeLayout(const Level& level) {
  ProbeLayout layout;
  if (level.goal) addGoalProbes(*level.goal, layout);
  for (const LoseCondition& lose : level.lose) {
    if (lose.type == LoseCondition::Type::Stealth)
      layout.exposure.push_back({ExposureProbe::Target::Player, 0, lose.light});
  }
  return layout;
}

}  // namespace game
