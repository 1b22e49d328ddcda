#include "game/level_format/sections.hpp"

// The "lose" section: what loses the level.
namespace game::level_format {

std::vector<LoseCondition> readLoseConditions(const LevelReader& reader, const OrderedJson& lose,
                                              const std::string& pointer) {
  static const std::vector<std::string> kTypes{"stealth", "fall"};
  if (!lose.is_array()) reader.expected(lose, pointer, "an array of lose conditions");
  std::vector<LoseCondition> conditions;
  for (std::size_t i = 0; i < lose.size(); ++i) {
    const OrderedJson& entry = lose[i];
    const std::string entryPointer = childPointer(pointer, i);
    LoseCondition condition;
    if (reader.readType(entry, entryPointer, kTypes) == 0) {
      reader.checkKeys(entry, entryPointer,
                       {"type", "label", "watcher", "exposure_limit", "seconds"}, {"watcher"},
                       "a stealth condition");
      condition.type = LoseCondition::Type::Stealth;
      condition.light = reader.readReference(entry["watcher"],
                                             childPointer(entryPointer, "watcher"), IdKind::Light);
      condition.exposureLimit = reader.readOptionalNumber(entry, "exposure_limit", entryPointer,
                                                          kUnitFraction, condition.exposureLimit);
      condition.seconds = reader.readOptionalNumber(entry, "seconds", entryPointer, kPositiveNumber,
                                                    condition.seconds);
    } else {
      reader.checkKeys(entry, entryPointer, {"type", "label", "below"}, {"below"},
                       "a fall condition");
      condition.type = LoseCondition::Type::Fall;
      condition.below =
          reader.readNumber(entry["below"], childPointer(entryPointer, "below"), kCoordinate);
    }
    condition.label = reader.readOptionalLabel(entry, entryPointer);
    conditions.push_back(condition);
  }
  return conditions;
}

}  // namespace game::level_format
