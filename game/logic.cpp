#include "game/logic.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "game/world.hpp"

namespace game {

namespace {

// As the goals count hold times: ceil with a 1e-4 tolerance, so 0.1 s is 6 ticks.
uint32_t ticksFor(float seconds) {
  return uint32_t(std::max(0.0, std::ceil(double(seconds) * 60.0 - 1e-4)));
}

}  // namespace

Logic::Logic(const Level& level, const ProbeLayout& layout)
    : firstFocus_(layout.firstLogicFocus), firstExposure_(layout.firstLogicExposure) {
  uint32_t focus = 0, exposure = 0;
  for (const Rule& rule : level.rules) {
    RuleState state;
    state.rule = rule;
    state.root = addNode(rule.condition, focus, exposure);
    state.lightsBefore.assign(rule.actions.size(), 0);
    rules_.push_back(std::move(state));
  }
  if (firstFocus_ + focus != layout.focus.size() ||
      firstExposure_ + exposure != layout.exposure.size()) {
    throw std::invalid_argument("Logic: the probe layout does not match the level's rules");
  }
  for (const LoseCondition& lose : level.lose) {
    if (lose.type == LoseCondition::Type::Fall) fallHeights_.push_back(lose.below);
  }
  coverage_.assign(focus, 0.0f);
  exposure_.assign(exposure, 0.0f);
}

// Depth first, parents before children: the order probeLayout gives the logic's probes.
uint32_t Logic::addNode(const Condition& condition, uint32_t& focus, uint32_t& exposure) {
  const uint32_t index = uint32_t(nodes_.size());
  nodes_.emplace_back();
  Node node;
  node.condition = condition;
  node.condition.children.clear();
  node.needTicks = ticksFor(condition.holdSeconds);
  if (condition.type == Condition::Type::Focus) node.probe = int32_t(focus++);
  if (condition.type == Condition::Type::Lit || condition.type == Condition::Type::Seen) {
    node.probe = int32_t(exposure++);
  }
  for (const Condition& child : condition.children) {
    node.children.push_back(addNode(child, focus, exposure));
  }
  nodes_[index] = std::move(node);
  return index;
}

// Every node is evaluated on every tick (no short cut), so hold times keep counting.
bool Logic::evaluate(uint32_t index, uint64_t tick, const World& world) {
  const Condition& condition = nodes_[index].condition;
  bool now = false;
  switch (condition.type) {
    case Condition::Type::Focus:
      now = coverage_[uint32_t(nodes_[index].probe)] >= condition.coverage;
      break;
    case Condition::Type::Lit:
      now = exposure_[uint32_t(nodes_[index].probe)] >= condition.threshold;
      break;
    case Condition::Type::Seen:
      now = exposure_[uint32_t(nodes_[index].probe)] > condition.threshold;
      break;
    case Condition::Type::Inside: {
      const glm::vec3 feet = world.feetPosition();
      now = Aabb{condition.min, condition.max}.contains(feet);
      break;
    }
    case Condition::Type::Rotation:
    case Condition::Type::Slide: {
      const float value = world.interactableValue(condition.entity);
      now = value >= condition.low && value <= condition.high;
      break;
    }
    case Condition::Type::Switch:
      now = world.switchOn(condition.entity) == condition.on;
      break;
    case Condition::Type::Timer: {
      const uint64_t need = ticksFor(condition.seconds);
      if (!condition.rule) {
        now = tick >= need;
      } else {
        const std::vector<uint64_t>& fired = rules_[*condition.rule].firings;
        now = !fired.empty() && tick - fired.back() >= need;
      }
      break;
    }
    case Condition::Type::Fired:
      now = !rules_[*condition.rule].firings.empty();
      break;
    case Condition::Type::All:
    case Condition::Type::Any: {
      const bool all = condition.type == Condition::Type::All;
      now = all;
      for (const uint32_t child : nodes_[index].children) {
        const bool childCounts = evaluate(child, tick, world);
        now = all ? (now && childCounts) : (now || childCounts);
      }
      break;
    }
    case Condition::Type::Not:
      now = !evaluate(nodes_[index].children.front(), tick, world);
      break;
  }
  Node& node = nodes_[index];
  node.runTicks = now ? node.runTicks + 1 : 0;
  node.counts = now && node.runTicks >= std::max(1u, node.needTicks);
  return node.counts;
}

void Logic::apply(RuleState& state, uint64_t tick, World& world) {
  for (size_t i = 0; i < state.rule.actions.size(); ++i) {
    const Action& action = state.rule.actions[i];
    switch (action.type) {
      case Action::Type::Play:
        world.playMover(action.entity, 1);
        break;
      case Action::Type::Reverse:
        world.playMover(action.entity, -1);
        break;
      case Action::Type::Stop:
        world.playMover(action.entity, 0);
        break;
      case Action::Type::Goto:
        world.sendMoverToKeyframe(action.entity, action.keyframe);
        break;
      case Action::Type::LightOn:
      case Action::Type::LightOff:
      case Action::Type::LightToggle: {
        const bool before = world.lightEnabled(action.light);
        state.lightsBefore[i] = before ? 1 : 0;
        world.setLightEnabled(action.light, action.type == Action::Type::LightOn    ? true
                                            : action.type == Action::Type::LightOff ? false
                                                                                    : !before);
        break;
      }
      case Action::Type::Show:
      case Action::Type::Hide:
        world.setVisible(action.entity, action.type == Action::Type::Show);
        break;
      case Action::Type::Lock:
      case Action::Type::Unlock:
        world.setLocked(action.entity, action.type == Action::Type::Lock);
        break;
      case Action::Type::SetRespawn:
        respawn_ = action;
        break;
      case Action::Type::Message:
        message_ = action.text;
        messageUntil_ = tick + std::max<uint64_t>(1, ticksFor(action.seconds));
        break;
      case Action::Type::Win:
      case Action::Type::Lose: {
        const Outcome outcome = action.type == Action::Type::Win ? Outcome::Won : Outcome::Lost;
        if (outcome_ == Outcome::Lost || (outcome_ && outcome == Outcome::Won)) break;
        outcome_ = outcome;
        outcomeTick_ = tick;
        reason_ = !action.text.empty() ? action.text
                                       : "rule \"" + state.rule.id +
                                             "\": " + (outcome == Outcome::Won ? "win" : "lose");
        break;
      }
    }
  }
}

// In reverse order, so a "while" rule that switched the same light twice restores the first state.
void Logic::undo(RuleState& state, World& world) {
  for (size_t i = state.rule.actions.size(); i-- > 0;) {
    const Action& action = state.rule.actions[i];
    switch (action.type) {
      case Action::Type::Play:
        world.playMover(action.entity, -1);
        break;
      case Action::Type::Reverse:
        world.playMover(action.entity, 1);
        break;
      case Action::Type::LightOn:
      case Action::Type::LightOff:
      case Action::Type::LightToggle:
        world.setLightEnabled(action.light, state.lightsBefore[i] != 0);
        break;
      case Action::Type::Show:
      case Action::Type::Hide:
        world.setVisible(action.entity, action.type == Action::Type::Hide);
        break;
      case Action::Type::Lock:
      case Action::Type::Unlock:
        world.setLocked(action.entity, action.type == Action::Type::Unlock);
        break;
      default:  // the loader refuses the rest in "while" rules; a message just runs out
        break;
    }
  }
}

void Logic::update(uint64_t tick, World& world, const ProbeReadings* latest) {
  if (outcome_) return;
  if (latest) {
    for (size_t i = 0; i < coverage_.size(); ++i) {
      if (firstFocus_ + i < latest->focusCoverage.size())
        coverage_[i] = latest->focusCoverage[firstFocus_ + i];
    }
    for (size_t i = 0; i < exposure_.size(); ++i) {
      if (firstExposure_ + i < latest->exposure.size())
        exposure_[i] = latest->exposure[firstExposure_ + i];
    }
  }
  if (respawn_) {
    const float feetY = world.feetPosition().y;
    if (std::any_of(fallHeights_.begin(), fallHeights_.end(),
                    [&](float below) { return feetY < below; })) {
      world.respawnPlayer(respawn_->position, respawn_->yawDegrees);
    }
  }
  for (RuleState& state : rules_) {
    const bool counts = evaluate(state.root, tick, world);
    const bool started = counts && !state.holding;
    const bool stopped = !counts && state.holding;
    state.holding = counts;
    if (started && (state.rule.mode != Rule::Mode::Once || state.firings.empty())) {
      state.firings.push_back(tick);
      apply(state, tick, world);
    } else if (stopped && state.rule.mode == Rule::Mode::While) {
      undo(state, world);
    }
  }
}

std::optional<std::string> Logic::message(uint64_t tick) const {
  if (message_.empty() || tick >= messageUntil_) return std::nullopt;
  return message_;
}

}  // namespace game
