// Probes: the ray-gen shader counts focus-region pixels that reach an instance (directly,
// through glass, via mirrors), and the probe ray-gen measures exposure to a light in fixed
// point. Analytic expectations.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "game/primitives.hpp"
#include "render/gpu_types.hpp"
#include "render/vulkan_error.hpp"
#include "scene/probes.hpp"
#include "scene_builder.hpp"
#include "vulkan_fixture.hpp"

namespace {

using scene::MaterialDesc;
using scene::MaterialKind;
using test::at;
using test::glassMaterial;
using test::mirrorMaterial;
using test::SceneBuilder;

constexpr float kPi = 3.14159265358979f;

MaterialDesc grey() {
  return MaterialDesc{};
}

class ProbeTest : public test::VulkanTest {
 protected:
  static scene::ProbeCounts measure(const scene::SceneDesc& scene,
                                    const scene::ProbeRequest& request, uint32_t width,
                                    uint32_t height, uint32_t frameIndex = 0) {
    render::RendererOptions options;
    options.width = width;
    options.height = height;
    render::Renderer renderer(context(), compiler(), scene, options);
    renderer.setProbes(request);
    scene::FrameDesc frame;
    frame.frameIndex = frameIndex;
    renderer.renderFrame(frame, false);
    return renderer.probeCounts();
  }

