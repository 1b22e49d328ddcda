// Glass (any-hit transmittance) and mirrors (bounces in ray-gen), with analytic answers.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "game/player_body.hpp"
#include "game/primitives.hpp"
#include "render/pipeline_variant.hpp"
#include "scene/color.hpp"
#include "scene_builder.hpp"
#include "vulkan_fixture.hpp"

namespace {

using scene::MaterialDesc;
using scene::MaterialKind;
using test::channel;

using test::at;
using test::glassMaterial;
using test::mirrorMaterial;
using test::SceneBuilder;

MaterialDesc emissive(const glm::vec3& radiance) {
  MaterialDesc material;
  material.baseColor = glm::vec3(0.0f);
  material.emissive = radiance;
  return material;
}

int expectedByte(double linear) {
  return int(std::lround(255.0 * scene::linearToSrgb(float(std::clamp(linear, 0.0, 1.0)))));
}

class GlassMirrorTest : public test::VulkanTest {
 protected:
  struct Frame {
    render::Rgba8Image image;
    std::vector<render::gpu::PixelPath> paths;
    render::PipelineDescription pipeline;
  };

  // Camera at the origin looking along -Z unless given; identity tonemap.
  static Frame render(const scene::SceneDesc& scene, uint32_t width, uint32_t height,
                      scene::CameraDesc camera = {}) {
    render::RendererOptions options;
    options.width = width;
    options.height = height;
    render::Renderer renderer(context(), compiler(), scene, options);
    scene::FrameDesc frame;
    frame.camera = camera;
    frame.tonemap = scene::Tonemap::Identity;
    renderer.renderFrame(frame);
    return {
        {width, height, renderer.pixels()}, renderer.pixelPaths(), renderer.pipelineDescription()};
  }

  // A 15x15 picture, for a renderer kept across changes to its scene.
  static render::RendererOptions smallView() {
    render::RendererOptions options;
    options.width = 15;
    options.height = 15;
    return options;
  }

  // Renders a frame of a smallView() renderer (identity tonemap) and returns its centre pixel.
  static glm::ivec3 centreAfterFrame(render::Renderer& renderer) {
    scene::FrameDesc frame;
    frame.tonemap = scene::Tonemap::Identity;
    renderer.renderFrame(frame);
    const render::Rgba8Image image{15, 15, renderer.pixels()};
    return glm::ivec3(channel(image, 7, 7, 0), channel(image, 7, 7, 1), channel(image, 7, 7, 2));
  }

