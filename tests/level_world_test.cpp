// Mover paths, the collision world, probe layouts and the World's tick: movers, switches,
// rotate and slide interactables.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "game/collision.hpp"
#include "game/level.hpp"
#include "game/mover_path.hpp"
#include "game/primitives.hpp"
#include "game/probes.hpp"
#include "game/world.hpp"

namespace {

using game::Mover;

Mover path(std::vector<glm::vec3> positions, Mover::Repeat repeat = Mover::Repeat::Once,
           Mover::Easing easing = Mover::Easing::Linear, float duration = 2.0f) {
  Mover mover;
  mover.durationSeconds = duration;
  mover.repeat = repeat;
  mover.easing = easing;
  for (const glm::vec3& p : positions) mover.keyframes.push_back({p, p * 10.0f});
  return mover;
}

TEST(Mover, KeyframesAreExactAtTheirTimes) {
  const Mover mover =
      path({{0.1f, 0.2f, 0.3f}, {1.7f, -2.3f, 0.9f}, {5.5f, 0.25f, -3.1f}, {-1.3f, 4.4f, 2.2f}},
           Mover::Repeat::Once, Mover::Easing::Linear, 3.0f);
  for (size_t k = 0; k < mover.keyframes.size(); ++k) {
    const game::MoverPose pose = game::evaluateMover(mover, double(k));  // 1 s apart
    EXPECT_EQ(pose.position, mover.keyframes[k].position) << k;
    EXPECT_EQ(pose.rotationDegrees, mover.keyframes[k].rotationDegrees) << k;
  }
  // Halfway between the second and third keyframe, component-wise.
  const game::MoverPose mid = game::evaluateMover(mover, 1.5);
  EXPECT_NEAR(mid.position.x, 0.5f * (1.7f + 5.5f), 1e-6f);
  EXPECT_NEAR(mid.rotationDegrees.z, 0.5f * (9.0f - 31.0f), 1e-5f);
}

TEST(Mover, EasingMidpoints) {
  EXPECT_DOUBLE_EQ(game::moverEasing(Mover::Easing::Linear, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(game::moverEasing(Mover::Easing::Smooth, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(game::moverEasing(Mover::Easing::EaseIn, 0.5), 0.25);
  EXPECT_DOUBLE_EQ(game::moverEasing(Mover::Easing::EaseOut, 0.5), 0.75);
  EXPECT_DOUBLE_EQ(game::moverEasing(Mover::Easing::Smooth, 0.25), 0.15625);
  for (const auto easing : {Mover::Easing::Linear, Mover::Easing::Smooth, Mover::Easing::EaseIn,
                            Mover::Easing::EaseOut}) {
    EXPECT_EQ(game::moverEasing(easing, 0.0), 0.0);
    EXPECT_EQ(game::moverEasing(easing, 1.0), 1.0);
  }
  // Easing applies to the whole path: EaseIn at half time is a quarter of the way.
  const Mover mover =
      path({{0, 0, 0}, {4, 0, 0}, {8, 0, 0}}, Mover::Repeat::Once, Mover::Easing::EaseIn, 2.0f);
  EXPECT_FLOAT_EQ(game::evaluateMover(mover, 1.0).position.x, 2.0f);
}

TEST(Mover, OnceClampsLoopWrapsPingPongReturns) {
  const glm::vec3 a(1, 2, 3), b(5, 2, -1);
  const Mover once = path({a, b}, Mover::Repeat::Once);
  EXPECT_EQ(game::evaluateMover(once, 2.0).position, b);
  EXPECT_EQ(game::evaluateMover(once, 7.5).position, b);
  EXPECT_EQ(game::evaluateMover(once, -1.0).position, a);

  const Mover loop = path({a, b}, Mover::Repeat::Loop);
  EXPECT_EQ(game::evaluateMover(loop, 2.0).position, a);  // wrapped
  EXPECT_NEAR(game::evaluateMover(loop, 2.5).position.x, 2.0f, 1e-6f);
  EXPECT_NEAR(game::evaluateMover(loop, 1.999).position.x, 5.0f, 1e-2f);

  const Mover pingPong = path({a, b}, Mover::Repeat::PingPong);
  EXPECT_EQ(game::evaluateMover(pingPong, 2.0).position, b);
  EXPECT_EQ(game::evaluateMover(pingPong, 4.0).position, a);
  EXPECT_NEAR(game::evaluateMover(pingPong, 3.0).position.x, 3.0f, 1e-6f);  // coming back
  EXPECT_NEAR(game::evaluateMover(pingPong, 5.0).position.x, 3.0f, 1e-6f);  // going again
}

TEST(Mover, TransformKeepsScaleAndUsesThePose) {
  game::Entity entity;
  entity.scale = glm::vec3(2.0f);
  entity.mover = path({{0, 0, 0}, {0, 0, 0}});
  entity.mover->keyframes[1].rotationDegrees = {0, 90, 0};
  const glm::mat4 m = game::moverTransform(entity, 2.0);
  const glm::vec3 x = glm::vec3(m * glm::vec4(1, 0, 0, 0));
  EXPECT_NEAR(x.x, 0.0f, 1e-5f);
  EXPECT_NEAR(x.z, -2.0f, 1e-5f);  // yaw 90 turns +X towards −Z, scaled by 2
}

// Levels built in code: boxes by size and centre.
struct LevelBuilder {
  game::Level level;
  LevelBuilder() { level.camera.position = {0.0f, 1.65f, 0.0f}; }
  uint32_t box(const glm::vec3& size, const glm::vec3& centre) {
    level.meshes.push_back(game::primitives::box(size));
    game::Entity entity;
    entity.id = "e" + std::to_string(level.entities.size());
    entity.mesh = uint32_t(level.meshes.size() - 1);
    entity.position = centre;
    level.entities.push_back(entity);
    return uint32_t(level.entities.size() - 1);
  }
  uint32_t floor() { return box({40.0f, 0.1f, 40.0f}, {0.0f, -0.05f, 0.0f}); }
  uint32_t light(bool enabled) {
    scene::LightDesc light;
    light.enabled = enabled;
    level.lights.push_back(light);
    level.lightIds.push_back("l" + std::to_string(level.lights.size() - 1));
    return uint32_t(level.lights.size() - 1);
  }
};

TEST(WorldCollision, RayCastFindsTheNearestTriangle) {
  LevelBuilder b;
  b.box({1, 1, 1}, {0, 0, -5});
  const uint32_t near = b.box({1, 1, 1}, {0, 0, -3});
  b.level.entities[near].scale = {2.0f, 2.0f, 2.0f};  // front face at z = -2
  const game::CollisionWorld world(b.level);
  const auto hit = world.rayCast({0.1f, 0.2f, 0.0f}, {0, 0, -2}, 10.0f);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->entity, near);
  EXPECT_NEAR(hit->distance, 2.0f, 1e-5f);
  EXPECT_NEAR(hit->point.z, -2.0f, 1e-5f);
  EXPECT_NEAR(hit->normal.z, 1.0f, 1e-5f);
  EXPECT_FALSE(world.rayCast({0.1f, 0.2f, 0.0f}, {0, 0, -1}, 1.9f));
  EXPECT_FALSE(world.rayCast({0.1f, 0.2f, 0.0f}, {0, 0, 1}, 100.0f));
}

TEST(WorldCollision, ClosestSegmentTriangle) {
  const glm::vec3 a(0, 0, 0), b(2, 0, 0), c(0, 0, 2);
  // Above the face: straight down.
  auto [s, t] = game::closestSegmentTriangle({0.5f, 1, 0.5f}, {0.5f, 3, 0.5f}, a, b, c);
  EXPECT_EQ(s, glm::vec3(0.5f, 1, 0.5f));
  EXPECT_EQ(t, glm::vec3(0.5f, 0, 0.5f));
  // Beside the hypotenuse, level with it: edge against segment.
  std::tie(s, t) = game::closestSegmentTriangle({2, -1, 2}, {2, 1, 2}, a, b, c);
  EXPECT_NEAR(glm::length(s - t), std::sqrt(2.0f), 1e-5f);
  EXPECT_NEAR(t.x, 1.0f, 1e-5f);
  // Piercing the face: distance 0 at the crossing.
  std::tie(s, t) = game::closestSegmentTriangle({0.5f, -1, 0.5f}, {0.5f, 1, 0.5f}, a, b, c);
  EXPECT_EQ(s, t);
}

TEST(WorldCollision, BigMeshQueriesMatchABruteForceScan) {
  // A 100 × 100 grid of tiny boxes' worth of triangles in one mesh (a stand-in for a glTF).
  scene::MeshData mesh;
  for (int i = 0; i < 60; ++i) {
    for (int j = 0; j < 60; ++j) {
      const uint32_t base = uint32_t(mesh.vertices.size());
      const float y = 0.05f * float((i * 7 + j * 3) % 5);
      for (const glm::vec3 p : {glm::vec3(i, y, j), glm::vec3(i + 1, y, j),
                                glm::vec3(i + 1, y, j + 1), glm::vec3(i, y, j + 1)})
        mesh.vertices.push_back({p});
      mesh.indices.insert(mesh.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
    }
  }
  const game::TriangleCollider collider(mesh);
  ASSERT_EQ(collider.triangleCount(), 7200u);
  const game::Aabb query{{10.2f, -1.0f, 20.7f}, {12.1f, 1.0f, 21.2f}};
  size_t visited = 0, overlapping = 0;
  collider.forEachOverlapping(query, [&](uint32_t) { ++visited; });
  for (size_t i = 0; i < collider.triangleCount(); ++i) {
    const glm::vec3* t = collider.triangle(i);
    const game::Aabb box{glm::min(t[0], glm::min(t[1], t[2])),
                         glm::max(t[0], glm::max(t[1], t[2]))};
    overlapping += box.overlaps(query) ? 1 : 0;
  }
  EXPECT_GE(visited, overlapping);
  EXPECT_LT(visited, 100u);  // culled, not scanned
  const auto hit = collider.rayCast({30.5f, 5.0f, 30.5f}, {0, -1, 0}, 10.0f);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->first, 5.0f - 0.05f * float((30 * 7 + 30 * 3) % 5), 1e-5f);
}

TEST(WorldProbes, LayoutIsDepthFirstThenStealth) {
  game::Level level;
  game::Goal focusA{game::Goal::Type::Focus};
  focusA.entity = 3;
  focusA.region = {0.3f, 0.4f};
  game::Goal litA{game::Goal::Type::Lit};
  litA.entity = 1;
  litA.light = 2;
  game::Goal focusB = focusA;
  focusB.entity = 5;
  game::Goal litB = litA;
  litB.entity = 4;
  game::Goal any{game::Goal::Type::Any};
  any.children = {litB, focusB, game::Goal{game::Goal::Type::Reach}};
  game::Goal all{game::Goal::Type::All};
  all.children = {focusA, litA, any};
  level.goal = all;
  game::LoseCondition fall;
  game::LoseCondition stealth{game::LoseCondition::Type::Stealth};
  stealth.light = 7;
  level.lose = {fall, stealth};
  const game::ProbeLayout layout = game::probeLayout(level);
  ASSERT_EQ(layout.focus.size(), 2u);
  EXPECT_EQ(layout.focus[0].entity, 3u);
  EXPECT_EQ(layout.focus[0].region, glm::vec2(0.3f, 0.4f));
  EXPECT_EQ(layout.focus[1].entity, 5u);
  ASSERT_EQ(layout.exposure.size(), 3u);
  EXPECT_EQ(layout.exposure[0].entity, 1u);
  EXPECT_EQ(layout.exposure[0].light, 2u);
  EXPECT_EQ(layout.exposure[1].entity, 4u);
  EXPECT_EQ(layout.exposure[1].target, game::ExposureProbe::Target::Entity);
  EXPECT_EQ(layout.exposure[2].target, game::ExposureProbe::Target::Player);
  EXPECT_EQ(layout.exposure[2].light, 7u);
  EXPECT_TRUE(game::probeLayout(game::Level{}).focus.empty());
}

game::PlayerInput interact(float adjust = 0.0f) {
  game::PlayerInput input;
  input.interact = true;
  input.adjust = adjust;
  return input;
}

TEST(World, SwitchTogglesItsLightThroughTheCrosshair) {
  LevelBuilder b;
  b.floor();
  const uint32_t light = b.light(true);
  b.light(true);
  const uint32_t lever = b.box({0.4f, 0.4f, 0.4f}, {0.0f, 1.65f, -2.0f});
  game::Interactable sw{game::Interactable::Type::Switch};
  sw.light = light;
  sw.startsOn = false;
  b.level.entities[lever].interactable = sw;
  game::World world(b.level);
  EXPECT_FALSE(world.lightEnabled(light));  // starts_on wins over the light's own flag
  EXPECT_TRUE(world.lightEnabled(1));
  EXPECT_EQ(world.pickedEntity(), lever);
  world.step(interact());
  EXPECT_TRUE(world.lightEnabled(light));
  world.step(interact());  // still held: no second toggle
  EXPECT_TRUE(world.lightEnabled(light));
  world.step({});
  world.step(interact());
  EXPECT_FALSE(world.lightEnabled(light));
  EXPECT_TRUE(world.lightEnabled(1));
  EXPECT_FALSE(world.lights()[light].enabled);

  // Looking away: nothing picked, pressing does nothing.
  game::PlayerInput away;
  away.yawDeltaDegrees = 90.0f;
  world.step(away);
  EXPECT_FALSE(world.pickedEntity());
  world.step(interact());
  EXPECT_FALSE(world.lightEnabled(light));
}

TEST(World, SwitchOutOfReachIsNotPicked) {
  LevelBuilder b;
  b.floor();
  b.light(true);
  const uint32_t lever = b.box({0.4f, 0.4f, 0.4f}, {0.0f, 1.65f, -3.5f});  // face at 3.3 m
  b.level.entities[lever].interactable = game::Interactable{game::Interactable::Type::Switch};
  game::World world(b.level);
  world.step(interact());
  EXPECT_FALSE(world.pickedEntity());
  EXPECT_TRUE(world.lightEnabled(0));
}

TEST(World, RotateFollowsAdjustAndClampsToItsLimits) {
  LevelBuilder b;
  b.floor();
  const glm::vec3 at(0.0f, 1.65f, -2.0f);
  const uint32_t dial = b.box({1.0f, 0.4f, 0.4f}, at);
  game::Interactable rotate{game::Interactable::Type::Rotate};
  rotate.axis = {0, 0, 1};
  rotate.min = -45.0f;
  rotate.max = 30.0f;
  rotate.start = 10.0f;
  b.level.entities[dial].interactable = rotate;
  game::World world(b.level);
  EXPECT_EQ(world.interactableValue(dial), 10.0f);
  for (int i = 0; i < 6; ++i) world.step(interact(1.0f));  // 90°/s × 0.1 s
  EXPECT_NEAR(world.interactableValue(dial), 19.0f, 1e-4f);
  EXPECT_EQ(world.heldEntity(), dial);
  for (int i = 0; i < 60; ++i) world.step(interact(1.0f));
  EXPECT_EQ(world.interactableValue(dial), 30.0f);
  for (int i = 0; i < 120; ++i) world.step(interact(-1.0f));
  EXPECT_EQ(world.interactableValue(dial), -45.0f);
  world.step({});
  EXPECT_FALSE(world.heldEntity());
  world.step(game::PlayerInput{.adjust = 1.0f});  // not held: adjust does nothing
  EXPECT_EQ(world.interactableValue(dial), -45.0f);

  // About the axis through the entity's position.
  const glm::mat4 expected = glm::translate(glm::mat4(1.0f), at) *
                             glm::rotate(glm::mat4(1.0f), glm::radians(-45.0f), glm::vec3(0, 0, 1));
  const glm::mat4& got = world.entityTransform(dial);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(got[c][r], expected[c][r], 1e-5f) << c << r;
}

TEST(World, SlideMovesAlongItsAxisAndListsTheChange) {
  LevelBuilder b;
  b.floor();
  const glm::vec3 at(0.0f, 1.65f, -2.0f);
  const uint32_t slider = b.box({0.4f, 0.4f, 0.4f}, at);
  game::Interactable slide{game::Interactable::Type::Slide};
  slide.axis = {1, 0, 0};
  slide.min = -1.0f;
  slide.max = 0.5f;
  b.level.entities[slider].interactable = slide;
  game::World world(b.level);
  for (int i = 0; i < 15; ++i) world.step(interact(1.0f));  // 1 m/s × 0.25 s
  EXPECT_NEAR(world.interactableValue(slider), 0.25f, 1e-5f);
  EXPECT_EQ(world.changedEntities(), std::vector<uint32_t>{slider});
  EXPECT_NEAR(world.entityTransform(slider)[3].x, 0.25f, 1e-5f);
  // Held even as it slides out from under the crosshair, up to its limit.
  for (int i = 0; i < 60; ++i) world.step(interact(1.0f));
  EXPECT_EQ(world.interactableValue(slider), 0.5f);
  EXPECT_TRUE(world.changedEntities().empty());  // at the limit: no change
  EXPECT_EQ(world.entityTransform(slider)[3].x, 0.5f);
  world.step({});
  world.step(interact(-1.0f));  // crosshair now misses it (0.3 m to the side): not picked
  EXPECT_EQ(world.interactableValue(slider), 0.5f);
}

TEST(World, ChangedEntitiesListsMoversAndTicksAdvance) {
  LevelBuilder b;
  const uint32_t floor = b.floor();
  const uint32_t lift = b.box({1, 1, 1}, {5, 0, 0});
  b.level.entities[lift].mover = path({{5, 0, 0}, {5, 2, 0}}, Mover::Repeat::PingPong);
  for (game::Keyframe& key : b.level.entities[lift].mover->keyframes) key.rotationDegrees = {};
  const uint32_t parked = b.box({1, 1, 1}, {-5, 0, 0});
  b.level.entities[parked].mover = path({{-5, 0, 0}, {-5, 0, 0}});  // never moves
  game::World world(b.level);
  EXPECT_EQ(world.tick(), 0u);
  EXPECT_EQ(world.changedEntities(), (std::vector<uint32_t>{lift, parked}));
  world.step({});
  EXPECT_EQ(world.tick(), 1u);
  EXPECT_EQ(world.changedEntities(), std::vector<uint32_t>{lift});
  EXPECT_NEAR(world.entityTransform(lift)[3].y, 2.0f / 120.0f, 1e-6f);
  for (int i = 1; i < 120; ++i) world.step({});
  EXPECT_EQ(world.entityTransform(lift)[3].y, 2.0f);  // t = 2 s: the far end
  for (int i = 0; i < 120; ++i) world.step({});
  EXPECT_EQ(world.entityTransform(lift)[3].y, 0.0f);  // t = 4 s: back
  EXPECT_EQ(world.entityTransform(floor), game::entityTransform(b.level.entities[floor]));
  // The collision world moved too: a ray down onto the lift hits its top.
  const auto hit = world.collision().rayCast({5, 10, 0}, {0, -1, 0}, 20.0f);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.y, 0.5f, 1e-5f);
}

TEST(World, CameraIsTheEyeWithTheLevelsFieldOfView) {
  LevelBuilder b;
  b.floor();
  b.level.camera.verticalFovDegrees = 72.0f;
  b.level.camera.yawDegrees = 30.0f;
  b.level.camera.pitchDegrees = -10.0f;
  game::World world(b.level);
  world.step({});
  const scene::CameraDesc camera = world.camera();
  EXPECT_EQ(camera.verticalFovDegrees, 72.0f);
  EXPECT_EQ(camera.yawDegrees, 30.0f);
  EXPECT_EQ(camera.pitchDegrees, -10.0f);
  EXPECT_NEAR(camera.position.y, 1.65f, 1e-4f);
  EXPECT_EQ(camera.position, world.eyePosition());
  EXPECT_NEAR(world.feetPosition().y, 0.0f, 1e-4f);
}

TEST(World, SameInputsGiveBitIdenticalStates) {
  LevelBuilder b;
  b.floor();
  b.box({1, 0.3f, 1}, {0.5f, 0.15f, -2});
  const uint32_t lift = b.box({2, 0.2f, 2}, {-3, 0, 0});
  b.level.entities[lift].mover =
      path({{-3, 0, 0}, {-3, 1, -2}}, Mover::Repeat::PingPong, Mover::Easing::Smooth);
  game::World first(b.level), second(b.level);
  for (int i = 0; i < 300; ++i) {
    game::PlayerInput input;
    input.move = {std::sin(float(i) * 0.1f), 1.0f};
    input.yawDeltaDegrees = float(i % 7) - 3.0f;
    input.jump = i % 50 == 0;
    first.step(input);
    second.step(input);
  }
  EXPECT_EQ(first.feetPosition(), second.feetPosition());
  EXPECT_EQ(first.yawDegrees(), second.yawDegrees());
}

}  // namespace