  // A sphere of radius 0.5 straight ahead, 4 m away; the camera at the origin looks along -Z.
  static constexpr float kRadius = 0.5f, kDistance = 4.0f;
  static constexpr uint32_t kSegments = 96;
  static SceneBuilder sphereAhead(uint32_t& orb) {
    SceneBuilder builder;
    orb =
        builder.instance(builder.mesh(game::primitives::sphere(kRadius, kSegments, kSegments / 2)),
                         builder.material(grey()), at({0, 0, -kDistance}));
    return builder;
  }
};

// Pixels whose centre ray certainly hits the sphere, and those near its silhouette (within the
// pixel's angular radius, or the tessellation's inward error) that may go either way.
struct AnalyticCount {
  uint32_t certain = 0, uncertain = 0;
};

AnalyticCount analyticSphereCount(uint32_t width, uint32_t height, scene::PixelBox box,
                                  float radius, float distance, uint32_t segments) {
  const float tanHalf = std::tan(0.5f * glm::radians(60.0f));
  const float aspect = float(width) / float(height);
  const float silhouette = std::asin(radius / distance);
  const float tessellation = std::acos(std::cos(kPi / float(segments))) * radius / distance;
  const float pixelRadius = std::sqrt(2.0f) * tanHalf / float(height);  // at the centre, ample
  AnalyticCount count;
  for (uint32_t y = box.y0; y < box.y1; ++y) {
    for (uint32_t x = box.x0; x < box.x1; ++x) {
      const float ndcX = (float(x) + 0.5f) / float(width) * 2.0f - 1.0f;
      const float ndcY = (float(y) + 0.5f) / float(height) * 2.0f - 1.0f;
      const glm::vec3 direction =
          glm::normalize(glm::vec3(ndcX * tanHalf * aspect, -ndcY * tanHalf, -1.0f));
      const float angle = std::acos(std::clamp(-direction.z, -1.0f, 1.0f));
      if (angle < silhouette - pixelRadius - tessellation)
        ++count.certain;
      else if (angle < silhouette + pixelRadius)
        ++count.uncertain;
    }
  }
  return count;
}

TEST_F(ProbeTest, sphere_in_the_focus_region_gives_the_analytic_pixel_count) {
  uint32_t orb = 0;
  const SceneBuilder builder = sphereAhead(orb);
  for (const glm::vec2 region : {glm::vec2(1.0f, 1.0f), glm::vec2(0.1f, 0.1f)}) {
    const uint32_t width = 96, height = 64;
    const scene::ProbeCounts counts = measure(builder.scene, {{{orb, region}}, {}}, width, height);
    const scene::PixelBox box = scene::focusPixelBox(region, width, height);
    const AnalyticCount expected =
        analyticSphereCount(width, height, box, kRadius, kDistance, kSegments);
    EXPECT_EQ(counts.focusRegionPixels[0], box.pixels());
    EXPECT_GE(counts.focusPixels[0], expected.certain) << "region " << region.x;
    EXPECT_LE(counts.focusPixels[0], expected.certain + expected.uncertain)
        << "region " << region.x;
    EXPECT_GT(expected.certain, 0u);
  }
}

TEST_F(ProbeTest, focus_box_is_centred_and_rounded) {
  const scene::PixelBox box = scene::focusPixelBox({0.2f, 0.25f}, 320, 180);
  EXPECT_EQ(box.x0, 128u);
  EXPECT_EQ(box.x1, 192u);
  EXPECT_EQ(box.y0, 67u);  // 45 rows; the odd row goes to the bottom: 67 above, 68 below
  EXPECT_EQ(box.y1, 112u);
}

TEST_F(ProbeTest, occluded_orb_counts_zero_and_glass_in_front_changes_nothing) {
  uint32_t orb = 0;
  SceneBuilder blocked = sphereAhead(orb);
  blocked.instance(blocked.mesh(game::primitives::box({3, 3, 0.1f})), blocked.material(grey()),
                   at({0, 0, -2}));
  EXPECT_EQ(measure(blocked.scene, {{{orb, {1, 1}}}, {}}, 48, 32).focusPixels[0], 0u);

  SceneBuilder open = sphereAhead(orb);
  const uint32_t direct = measure(open.scene, {{{orb, {1, 1}}}, {}}, 48, 32).focusPixels[0];
  SceneBuilder glazed = sphereAhead(orb);
  glazed.instance(glazed.mesh(game::primitives::box({3, 3, 0.02f})),
                  glazed.material(glassMaterial({0.2f, 0.9f, 0.3f})), at({0, 0, -2}));
  EXPECT_GT(direct, 0u);
  EXPECT_EQ(measure(glazed.scene, {{{orb, {1, 1}}}, {}}, 48, 32).focusPixels[0], direct);
}

TEST_F(ProbeTest, orb_seen_only_in_a_mirror_counts) {
  // A mirror ahead turned 45 degrees about Y reflects the view towards +X, where the orb is;
  // the orb itself is outside the direct view.
  SceneBuilder builder;
  const glm::mat4 turned =
      glm::rotate(at({0, 0, -3}), glm::radians(45.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  builder.instance(builder.mesh(game::primitives::box({2.0f, 2.0f, 0.02f})),
                   builder.material(mirrorMaterial()), turned);
  const uint32_t orb = builder.instance(builder.mesh(game::primitives::sphere(0.4f, 32, 16)),
                                        builder.material(grey()), at({3, 0, -3}));
  const scene::ProbeCounts counts = measure(builder.scene, {{{orb, {0.3f, 0.3f}}}, {}}, 64, 48);
  EXPECT_GT(counts.focusPixels[0], 0u);
  // Without the mirror the orb is not in view.
  SceneBuilder bare;
  bare.instance(bare.mesh(game::primitives::box({0.1f, 0.1f, 0.1f})), bare.material(grey()),
                at({0, -50, 0}));
  const uint32_t bareOrb = bare.instance(bare.mesh(game::primitives::sphere(0.4f, 32, 16)),
                                         bare.material(grey()), at({3, 0, -3}));
  EXPECT_EQ(measure(bare.scene, {{{bareOrb, {0.3f, 0.3f}}}, {}}, 64, 48).focusPixels[0], 0u);
}

// 64 points on a horizontal sensor at y = 0 (an 8x8 grid over [-1, 1]^2), facing up.
scene::ExposureProbeDesc sensorGrid(uint32_t light) {
  scene::ExposureProbeDesc probe;
  probe.light = light;
  for (int j = 0; j < 8; ++j) {
    for (int i = 0; i < 8; ++i) {
      probe.points.push_back(
          {glm::vec3(-0.875f + 0.25f * float(i), 0.001f, -0.875f + 0.25f * float(j)),
           glm::vec3(0, 1, 0), true});
    }
  }
  return probe;
}

scene::SceneDesc sensorScene(scene::LightDesc light, bool blockHalf, bool glassAbove) {
  SceneBuilder builder;
  builder.instance(builder.mesh(game::primitives::box({2, 0.002f, 2})), builder.material(grey()),
                   at({0, -0.001f, 0}));
  if (blockHalf)  // covers x < 0 only, 1 m up
    builder.instance(builder.mesh(game::primitives::box({1.0f, 0.02f, 3.0f})),
                     builder.material(grey()), at({-0.5f, 1.0f, 0}));
  if (glassAbove)
    builder.instance(builder.mesh(game::primitives::box({4, 0.02f, 4})),
                     builder.material(glassMaterial({0.5f, 0.5f, 0.5f})), at({0, 1.5f, 0}));
  builder.light(light);
  builder.scene.exposureProbes = true;
  return builder.scene;
}

scene::LightDesc pointLightAbove() {
  scene::LightDesc light;
  light.type = scene::LightType::Point;
  light.position = {0, 3, 0};
  light.intensity = 10.0f;
  return light;
}

TEST_F(ProbeTest, exposure_is_exact_for_a_point_light_blocked_over_half_the_sensor) {
  EXPECT_EQ(measure(sensorScene(pointLightAbove(), false, false), {{}, {sensorGrid(0)}}, 8, 8)
                .exposureFixed[0],
            64u * scene::ProbeCounts::exposureOne);
  // The blocker's shadow from a light at x = 0 falls on x < 0 only, edge at 0: 32 of 64.
  const scene::ProbeCounts half =
      measure(sensorScene(pointLightAbove(), true, false), {{}, {sensorGrid(0)}}, 8, 8);
  EXPECT_EQ(half.exposureFixed[0], 32u * scene::ProbeCounts::exposureOne);
  EXPECT_FLOAT_EQ(half.exposure(0), 0.5f);
}

TEST_F(ProbeTest, switched_off_light_gives_zero_and_glass_gives_its_tint) {
  scene::LightDesc off = pointLightAbove();
  off.enabled = false;
  EXPECT_EQ(measure(sensorScene(off, false, false), {{}, {sensorGrid(0)}}, 8, 8).exposureFixed[0],
            0u);
  // Grey glass of transmittance 0.5 (luminance 0.5): 512 per point, rounded exactly.
  EXPECT_EQ(measure(sensorScene(pointLightAbove(), false, true), {{}, {sensorGrid(0)}}, 8, 8)
                .exposureFixed[0],
            64u * 512u);
}

TEST_F(ProbeTest, area_light_gives_a_partial_deterministic_exposure) {
  scene::LightDesc sphere = pointLightAbove();
  sphere.type = scene::LightType::Sphere;
  sphere.radius = 1.0f;
  const scene::SceneDesc scene = sensorScene(sphere, true, false);
  const scene::ProbeCounts first = measure(scene, {{}, {sensorGrid(0)}}, 8, 8, 7);
  const scene::ProbeCounts again = measure(scene, {{}, {sensorGrid(0)}}, 8, 8, 7);
  EXPECT_EQ(first.exposureFixed[0], again.exposureFixed[0]);
  // More than the hard shadow's half (penumbra points on the blocked side see part of the
  // sphere), less than all.
  EXPECT_GT(first.exposure(0), 0.5f);
  EXPECT_LT(first.exposure(0), 1.0f);
}

TEST_F(ProbeTest, exposure_probes_need_a_scene_that_asks_for_them) {
  scene::SceneDesc scene = sensorScene(pointLightAbove(), false, false);
  scene.exposureProbes = false;
  render::RendererOptions options;
  options.width = 8;
  options.height = 8;
  render::Renderer renderer(context(), compiler(), scene, options);
  EXPECT_THROW(renderer.setProbes({{}, {sensorGrid(0)}}), render::RenderError);
}

// "casts_shadow": "directional": a roof 1 m up blocks (or, as glass, tints) the sun but is not
// tested by the shadow rays towards a lamp, here one above it at y = 3 (in a level the lamps are
// inside the shell, where that changes nothing). The probes and the picture agree.
enum class Roof { None, Casts, DirectionalOnly, DirectionalOnlyGlass };

scene::SceneDesc roofScene(const scene::LightDesc& light, Roof roof) {
  scene::SceneDesc scene = sensorScene(light, false, false);
  SceneBuilder builder{scene};
  if (roof != Roof::None) {
    const MaterialDesc material =
        roof == Roof::DirectionalOnlyGlass ? glassMaterial({0.5f, 0.5f, 0.5f}) : grey();
    builder.instance(builder.mesh(game::primitives::box({4, 0.02f, 4})), builder.material(material),
                     at({0, 1.0f, 0}));
    builder.scene.instances.back().shadowsDirectionalOnly = roof != Roof::Casts;
  }
  return builder.scene;
}

scene::LightDesc sunAbove() {
  scene::LightDesc light;
  light.type = scene::LightType::Directional;
  light.direction = {0, -1, 0};
  light.intensity = 3.0f;
  return light;
}

TEST_F(ProbeTest, a_caster_of_directional_shadows_alone_blocks_the_sun_and_not_the_lamps) {
  EXPECT_EQ(render::gpu::instanceMask(false, true, false, true),
            MASK_VISIBLE | MASK_SHADOW_DIRECTIONAL);
  EXPECT_EQ(render::gpu::instanceMask(true, true, false, true),
            MASK_GLASS | MASK_GLASS_SHADOW_DIRECTIONAL);
  constexpr uint32_t kAll = 64u * scene::ProbeCounts::exposureOne;
  auto exposure = [&](const scene::LightDesc& light, Roof roof) {
    return measure(roofScene(light, roof), {{}, {sensorGrid(0)}}, 8, 8).exposureFixed[0];
  };
  EXPECT_EQ(exposure(sunAbove(), Roof::None), kAll);
  EXPECT_EQ(exposure(sunAbove(), Roof::DirectionalOnly), 0u);
  EXPECT_EQ(exposure(sunAbove(), Roof::DirectionalOnlyGlass), kAll / 2);
  EXPECT_EQ(exposure(pointLightAbove(), Roof::Casts), 0u);
  EXPECT_EQ(exposure(pointLightAbove(), Roof::DirectionalOnly), kAll);
  EXPECT_EQ(exposure(pointLightAbove(), Roof::DirectionalOnlyGlass), kAll);

  // The linear radiance at the centre of a view straight down from 0.5 m, under the roof.
  auto floorUnderRoof = [](const scene::SceneDesc& scene) {
    render::RendererOptions options;
    options.width = 8;
    options.height = 8;
    render::Renderer renderer(context(), compiler(), scene, options);
    scene::FrameDesc frame;
    frame.camera.position = {0.0f, 0.5f, 0.0f};
    frame.camera.pitchDegrees = -90.0f;
    renderer.renderFrame(frame, false);
    return renderer.readRadiance()[4 * 8 + 4];
  };

  // The picture: the sun as under a roof that casts every shadow, the lamp as under none.
  EXPECT_EQ(floorUnderRoof(roofScene(sunAbove(), Roof::DirectionalOnly)),
            floorUnderRoof(roofScene(sunAbove(), Roof::Casts)));
  EXPECT_LT(floorUnderRoof(roofScene(sunAbove(), Roof::DirectionalOnly)).g,
            floorUnderRoof(roofScene(sunAbove(), Roof::None)).g);
  EXPECT_EQ(floorUnderRoof(roofScene(pointLightAbove(), Roof::DirectionalOnly)),
            floorUnderRoof(roofScene(pointLightAbove(), Roof::None)));
}

}  // namespace