  // A white emissive wall 2 m ahead filling the view.
  static SceneBuilder wallScene() {
    SceneBuilder builder;
    builder.instance(builder.mesh(game::primitives::box({20, 20, 0.1f})),
                     builder.material(emissive(glm::vec3(1.0f))), at({0, 0, -2}));
    return builder;
  }
};

TEST_F(GlassMirrorTest, glass_pane_in_front_of_white_emitter_shows_its_tint) {
  const glm::vec3 tint(0.2f, 0.5f, 0.8f);
  SceneBuilder builder = wallScene();
  builder.instance(builder.mesh(game::primitives::box({4, 4, 0.02f})),
                   builder.material(glassMaterial(tint)), at({0, 0, -1}));
  const Frame frame = render(builder.scene, 15, 15);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(channel(frame.image, 7, 7, c), expectedByte(tint[c]), 1);
  EXPECT_EQ(frame.pipeline.hitGroups, (std::vector<std::string>{"surface.rchit", "glass.rahit"}));
}

TEST_F(GlassMirrorTest, glass_follows_its_instance_moved_or_hidden_and_opaque_instances_do_not) {
  // Glass rays trace a structure of their own (the glass instances alone): moving the pane off
  // the view, hiding it, and moving the opaque wall must all reach what they see.
  const glm::vec3 tint(0.2f, 0.5f, 0.8f);
  SceneBuilder builder = wallScene();
  builder.instance(builder.mesh(game::primitives::box({4, 4, 0.02f})),
                   builder.material(glassMaterial(tint)), at({0, 0, -1}));
  render::Renderer renderer(context(), compiler(), builder.scene, smallView());
  auto centre = [&]() { return centreAfterFrame(renderer); };
  const glm::ivec3 tinted(expectedByte(tint.r), expectedByte(tint.g), expectedByte(tint.b));
  const glm::ivec3 white(255);
  EXPECT_EQ(centre(), tinted);
  std::vector<glm::mat4> transforms = {at({0, 0, -2}), at({30, 0, -1})};  // the pane aside
  renderer.setInstanceTransforms(transforms);
  EXPECT_EQ(centre(), white);
  transforms[1] = at({0, 0, -1});  // back in front
  renderer.setInstanceTransforms(transforms);
  EXPECT_EQ(centre(), tinted);
  renderer.setInstanceVisible(1, false);
  EXPECT_EQ(centre(), white);
  renderer.setInstanceVisible(1, true);
  EXPECT_EQ(centre(), tinted);
  transforms[0] = at({0, 0, -0.5f});  // the wall in front of the pane: no tint
  renderer.setInstanceTransforms(transforms);
  EXPECT_EQ(centre(), white);
}

TEST_F(GlassMirrorTest, the_eye_sees_past_the_players_body_and_follows_instances_moved_or_hidden) {
  // Camera rays trace a structure without the player's body (the eye is inside the body's box):
  // it must show what the scene's does, an instance moved or hidden too, and a mirror ahead
  // must still show the body. The body comes first, so the structure's entries are not the
  // scene's instance numbers.
  SceneBuilder builder;
  const uint32_t body = builder.instance(builder.mesh(game::playerBodyMesh()),
                                         builder.material(game::playerBodyMaterial()),
                                         game::playerBodyTransform({0, -1.65f, 0}));
  builder.scene.instances[body].playerBody = true;
  builder.instance(builder.mesh(game::primitives::box({20, 20, 0.1f})),
                   builder.material(emissive(glm::vec3(1.0f))), at({0, 0, -2}));
  const uint32_t panel =
      builder.instance(builder.mesh(game::primitives::box({4, 4, 0.02f})),
                       builder.material(emissive(glm::vec3(1.0f, 0.0f, 0.0f))), at({0, 0, -1}));
  render::Renderer renderer(context(), compiler(), builder.scene, smallView());
  auto centre = [&]() { return centreAfterFrame(renderer); };
  const glm::ivec3 red(255, 0, 0), white(255);
  EXPECT_EQ(centre(), red);
  std::vector<glm::mat4> transforms = {game::playerBodyTransform({0, -1.65f, 0}), at({0, 0, -2}),
                                       at({30, 0, -1})};  // the panel aside
  renderer.setInstanceTransforms(transforms);
  EXPECT_EQ(centre(), white);
  transforms[panel] = at({0, 0, -1});  // back in front
  renderer.setInstanceTransforms(transforms);
  EXPECT_EQ(centre(), red);
  renderer.setInstanceVisible(panel, false);
  EXPECT_EQ(centre(), white);
  renderer.setInstanceVisible(panel, true);
  EXPECT_EQ(centre(), red);

  // The same scene with the panel a mirror facing the camera: the ray back meets the body.
  builder.scene.materials[builder.scene.instances[panel].material] = mirrorMaterial();
  render::Renderer mirrored(context(), compiler(), builder.scene, smallView());
  centreAfterFrame(mirrored);
  EXPECT_EQ(mirrored.pixelPaths()[7 * 15 + 7].finalInstance, body);
}

TEST_F(GlassMirrorTest, overlapping_panes_multiply_and_creation_order_does_not_matter) {
  const std::vector<glm::vec3> tints = {
      {0.9f, 0.8f, 0.7f}, {0.5f, 0.9f, 0.95f}, {0.8f, 0.6f, 0.9f}};
  std::vector<int> order(tints.size());
  std::iota(order.begin(), order.end(), 0);
  std::optional<std::vector<uint8_t>> first;
  int permutations = 0;
  do {
    SceneBuilder builder = wallScene();
    const uint32_t pane = builder.mesh(game::primitives::box({4, 4, 0.02f}));
    for (int which : order)
      builder.instance(pane, builder.material(glassMaterial(tints[which])),
                       at({0, 0, -0.4f - 0.3f * float(which)}));
    const Frame frame = render(builder.scene, 9, 9);
    if (!first) {
      const glm::vec3 product = tints[0] * tints[1] * tints[2];
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(channel(frame.image, 4, 4, c), expectedByte(product[c]), 1) << c;
      first = frame.image.pixels;
    } else {
      EXPECT_EQ(frame.image.pixels, *first) << "creation order changed the image";
    }
    ++permutations;
  } while (std::next_permutation(order.begin(), order.end()));
  EXPECT_EQ(permutations, 6);
}

TEST_F(GlassMirrorTest, glass_behind_an_opaque_wall_is_invisible) {
  const Frame without = render(wallScene().scene, 16, 16);
  SceneBuilder builder = wallScene();
  builder.instance(builder.mesh(game::primitives::box({4, 4, 0.02f})),
                   builder.material(glassMaterial({0.1f, 0.1f, 0.1f})), at({0, 0, -3}));
  const Frame with = render(builder.scene, 16, 16);
  EXPECT_EQ(with.pipeline.misses.size(), 3u);  // the glass variant really ran
  EXPECT_EQ(without.image.pixels, with.image.pixels);
}

TEST_F(GlassMirrorTest, mirror_at_45_degrees_shows_object_behind_camera_at_cpu_computed_pixel) {
  // Mirror facing (1, 0, 1)/sqrt2 through (0, 0, -3); the camera looks along -Z. Rays on the
  // left of the image reflect back past the camera, to a green emitter at z = +0.3.
  SceneBuilder builder;
  const float thickness = 0.01f;
  const uint32_t mirrorInstance = builder.instance(
      builder.mesh(game::primitives::box({30, 30, thickness})), builder.material(mirrorMaterial()),
      glm::rotate(at({0, 0, -3}), glm::radians(45.0f), glm::vec3(0, 1, 0)));
  const glm::vec3 objectPosition(4.0f, 0.0f, 0.3f);
  const uint32_t object =
      builder.instance(builder.mesh(game::primitives::sphere(0.4f)),
                       builder.material(emissive({0, 1, 0})), at(objectPosition));
  builder.scene.maxMirrorBounces = 4;
  const uint32_t size = 65;
  const Frame frame = render(builder.scene, size, size);

  // CPU: the object's image in the mirror plane, projected through the camera.
  const glm::vec3 normal = glm::normalize(glm::vec3(1, 0, 1));
  const glm::vec3 pointOnMirror = glm::vec3(0, 0, -3) + normal * (thickness * 0.5f);
  const glm::vec3 image =
      objectPosition - 2.0f * glm::dot(objectPosition - pointOnMirror, normal) * normal;
  const double tanHalf = std::tan(glm::radians(60.0) / 2.0);
  const double ndcX = (image.x / -image.z) / tanHalf;
  const double ndcY = (image.y / -image.z) / tanHalf;
  const uint32_t column = uint32_t(std::floor((ndcX + 1.0) * 0.5 * size));
  const uint32_t row = uint32_t(std::floor((1.0 - ndcY) * 0.5 * size));
  ASSERT_LT(column, size);
  EXPECT_LT(ndcX, -0.5);  // well to the left: the object really is behind the camera
  EXPECT_EQ(channel(frame.image, column, row, 1), 255);
  EXPECT_EQ(channel(frame.image, column, row, 0), 0);
  const render::gpu::PixelPath path = frame.paths[row * size + column];
  EXPECT_EQ(path.finalInstance, object);
  EXPECT_EQ(path.bounces, 1u);
  // The image centre sees the mirror reflecting empty sky: black, nothing reached.
  EXPECT_EQ(channel(frame.image, size / 2, size / 2, 1), 0);
  EXPECT_EQ(frame.paths[(size / 2) * size + size / 2].finalInstance, PATH_REACHED_NOTHING);
  (void)mirrorInstance;
}

TEST_F(GlassMirrorTest, parallel_mirrors_stop_at_the_bounce_cap_without_nan) {
  std::optional<render::ShaderDefines> firstDefines;
  for (uint32_t cap : {1u, 4u, 31u}) {
    SceneBuilder builder;
    const uint32_t slab = builder.mesh(game::primitives::box({10, 10, 0.02f}));
    const uint32_t silver = builder.material(mirrorMaterial({0.9f, 0.9f, 0.9f}));
    builder.instance(slab, silver, at({0, 0, -1}));
    builder.instance(slab, silver, at({0, 0, 1}));
    builder.scene.environment.skyHorizon = glm::vec3(0.5f);
    builder.scene.maxMirrorBounces = cap;
    const Frame frame = render(builder.scene, 9, 9);
    // The cap is a uniform: every cap renders with the one pipeline (one compile).
    if (!firstDefines) firstDefines = frame.pipeline.defines;
    EXPECT_EQ(frame.pipeline.defines, *firstDefines) << "cap " << cap;
    const render::gpu::PixelPath centre = frame.paths[4 * 9 + 4];
    EXPECT_EQ(centre.bounces, cap) << "cap " << cap;
    EXPECT_EQ(centre.finalInstance, PATH_REACHED_NOTHING);
    EXPECT_EQ(channel(frame.image, 4, 4, 0), 0);  // the path ends black at the cap
  }
}

TEST_F(GlassMirrorTest, glass_shadow_on_white_floor_is_tint_times_unshadowed) {
  // Sun along (1, -1, 0): a pane 0.3 m up at x in [-0.1, 0.1] shadows x in [0.2, 0.4].
  const glm::vec3 tint(0.25f, 0.5f, 0.75f);
  SceneBuilder builder;
  MaterialDesc white;
  white.baseColor = glm::vec3(1.0f);
  builder.instance(builder.mesh(game::primitives::plane(100, 100)), builder.material(white),
                   glm::mat4(1.0f));
  builder.instance(builder.mesh(game::primitives::box({0.2f, 0.02f, 0.2f})),
                   builder.material(glassMaterial(tint)), at({0, 0.3f, 0}));
  scene::LightDesc sun;
  sun.type = scene::LightType::Directional;
  sun.direction = glm::vec3(1, -1, 0);
  sun.intensity = 2.0f;
  builder.scene.lights.push_back(sun);
  scene::CameraDesc camera;
  camera.position = glm::vec3(0, 1, 0);
  camera.pitchDegrees = -90.0f;
  const Frame frame = render(builder.scene, 33, 33, camera);
  auto columnForFloorX = [](double x) {
    return uint32_t(std::floor((x / std::tan(M_PI / 6.0) + 1.0) * 0.5 * 33.0));
  };
  const double unshadowed = 2.0 * std::sqrt(0.5) / M_PI;
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(channel(frame.image, columnForFloorX(-0.3), 16, c), expectedByte(unshadowed), 1);
    EXPECT_NEAR(channel(frame.image, columnForFloorX(0.3), 16, c),
                expectedByte(tint[c] * unshadowed), 1)
        << "channel " << c;
  }
}

