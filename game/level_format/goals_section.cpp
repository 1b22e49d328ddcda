#include "game/level_format/sections.hpp"

// The "goal" section: what wins the level.
namespace game::level_format {

Goal readGoal(const LevelReader& reader, const OrderedJson& goal, const std::string& pointer,
              int depth) {
  static const std::vector<std::string> kTypes{"focus", "lit", "reach", "all", "any"};
  const std::size_t type = reader.readType(goal, pointer, kTypes);
  const std::string what = withArticle(kTypes[type]) + " goal";
  Goal result;
  result.type = static_cast<Goal::Type>(type);
  switch (result.type) {
    case Goal::Type::Focus:
      reader.checkKeys(
          goal, pointer,
          {"type", "label", "orb", "region", "coverage", "rise_per_second", "fall_per_second"},
          {"orb"}, what);
      result.entity =
          reader.readReference(goal["orb"], childPointer(pointer, "orb"), IdKind::Entity);
      result.region = reader.readOptionalRegion(goal, pointer, result.region);
      result.coverage =
          reader.readOptionalNumber(goal, "coverage", pointer, kUnitFraction, result.coverage);
      result.risePerSecond = reader.readOptionalNumber(goal, "rise_per_second", pointer,
                                                       kPositiveNumber, result.risePerSecond);
      result.fallPerSecond = reader.readOptionalNumber(goal, "fall_per_second", pointer,
                                                       kNonNegativeNumber, result.fallPerSecond);
      break;
    case Goal::Type::Lit:
      reader.checkKeys(goal, pointer,
                       {"type", "label", "sensor", "light", "threshold", "color", "hold_seconds"},
                       {"sensor", "light"}, what);
      result.entity =
          reader.readReference(goal["sensor"], childPointer(pointer, "sensor"), IdKind::Entity);
      result.light =
          reader.readReference(goal["light"], childPointer(pointer, "light"), IdKind::Light);
      result.threshold =
          reader.readOptionalNumber(goal, "threshold", pointer, kUnitFraction, result.threshold);
      result.channel = reader.readSensorColor(goal, pointer);
      result.holdSeconds = reader.readOptionalNumber(goal, "hold_seconds", pointer,
                                                     kNonNegativeNumber, result.holdSeconds);
      break;
    case Goal::Type::Reach: {
      reader.checkKeys(goal, pointer, {"type", "label", "min", "max"}, {"min", "max"}, what);
      reader.readBox(goal, pointer, result.min, result.max);
      break;
    }
    case Goal::Type::All:
    case Goal::Type::Any: {
      reader.checkKeys(goal, pointer, {"type", "label", "of"}, {"of"}, what);
      const OrderedJson& children = goal["of"];
      const std::string ofPointer = childPointer(pointer, "of");
      if (!children.is_array() || children.empty() || children.size() > kMaxGoalChildren) {
        reader.expected(children, ofPointer, "an array of 1 to 16 goals");
      }
      if (depth >= kMaxGoalDepth) {
        reader.failValue(ofPointer, "goals nest more than " + std::to_string(kMaxGoalDepth) +
                                        " deep, the limit");
      }
      for (std::size_t i = 0; i < children.size(); ++i) {
        result.children.push_back(
            readGoal(reader, children[i], childPointer(ofPointer, i), depth + 1));
      }
      break;
    }
  }
  result.label = reader.readOptionalLabel(goal, pointer);
  return result;
}

}  // namespace game::level_format
