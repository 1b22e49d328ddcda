#include "app/level_summary.hpp"

#include <cstdio>

namespace app {

namespace {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string percent(float share) {
  return number(double(share) * 100.0) + "%";
}

}  // namespace

std::string counted(std::size_t count, const std::string& noun, const std::string& plural) {
  return std::to_string(count) + " " + (count == 1 ? noun : plural.empty() ? noun + "s" : plural);
}

std::string describeGoal(const game::Level& level, const game::Goal& goal) {
  switch (goal.type) {
    case game::Goal::Type::Focus:
      return "keep " + game::quotedEntityId(level, goal.entity) +
             " in the centre of the view (covering " + percent(goal.coverage) + " of the middle " +
             percent(goal.region.x) + " x " + percent(goal.region.y) + ") for " +
             number(1.0 / double(goal.risePerSecond)) + " s";
    case game::Goal::Type::Lit:
      return "light " + game::quotedEntityId(level, goal.entity) + " with " +
             game::quotedLightId(level, goal.light) + " (exposure at least " +
             percent(goal.threshold) +
             (goal.holdSeconds > 0.0f ? " for " + number(goal.holdSeconds) + " s" : "") + ")";
    case game::Goal::Type::Reach:
      return "reach the box x " + number(goal.min.x) + ".." + number(goal.max.x) + ", y " +
             number(goal.min.y) + ".." + number(goal.max.y) + ", z " + number(goal.min.z) + ".." +
             number(goal.max.z);
    case game::Goal::Type::All:
    case game::Goal::Type::Any: {
      std::string text = goal.type == game::Goal::Type::All ? "all of: " : "any of: ";
      for (size_t i = 0; i < goal.children.size(); ++i)
        text += (i ? "; " : "") + describeGoal(level, goal.children[i]);
      return text;
    }
  }
  return "";
}

std::string describeLoss(const game::Level& level, const game::LoseCondition& lose) {
  if (lose.type == game::LoseCondition::Type::Fall)
    return "falling below " + number(lose.below) + " m";
  return "being seen by " + game::quotedLightId(level, lose.light) + " (exposure above " +
         percent(lose.exposureLimit) + ") for " + number(lose.seconds) + " s";
}

}  // namespace app
