#pragma once
// The player's body as the rays see it: a simple figure (a rounded trunk and a head) standing
// on the feet. It casts shadows and shows in mirrors; camera rays from the eye skip it. The
// stealth probe's sample points (game/probe_points.cpp) lie on this figure, so the exposure the
// rules read and the shadow on screen come from the same shape.
#include <glm/glm.hpp>

#include "scene/scene_desc.hpp"

namespace game {

struct PlayerBody {
  static constexpr float trunkRadius = 0.225f;
  static constexpr float trunkHeight = 1.45f;  // from the feet
  static constexpr float headRadius = 0.16f;
  static constexpr float headCentre = 1.6f;  // above the feet
  static constexpr float height = headCentre + headRadius;
};

// The figure with its feet at the origin.
scene::MeshData playerBodyMesh();
// Its material: dark cloth.
scene::MaterialDesc playerBodyMaterial();
// Object to world for feet at `feet`.
glm::mat4 playerBodyTransform(const glm::vec3& feet);

}  // namespace game
