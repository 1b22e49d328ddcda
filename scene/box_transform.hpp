#pragma once
// The axis-aligned box around a box placed by a transform: its eight corners transformed. For
// any box type with glm::vec3 `min` and `max` members (the game's collision boxes, the
// renderer's hierarchy leaves).
#include <limits>

#include <glm/glm.hpp>

namespace scene {

template <typename Box>
Box transformBox(const Box& box, const glm::mat4& transform) {
  Box out = box;
  out.min = glm::vec3(std::numeric_limits<float>::max());
  out.max = glm::vec3(std::numeric_limits<float>::lowest());
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 local((corner & 1) ? box.max.x : box.min.x,
                          (corner & 2) ? box.max.y : box.min.y,
                          (corner & 4) ? box.max.z : box.min.z);
    const glm::vec3 placed = glm::vec3(transform * glm::vec4(local, 1.0f));
    out.min = glm::min(out.min, placed);
    out.max = glm::max(out.max, placed);
  }
  return out;
}

}  // namespace scene
