#include "game/rules.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "game/world.hpp"

namespace game {

namespace {

uint32_t ticksFor(float seconds) {
  const double ticks = std::ceil(double(seconds) * 60.0 - 1e-4);
  return uint32_t(std::max(1.0, ticks));
}

}  // namespace

const char* outcomeName(Outcome outcome) {
  switch (outcome) {
    case Outcome::Playing:
      return "playing";
    case Outcome::Won:
      return "won";
    case Outcome::Lost:
      return "lost";
  }
  return "?";
}

Rules::Rules(const Level& level, const ProbeLayout& layout) {
  uint32_t focusCount = 0, exposureCount = 0;
  if (level.goal) addNode(*level.goal, level, focusCount, exposureCount);
  for (const LoseCondition& condition : level.lose) {
    Loss loss{condition, quotedLightId(level, condition.light)};
    if (condition.type == LoseCondition::Type::Stealth) {
      loss.probe = int32_t(exposureCount++);
      loss.needTicks = ticksFor(condition.seconds);
    }
    losses_.push_back(std::move(loss));
  }
  if (focusCount != layout.firstLogicFocus || exposureCount != layout.firstLogicExposure)
    throw std::invalid_argument("Rules: the probe layout does not match the level's goals");
  coverage_.assign(focusCount, 0.0f);
  exposure_.assign(exposureCount, 0.0f);
}

// Same depth-first order as probeLayout, so probe indices line up.
uint32_t Rules::addNode(const Goal& goal, const Level& level, uint32_t& focusCount,
                        uint32_t& exposureCount) {
  const uint32_t index = uint32_t(nodes_.size());
  nodes_.emplace_back();
  progress_.emplace_back();
  Node node;
  node.goal = goal;
  node.goal.children.clear();
  std::string label;
  switch (goal.type) {
    case Goal::Type::Focus:
      node.probe = int32_t(focusCount++);
      label = "Hold " + quotedEntityId(level, goal.entity) + " in view";
      progress_[index].orb = int32_t(goal.entity);
      break;
    case Goal::Type::Lit:
      node.probe = int32_t(exposureCount++);
      node.needTicks = ticksFor(goal.holdSeconds);
      label = "Light " + quotedEntityId(level, goal.entity) + " with " +
              quotedLightId(level, goal.light);
      break;
    case Goal::Type::Reach:
      label = "Reach the goal";
      break;
    case Goal::Type::All:
    case Goal::Type::Any:
      label = goal.type == Goal::Type::All
                  ? "All " + std::to_string(goal.children.size()) + " of these"
                  : "Any one of " + std::to_string(goal.children.size());
      for (const Goal& child : goal.children)
        node.children.push_back(addNode(child, level, focusCount, exposureCount));
      break;
  }
  nodes_[index] = std::move(node);
  progress_[index].label = goal.label.empty() ? std::move(label) : goal.label;
  return index;
}

// Evaluates every node once per tick (no short cut: focus and lit goals keep counting).
bool Rules::evaluate(uint32_t index, const glm::vec3& feet) {
  Node& node = nodes_[index];
  const Goal& goal = node.goal;
  float progress = 0.0f;
  bool met = false;
  switch (goal.type) {
    case Goal::Type::Focus: {
      const bool covered = coverage_[uint32_t(node.probe)] >= goal.coverage;
      node.score += (covered ? goal.risePerSecond : -goal.fallPerSecond) * TICK_SECONDS;
      node.score = std::clamp(node.score, 0.0, 1.0);
      if (node.score >= 1.0 - 1e-9) node.score = 1.0;
      progress = float(node.score);
      met = node.score == 1.0;
      break;
    }
    case Goal::Type::Lit:
      node.runTicks = exposure_[uint32_t(node.probe)] >= goal.threshold ? node.runTicks + 1 : 0;
      progress = std::min(1.0f, float(node.runTicks) / float(node.needTicks));
      met = node.runTicks >= node.needTicks;
      break;
    case Goal::Type::Reach: {
      met = Aabb{goal.min, goal.max}.contains(feet);
      // How much of the way from where the player first stood has been covered.
      const float distance = glm::distance(feet, glm::clamp(feet, goal.min, goal.max));
      if (node.startDistance < 0.0f) node.startDistance = distance;
      progress = met ? 1.0f
                 : node.startDistance > 0.0f
                     ? std::clamp(1.0f - distance / node.startDistance, 0.0f, 1.0f)
                     : 0.0f;
      break;
    }
    case Goal::Type::All:
    case Goal::Type::Any: {
      const bool all = goal.type == Goal::Type::All;
      met = all;
      float sum = 0.0f, best = 0.0f;
      for (uint32_t child : nodes_[index].children) {
        const bool childMet = evaluate(child, feet);
        met = all ? (met && childMet) : (met || childMet);
        sum += progress_[child].progress;
        best = std::max(best, progress_[child].progress);
      }
      const size_t count = nodes_[index].children.size();
      progress = all ? (count ? sum / float(count) : 1.0f) : best;
      break;
    }
  }
  progress_[index].progress = progress;
  progress_[index].met = met;
  return met;
}

void Rules::update(uint64_t tick, const World& world, const ProbeReadings* latest) {
  if (outcome_ != Outcome::Playing) return;
  if (latest) {
    std::copy_n(latest->focusCoverage.begin(),
                std::min(latest->focusCoverage.size(), coverage_.size()), coverage_.begin());
    std::copy_n(latest->exposure.begin(), std::min(latest->exposure.size(), exposure_.size()),
                exposure_.begin());
  }
  const glm::vec3 feet = world.feetPosition();

  std::string lostReason;
  for (Loss& loss : losses_) {
    bool triggered = false;
    std::string why;
    if (loss.condition.type == LoseCondition::Type::Stealth) {
      const bool seen = exposure_[uint32_t(loss.probe)] > loss.condition.exposureLimit;
      loss.runTicks = seen ? loss.runTicks + 1 : 0;
      triggered = loss.runTicks >= loss.needTicks;
      why = loss.condition.label.empty() ? "Seen by " + loss.watcher : loss.condition.label;
    } else {
      triggered = feet.y < loss.condition.below;
      why = loss.condition.label.empty() ? "Fell" : loss.condition.label;
    }
    if (triggered && lostReason.empty()) lostReason = why;  // the first in file order
  }
  const bool won = !nodes_.empty() && evaluate(0, feet);

  if (!lostReason.empty()) {
    outcome_ = Outcome::Lost;
    reason_ = lostReason;
  } else if (won) {
    outcome_ = Outcome::Won;
    reason_ = progress_[0].label + ": met";
  } else {
    return;
  }
  outcomeTick_ = tick;
}

void Rules::decide(Outcome outcome, uint64_t tick, const std::string& reason) {
  const bool decidedEarlier = outcome_ != Outcome::Playing && outcomeTick_ != tick;
  if (outcome == Outcome::Playing || decidedEarlier || outcome_ == Outcome::Lost) return;
  if (outcome_ == Outcome::Won && outcome != Outcome::Lost) return;
  outcome_ = outcome;
  outcomeTick_ = tick;
  reason_ = reason;
}

}  // namespace game
