#include <algorithm>
#include <functional>
#include <map>
#include <tuple>

#include "game/level_format/sections.hpp"

// The "logic" section: named rules, each a condition and the actions it runs (docs/LEVELS.md,
// "Logic"). Checked as a whole once every rule is read: `fired` conditions may not form a cycle,
// and a mover driven by a "while" rule may not be driven by any other rule.
namespace game {

const char* interactableName(Interactable::Type type) {
  switch (type) {
    case Interactable::Type::Rotate:
      return "rotate";
    case Interactable::Type::Slide:
      return "slide";
    case Interactable::Type::Switch:
      return "switch";
  }
  return "";
}

}  // namespace game

namespace game::level_format {

namespace {

const std::vector<std::string> kConditionTypes{"focus",    "lit",   "seen",   "inside",
                                               "rotation", "slide", "switch", "timer",
                                               "fired",    "all",   "any",    "not"};
const std::vector<std::string> kActionTypes{
    "play", "reverse", "stop",   "goto",        "light_on", "light_off", "light_toggle", "show",
    "hide", "lock",    "unlock", "set_respawn", "message",  "win",       "lose"};
const std::vector<std::string> kModes{"once", "repeat", "while"};
constexpr std::size_t kMaxMessageCharacters = 200;

// Where the references a rule makes were written, for the whole-section checks.
struct RuleReferences {
  std::vector<std::pair<uint32_t, std::string>> fired;   // (rule, pointer of the id)
  std::vector<std::pair<uint32_t, std::string>> movers;  // (entity, pointer of the id)
};

std::string quoted(const std::string& text) {
  return "\"" + text + "\"";
}

// The entity at `pointer`, which must be an interactable of `type` (or of any type).
uint32_t readInteractableReference(const LevelReader& reader, const Level& level,
                                   const OrderedJson& value, const std::string& pointer,
                                   std::optional<Interactable::Type> type,
                                   const std::string& usedBy) {
  const uint32_t entity = reader.readReference(value, pointer, IdKind::Entity);
  const Entity& target = level.entities[entity];
  if (!target.interactable) {
    reader.failValue(pointer, "entity " + quoted(target.id) + " is not an interactable; " + usedBy +
                                  " needs an entity with an \"interactable\"");
  }
  if (type && target.interactable->type != *type) {
    reader.failValue(pointer, "entity " + quoted(target.id) + " is a " +
                                  interactableName(target.interactable->type) + " interactable; " +
                                  usedBy + " needs a " + interactableName(*type) + " interactable");
  }
  return entity;
}

Condition readCondition(const LevelReader& reader, const Level& level, const OrderedJson& json,
                        const std::string& pointer, int depth, RuleReferences& references) {
  const std::size_t type = reader.readType(json, pointer, kConditionTypes);
  const std::string what = "a " + kConditionTypes[type] + " condition";
  const std::string usedBy = "a " + quoted(kConditionTypes[type]) + " condition";
  Condition condition;
  condition.type = static_cast<Condition::Type>(type);
  switch (condition.type) {
    case Condition::Type::Focus:
      reader.checkKeys(json, pointer, {"type", "orb", "region", "coverage", "hold_seconds"},
                       {"orb"}, what);
      condition.entity =
          reader.readReference(json["orb"], childPointer(pointer, "orb"), IdKind::Entity);
      condition.region = reader.readOptionalRegion(json, pointer, condition.region);
      condition.coverage =
          reader.readOptionalNumber(json, "coverage", pointer, kUnitFraction, condition.coverage);
      break;
    case Condition::Type::Lit:
      reader.checkKeys(json, pointer,
                       {"type", "label", "sensor", "light", "threshold", "color", "hold_seconds"},
                       {"sensor", "light"}, what);
      condition.label = reader.readOptionalLabel(json, pointer);
      condition.entity =
          reader.readReference(json["sensor"], childPointer(pointer, "sensor"), IdKind::Entity);
      condition.light =
          reader.readReference(json["light"], childPointer(pointer, "light"), IdKind::Light);
      condition.threshold =
          reader.readOptionalNumber(json, "threshold", pointer, kUnitFraction, condition.threshold);
      condition.channel = reader.readSensorColor(json, pointer);
      break;
    case Condition::Type::Seen:
      reader.checkKeys(json, pointer, {"type", "label", "watcher", "threshold", "hold_seconds"},
                       {"watcher"}, what);
      condition.label = reader.readOptionalLabel(json, pointer);
      condition.light =
          reader.readReference(json["watcher"], childPointer(pointer, "watcher"), IdKind::Light);
      condition.threshold =
          reader.readOptionalNumber(json, "threshold", pointer, kUnitInterval, condition.threshold);
      break;
    case Condition::Type::Inside: {
      reader.checkKeys(json, pointer, {"type", "min", "max", "hold_seconds"}, {"min", "max"}, what);
      reader.readBox(json, pointer, condition.min, condition.max);
      break;
    }
    case Condition::Type::Rotation:
    case Condition::Type::Slide: {
      const bool rotation = condition.type == Condition::Type::Rotation;
      const char* low = rotation ? "min_degrees" : "min";
      const char* high = rotation ? "max_degrees" : "max";
      reader.checkKeys(json, pointer, {"type", "entity", low, high, "hold_seconds"},
                       {"entity", low, high}, what);
      condition.entity = readInteractableReference(
          reader, level, json["entity"], childPointer(pointer, "entity"),
          rotation ? Interactable::Type::Rotate : Interactable::Type::Slide, usedBy);
      std::tie(condition.low, condition.high) =
          reader.readOrderedPair(json, pointer, low, high, rotation ? kAnyNumber : kCoordinate);
      break;
    }
    case Condition::Type::Switch:
      reader.checkKeys(json, pointer, {"type", "entity", "on", "hold_seconds"}, {"entity"}, what);
      condition.entity =
          readInteractableReference(reader, level, json["entity"], childPointer(pointer, "entity"),
                                    Interactable::Type::Switch, usedBy);
      condition.on = reader.readOptionalBool(json, "on", pointer, true);
      break;
    case Condition::Type::Timer:
      reader.checkKeys(json, pointer, {"type", "seconds", "since", "hold_seconds"}, {"seconds"},
                       what);
      condition.seconds =
          reader.readNumber(json["seconds"], childPointer(pointer, "seconds"), kNonNegativeNumber);
      if (json.contains("since")) {
        condition.rule =
            reader.readReference(json["since"], childPointer(pointer, "since"), IdKind::Rule);
      }
      break;
    case Condition::Type::Fired: {
      reader.checkKeys(json, pointer, {"type", "rule", "hold_seconds"}, {"rule"}, what);
      const std::string rulePointer = childPointer(pointer, "rule");
      condition.rule = reader.readReference(json["rule"], rulePointer, IdKind::Rule);
      references.fired.emplace_back(*condition.rule, rulePointer);
      break;
    }
    case Condition::Type::All:
    case Condition::Type::Any:
    case Condition::Type::Not: {
      reader.checkKeys(json, pointer, {"type", "of", "hold_seconds"}, {"of"}, what);
      const OrderedJson& of = json["of"];
      const std::string ofPointer = childPointer(pointer, "of");
      if (depth >= kMaxGoalDepth) {
        reader.failValue(ofPointer, "conditions nest more than " + std::to_string(kMaxGoalDepth) +
                                        " deep, the limit");
      }
      if (condition.type == Condition::Type::Not) {
        if (!of.is_object()) reader.expected(of, ofPointer, "a condition (an object)");
        condition.children.push_back(
            readCondition(reader, level, of, ofPointer, depth + 1, references));
        break;
      }
      if (!of.is_array() || of.empty() || of.size() > kMaxGoalChildren) {
        reader.expected(of, ofPointer, "an array of 1 to 16 conditions");
      }
      for (std::size_t i = 0; i < of.size(); ++i) {
        condition.children.push_back(
            readCondition(reader, level, of[i], childPointer(ofPointer, i), depth + 1, references));
      }
      break;
    }
  }
  condition.holdSeconds =
      reader.readOptionalNumber(json, "hold_seconds", pointer, kNonNegativeNumber, 0.0f);
  return condition;
}

bool isMoverAction(Action::Type type) {
  return type == Action::Type::Play || type == Action::Type::Reverse ||
         type == Action::Type::Stop || type == Action::Type::Goto;
}

// What a "while" rule may do: actions with an opposite to undo them by (and a message).
bool undoable(Action::Type type) {
  switch (type) {
    case Action::Type::Stop:
    case Action::Type::Goto:
    case Action::Type::SetRespawn:
    case Action::Type::Win:
    case Action::Type::Lose:
      return false;
    default:
      return true;
  }
}

Action readAction(const LevelReader& reader, const Level& level, const OrderedJson& json,
                  const std::string& pointer, Rule::Mode mode, RuleReferences& references) {
  reader.requireObject(json, pointer);
  if (!json.contains("do")) reader.failMissing(pointer, "do");
  const std::string doPointer = childPointer(pointer, "do");
  const std::size_t type = reader.readChoice(json["do"], doPointer, kActionTypes);
  const std::string name = quoted(kActionTypes[type]);
  const std::string what = "a " + name + " action";
  Action action;
  action.type = static_cast<Action::Type>(type);
  if (mode == Rule::Mode::While && !undoable(action.type)) {
    reader.failValue(doPointer, "a \"while\" rule cannot " + name +
                                    ": its actions are undone when its condition stops holding; "
                                    "use \"fires\": \"once\" or \"repeat\"");
  }
  if (isMoverAction(action.type)) {
    if (action.type == Action::Type::Goto) {
      reader.checkKeys(json, pointer, {"do", "mover", "keyframe"}, {"mover", "keyframe"}, what);
    } else {
      reader.checkKeys(json, pointer, {"do", "mover"}, {"mover"}, what);
    }
    const std::string moverPointer = childPointer(pointer, "mover");
    action.entity = reader.readReference(json["mover"], moverPointer, IdKind::Entity);
    const Entity& entity = level.entities[action.entity];
    if (!entity.mover) {
      reader.failValue(moverPointer, "entity " + quoted(entity.id) + " has no mover; " + what +
                                         " needs an entity with a \"mover\"");
    }
    references.movers.emplace_back(action.entity, moverPointer);
    if (action.type == Action::Type::Goto) {
      const auto last = static_cast<int64_t>(entity.mover->keyframes.size() - 1);
      action.keyframe =
          reader.readCount(json["keyframe"], childPointer(pointer, "keyframe"), 0, last);
    }
    return action;
  }
  switch (action.type) {
    case Action::Type::LightOn:
    case Action::Type::LightOff:
    case Action::Type::LightToggle:
      reader.checkKeys(json, pointer, {"do", "light"}, {"light"}, what);
      action.light =
          reader.readReference(json["light"], childPointer(pointer, "light"), IdKind::Light);
      break;
    case Action::Type::Show:
    case Action::Type::Hide:
      reader.checkKeys(json, pointer, {"do", "entity"}, {"entity"}, what);
      action.entity =
          reader.readReference(json["entity"], childPointer(pointer, "entity"), IdKind::Entity);
      break;
    case Action::Type::Lock:
    case Action::Type::Unlock:
      reader.checkKeys(json, pointer, {"do", "entity"}, {"entity"}, what);
      action.entity = readInteractableReference(
          reader, level, json["entity"], childPointer(pointer, "entity"), std::nullopt, what);
      break;
    case Action::Type::SetRespawn:
      reader.checkKeys(json, pointer, {"do", "position", "yaw_degrees"}, {"position"}, what);
      action.position =
          reader.readVec3(json["position"], childPointer(pointer, "position"), kCoordinate);
      action.yawDegrees = reader.readOptionalNumber(json, "yaw_degrees", pointer, kAnyNumber,
                                                    level.camera.yawDegrees);
      break;
    case Action::Type::Message:
      reader.checkKeys(json, pointer, {"do", "text", "seconds"}, {"text"}, what);
      action.text =
          reader.readString(json["text"], childPointer(pointer, "text"), 1, kMaxMessageCharacters);
      action.seconds =
          reader.readOptionalNumber(json, "seconds", pointer, kPositiveNumber, action.seconds);
      break;
    case Action::Type::Win:
      reader.checkKeys(json, pointer, {"do"}, {}, what);
      break;
    case Action::Type::Lose:
      reader.checkKeys(json, pointer, {"do", "reason"}, {}, what);
      if (json.contains("reason")) {
        action.text = reader.readString(json["reason"], childPointer(pointer, "reason"), 1,
                                        kMaxMessageCharacters);
      }
      break;
    default:
      break;
  }
  return action;
}

// A rule whose condition waits, through `fired` conditions, for itself never fires.
void checkNoFiredCycle(const LevelReader& reader, const Level& level,
                       const std::vector<RuleReferences>& references) {
  enum class Mark { Unvisited, OnPath, Done };
  std::vector<Mark> marks(level.rules.size(), Mark::Unvisited);
  std::vector<uint32_t> path;
  std::function<void(uint32_t)> visit = [&](uint32_t rule) {
    marks[rule] = Mark::OnPath;
    path.push_back(rule);
    for (const auto& [other, pointer] : references[rule].fired) {
      if (marks[other] == Mark::OnPath) {
        std::string cycle;
        const auto start = std::find(path.begin(), path.end(), other);
        for (auto it = start; it != path.end(); ++it) cycle += quoted(level.rules[*it].id) + " -> ";
        cycle += quoted(level.rules[other].id);
        reader.failValue(pointer, "rule " + quoted(level.rules[rule].id) +
                                      " waits for itself through \"fired\" conditions (" + cycle +
                                      "), so it can never fire");
      }
      if (marks[other] == Mark::Unvisited) visit(other);
    }
    path.pop_back();
    marks[rule] = Mark::Done;
  };
  for (uint32_t rule = 0; rule < level.rules.size(); ++rule) {
    if (marks[rule] == Mark::Unvisited) visit(rule);
  }
}

// A "while" rule undoes what it did to its movers; another rule moving them would fight it.
void checkWhileMoversUnshared(const LevelReader& reader, const Level& level,
                              const std::vector<RuleReferences>& references) {
  std::map<uint32_t, uint32_t> firstRuleOfMover;
  for (uint32_t rule = 0; rule < level.rules.size(); ++rule) {
    for (const auto& [entity, pointer] : references[rule].movers) {
      const auto [found, inserted] = firstRuleOfMover.emplace(entity, rule);
      if (inserted || found->second == rule) continue;
      const Rule& first = level.rules[found->second];
      const Rule& second = level.rules[rule];
      if (first.mode != Rule::Mode::While && second.mode != Rule::Mode::While) continue;
      const Rule& whileRule = first.mode == Rule::Mode::While ? first : second;
      const Rule& other = &whileRule == &first ? second : first;
      reader.failValue(pointer, "mover " + quoted(level.entities[entity].id) +
                                    " is driven by the \"while\" rule " + quoted(whileRule.id) +
                                    " and by the rule " + quoted(other.id) +
                                    "; a mover a \"while\" rule drives may have no other rule");
    }
  }
}

}  // namespace

void readLogic(LevelReader& reader, const OrderedJson& logic, const std::string& pointer,
               Level& level) {
  std::vector<RuleReferences> references;
  reader.forEachEntry(
      logic, pointer,
      [&](const std::string& id, const OrderedJson& json, const std::string& rulePointer) {
        reader.checkKeys(json, rulePointer, {"when", "then", "fires"}, {"when", "then"});
        Rule rule;
        rule.id = id;
        rule.mode = static_cast<Rule::Mode>(
            reader.readOptionalChoice(json, "fires", rulePointer, kModes, 0));
        references.emplace_back();
        rule.condition = readCondition(reader, level, json["when"],
                                       childPointer(rulePointer, "when"), 1, references.back());
        const OrderedJson& then = json["then"];
        const std::string thenPointer = childPointer(rulePointer, "then");
        if (!then.is_array() || then.empty() || then.size() > kMaxActions) {
          reader.expected(then, thenPointer,
                          "an array of 1 to " + std::to_string(kMaxActions) + " actions");
        }
        for (std::size_t i = 0; i < then.size(); ++i) {
          rule.actions.push_back(readAction(reader, level, then[i], childPointer(thenPointer, i),
                                            rule.mode, references.back()));
        }
        level.rules.push_back(std::move(rule));
      });
  checkNoFiredCycle(reader, level, references);
  checkWhileMoversUnshared(reader, level, references);
}

}  // namespace game::level_format

namespace game {

const char* actionName(Action::Type type) {
  return level_format::kActionTypes[std::size_t(type)].c_str();
}

}  // namespace game
