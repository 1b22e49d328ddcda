#pragma once
// Where a mover is at a given time: keyframes evenly spaced over the duration, eased as a whole.
#include <glm/glm.hpp>

#include "game/level.hpp"

namespace game {

struct MoverPose {
  glm::vec3 position{0.0f};
  glm::vec3 rotationDegrees{0.0f};  // same convention as Entity::rotationDegrees
};

// The whole-path parameter u in [0, 1] before easing: Once clamps at the end, Loop wraps to the
// start, PingPong runs forth and back (period 2 × duration). Negative times count as 0.
double moverPathParameter(const Mover& mover, double seconds);

// Linear u, Smooth 3u² − 2u³, EaseIn u², EaseOut 1 − (1 − u)².
double moverEasing(Mover::Easing easing, double u);

// The pose at `seconds`; exactly the keyframe's values at its time.
MoverPose evaluateMover(const Mover& mover, double seconds);

// The entity's object-to-world transform with its pose replaced by the mover's (scale kept).
glm::mat4 moverTransform(const Entity& entity, double seconds);

}  // namespace game