TEST_F(GlassMirrorTest, path_reaches_orb_through_glass_and_via_mirrors_but_not_behind_a_box) {
  const uint32_t size = 17, centre = (size / 2) * size + size / 2;
  auto orbScene = [](SceneBuilder& builder, const glm::vec3& orbAt) {
    return builder.instance(builder.mesh(game::primitives::sphere(0.5f)),
                            builder.material(emissive({1, 0.5f, 0})), at(orbAt));
  };
  {  // through glass
    SceneBuilder builder;
    const uint32_t orb = orbScene(builder, {0, 0, -4});
    builder.instance(builder.mesh(game::primitives::box({2, 2, 0.02f})),
                     builder.material(glassMaterial({0.5f, 0.5f, 1})), at({0, 0, -2}));
    const Frame frame = render(builder.scene, size, size);
    EXPECT_EQ(frame.paths[centre].finalInstance, orb);
    EXPECT_EQ(frame.paths[centre].bounces, 0u);
  }
  {  // via one mirror facing the camera, the orb behind the camera
    SceneBuilder builder;
    const uint32_t orb = orbScene(builder, {0, 0, 3});
    builder.instance(builder.mesh(game::primitives::box({10, 10, 0.02f})),
                     builder.material(mirrorMaterial()), at({0, 0, -3}));
    const Frame frame = render(builder.scene, size, size, {{0, 0, 0}, 0, 0, 20});
    EXPECT_EQ(frame.paths[centre].finalInstance, orb);
    EXPECT_EQ(frame.paths[centre].bounces, 1u);
  }
  {  // via two mirrors: a periscope, down then forward
    SceneBuilder builder;
    const uint32_t slab = builder.mesh(game::primitives::box({3, 3, 0.02f}));
    const uint32_t silver = builder.material(mirrorMaterial());
    // Upper mirror ahead at z=-2 turns the view down; lower mirror at y=-3 turns it forward.
    builder.instance(slab, silver,
                     glm::rotate(at({0, 0, -2}), glm::radians(45.0f), glm::vec3(1, 0, 0)));
    builder.instance(slab, silver,
                     glm::rotate(at({0, -3, -2}), glm::radians(45.0f), glm::vec3(1, 0, 0)));
    const uint32_t orb = orbScene(builder, {0, -3, -6});
    const Frame frame = render(builder.scene, size, size, {{0, 0, 0}, 0, 0, 20});
    EXPECT_EQ(frame.paths[centre].finalInstance, orb);
    EXPECT_EQ(frame.paths[centre].bounces, 2u);
  }
  {  // behind an opaque box: the box is what the path reached
    SceneBuilder builder;
    const uint32_t orb = orbScene(builder, {0, 0, -4});
    MaterialDesc grey;
    const uint32_t box = builder.instance(builder.mesh(game::primitives::box({2, 2, 0.5f})),
                                          builder.material(grey), at({0, 0, -2}));
    const Frame frame = render(builder.scene, size, size);
    EXPECT_NE(frame.paths[centre].finalInstance, orb);
    EXPECT_EQ(frame.paths[centre].finalInstance, box);
  }
}

