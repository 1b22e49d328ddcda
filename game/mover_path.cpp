#include "game/mover_path.hpp"

#include <algorithm>
#include <cmath>

namespace game {

double moverPathParameter(const Mover& mover, double seconds) {
  const double duration = mover.durationSeconds;
  if (!(duration > 0.0)) return 1.0;
  const double t = std::max(seconds, 0.0);
  switch (mover.repeat) {
    case Mover::Repeat::Once:
      return std::min(t / duration, 1.0);
    case Mover::Repeat::Loop:
      return std::fmod(t, duration) / duration;
    case Mover::Repeat::PingPong: {
      const double phase = std::fmod(t, 2.0 * duration) / duration;  // [0, 2)
      return phase <= 1.0 ? phase : 2.0 - phase;
    }
  }
  return 0.0;
}

double moverEasing(Mover::Easing easing, double u) {
  switch (easing) {
    case Mover::Easing::Linear:
      return u;
    case Mover::Easing::Smooth:
      return u * u * (3.0 - 2.0 * u);
    case Mover::Easing::EaseIn:
      return u * u;
    case Mover::Easing::EaseOut:
      return 1.0 - (1.0 - u) * (1.0 - u);
  }
  return u;
}

namespace {

// a·(1 − f) + b·f is exact at both ends, unlike a + (b − a)·f.
glm::vec3 blend(const glm::vec3& a, const glm::vec3& b, double f) {
  return glm::vec3(glm::dvec3(a) * (1.0 - f) + glm::dvec3(b) * f);
}

}  // namespace

MoverPose evaluateMover(const Mover& mover, double seconds) {
  const std::vector<Keyframe>& keys = mover.keyframes;
  if (keys.empty()) return {};
  if (keys.size() == 1) return {keys[0].position, keys[0].rotationDegrees};
  const double eased = moverEasing(mover.easing, moverPathParameter(mover, seconds));
  const double segments = double(keys.size() - 1);
  double along = std::clamp(eased, 0.0, 1.0) * segments;
  // Snap rounding noise so keyframe times give the keyframe exactly.
  if (std::abs(along - std::round(along)) < 1e-9) along = std::round(along);
  const size_t index = std::min(size_t(along), keys.size() - 2);
  const double f = along - double(index);
  return {blend(keys[index].position, keys[index + 1].position, f),
          blend(keys[index].rotationDegrees, keys[index + 1].rotationDegrees, f)};
}

glm::mat4 moverTransform(const Entity& entity, double seconds) {
  Entity posed = entity;
  if (entity.mover) {
    const MoverPose pose = evaluateMover(*entity.mover, seconds);
    posed.position = pose.position;
    posed.rotationDegrees = pose.rotationDegrees;
  }
  return entityTransform(posed);
}

}  // namespace game
