#include "game/probes.hpp"

#include <algorithm>
#include <set>

namespace game {

namespace {

// Depth first, parents before children, so probe indices follow the goal tree's file order.
std::string litLabel(const Level& level, uint32_t sensor, uint32_t light,
                     scene::ExposureChannel channel) {
  const char* colour = channel == scene::ExposureChannel::Red     ? " red"
                       : channel == scene::ExposureChannel::Green ? " green"
                       : channel == scene::ExposureChannel::Blue  ? " blue"
                                                                  : "";
  return quotedEntityId(level, sensor) + " lit" + colour + " by " + quotedLightId(level, light);
}

std::string seenLabel(const Level& level, uint32_t watcher) {
  return "Seen by " + quotedLightId(level, watcher);
}

void addGoalProbes(const Level& level, const Goal& goal, ProbeLayout& layout) {
  switch (goal.type) {
    case Goal::Type::Focus:
      layout.focus.push_back({goal.entity, goal.region});
      break;
    case Goal::Type::Lit:
      layout.exposure.push_back(
          {ExposureProbe::Target::Entity, goal.entity, goal.light,
           goal.label.empty() ? litLabel(level, goal.entity, goal.light, goal.channel) : goal.label,
           goal.threshold, goal.channel});
      break;
    case Goal::Type::Reach:
      break;
    case Goal::Type::All:
    case Goal::Type::Any:
      for (const Goal& child : goal.children) addGoalProbes(level, child, layout);
      break;
  }
}

// Same order as the logic's own walk over its conditions (game/logic.cpp).
void addConditionProbes(const Level& level, const Condition& condition, ProbeLayout& layout) {
  switch (condition.type) {
    case Condition::Type::Focus:
      layout.focus.push_back({condition.entity, condition.region});
      break;
    case Condition::Type::Lit:
      layout.exposure.push_back(
          {ExposureProbe::Target::Entity, condition.entity, condition.light,
           condition.label.empty()
               ? litLabel(level, condition.entity, condition.light, condition.channel)
               : condition.label,
           condition.threshold, condition.channel});
      break;
    case Condition::Type::Seen:
      layout.exposure.push_back(
          {ExposureProbe::Target::Player, 0, condition.light,
           condition.label.empty() ? seenLabel(level, condition.light) : condition.label,
           condition.threshold});
      break;
    default:
      break;
  }
  for (const Condition& child : condition.children) addConditionProbes(level, child, layout);
}

}  // namespace

ProbeLayout probeLayout(const Level& level) {
  ProbeLayout layout;
  if (level.goal) addGoalProbes(level, *level.goal, layout);
  for (const LoseCondition& lose : level.lose) {
    if (lose.type == LoseCondition::Type::Stealth)
      layout.exposure.push_back({ExposureProbe::Target::Player, 0, lose.light,
                                 lose.label.empty() ? seenLabel(level, lose.light) : lose.label,
                                 lose.exposureLimit});
  }
  layout.firstLogicFocus = layout.focus.size();
  layout.firstLogicExposure = layout.exposure.size();
  for (const Rule& rule : level.rules) addConditionProbes(level, rule.condition, layout);
  return layout;
}

std::vector<size_t> hudMeters(const std::vector<ExposureProbe>& meters,
                              const std::vector<float>& readings, size_t rows) {
  std::vector<size_t> distinct;
  std::set<std::string> labels;
  for (size_t i = 0; i < meters.size(); ++i)
    if (labels.insert(meters[i].label).second) distinct.push_back(i);
  auto priority = [&](size_t i) {
    if (meters[i].target == ExposureProbe::Target::Player) return 0;
    return i < readings.size() && readings[i] > 0.0f ? 1 : 2;
  };
  std::stable_sort(distinct.begin(), distinct.end(),
                   [&](size_t a, size_t b) { return priority(a) < priority(b); });
  if (distinct.size() > rows) distinct.resize(rows);
  std::sort(distinct.begin(), distinct.end());
  return distinct;
}

}  // namespace game