TEST(PipelineVariant, plain_glass_and_mirror_levels_build_the_documented_pipelines) {
  const render::PipelineDescription plain = render::describePipeline({false, false, 0});
  EXPECT_EQ(plain.misses, (std::vector<std::string>{"surface.rmiss", "shadow.rmiss"}));
  EXPECT_EQ(plain.hitGroups, (std::vector<std::string>{"surface.rchit"}));
  EXPECT_EQ(plain.recursionDepth, 1u);
  EXPECT_EQ(
      plain.defines,
      (render::ShaderDefines{
          {"HAS_GLASS", "0"}, {"HAS_MIRRORS", "0"}, {"SOFT_SHADOWS", "0"}, {"LIGHT_ROUTES", "0"}}));

  const render::PipelineDescription withGlass = render::describePipeline({true, false, 0});
  EXPECT_EQ(withGlass.misses,
            (std::vector<std::string>{"surface.rmiss", "shadow.rmiss", "glass.rmiss"}));
  EXPECT_EQ(withGlass.hitGroups, (std::vector<std::string>{"surface.rchit", "glass.rahit"}));
  EXPECT_EQ(withGlass.recursionDepth, 1u);

  const render::PipelineDescription withMirrors = render::describePipeline({false, true, 4});
  EXPECT_EQ(withMirrors.hitGroups, (std::vector<std::string>{"surface.rchit"}));
  EXPECT_EQ(
      withMirrors.defines,
      (render::ShaderDefines{
          {"HAS_GLASS", "0"}, {"HAS_MIRRORS", "1"}, {"SOFT_SHADOWS", "0"}, {"LIGHT_ROUTES", "0"}}));
  EXPECT_EQ(withMirrors.recursionDepth, 1u);

  const render::PipelineDescription soft = render::describePipeline({false, false, 0, true});
  EXPECT_EQ(soft.hitGroups, (std::vector<std::string>{"surface.rchit"}));
  EXPECT_EQ(soft.defines[2], (std::pair<std::string, std::string>{"SOFT_SHADOWS", "1"}));

  render::PipelineFeatures routed{false, true, 4};
  routed.lightRoutes = true;
  EXPECT_EQ(render::describePipeline(routed).defines.back(),
            (std::pair<std::string, std::string>{"LIGHT_ROUTES", "1"}));
  EXPECT_EQ(soft.recursionDepth, 1u);
}

TEST(PipelineVariant, features_follow_the_materials_instances_use) {
  SceneBuilder builder;
  const uint32_t cube = builder.mesh(game::primitives::box({1, 1, 1}));
  builder.instance(cube, builder.material(MaterialDesc{}), glm::mat4(1.0f));
  builder.material(glassMaterial({0.5f, 0.5f, 0.5f}));  // defined but unused: no glass variant
  builder.scene.maxMirrorBounces = 7;
  EXPECT_EQ(render::featuresOf(builder.scene), (render::PipelineFeatures{false, false, 0}));
  builder.instance(cube, builder.material(mirrorMaterial()), glm::mat4(1.0f));
  EXPECT_EQ(render::featuresOf(builder.scene), (render::PipelineFeatures{false, true, 7}));
  // With a light, a flat mirror routes light; a curved one does not.
  scene::LightDesc lamp;
  builder.light(lamp);
  EXPECT_TRUE(render::featuresOf(builder.scene).lightRoutes);
  builder.scene.instances.back().mesh = builder.mesh(game::primitives::sphere(1.0f, 16, 8));
  EXPECT_FALSE(render::featuresOf(builder.scene).lightRoutes);
}

}  // namespace
