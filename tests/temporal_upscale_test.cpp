// Temporal upscaling: a 32x18 picture accumulated into a 128x72 history (4x, as play's 320x180
// in a 1280x720 window), and probes that do not see the jitter.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "game/primitives.hpp"
#include "render/image_metrics.hpp"
#include "render/temporal_upscaler.hpp"
#include "render/vulkan_error.hpp"
#include "scene/color.hpp"
#include "scene_builder.hpp"
#include "vulkan_fixture.hpp"

namespace {

using test::at;
using test::SceneBuilder;

constexpr uint32_t kRenderWidth = 32, kRenderHeight = 18;
constexpr uint32_t kOutputWidth = 128, kOutputHeight = 72;
// A white box against a dark wall 5 m away, seen head-on; the box's x per frame is given.
constexpr float kBoxDepth = -3.0f;

// The width of a render pixel (a sample's spacing) `distance` ahead of the camera (60 degrees
// vertical field of view).
float renderPixelAt(float distance) {
  return 2.0f * distance * std::tan(glm::radians(30.0f)) / float(kRenderHeight);
}

uint32_t greyMaterial(SceneBuilder& builder, float grey) {
  scene::MaterialDesc material;
  material.baseColor = glm::vec3(grey);
  return builder.material(material);
}

scene::SceneDesc boxScene(float boxX) {
  SceneBuilder builder;
  scene::MaterialDesc dark, white;
  dark.baseColor = glm::vec3(0.1f);
  white.baseColor = glm::vec3(1.0f);
  white.emissive = glm::vec3(1.0f);
  const uint32_t wall = builder.material(dark), paint = builder.material(white);
  builder.instance(builder.mesh(game::primitives::box({20.0f, 20.0f, 0.1f})), wall,
                   at({0.0f, 0.0f, -5.0f}));
  builder.instance(builder.mesh(game::primitives::box({0.8f, 0.8f, 0.8f})), paint,
                   at({boxX, 0.0f, kBoxDepth}));
  scene::LightDesc light;
  light.position = glm::vec3(0.0f, 2.0f, 0.0f);
  light.intensity = 4.0f;
  builder.light(light);
  return builder.scene;
}

// A lamp (a sphere light, seen as its own white) 0.8 m across where the box is, and what lights
// the wall; `lampX` as the box's x. The sphere is the scene's light kLampLight.
constexpr uint32_t kLampLight = 1;

scene::LightDesc lampAt(float lampX) {
  scene::LightDesc lamp;
  lamp.type = scene::LightType::Sphere;
  lamp.position = glm::vec3(lampX, 0.0f, kBoxDepth);
  lamp.radius = 0.4f;
  lamp.intensity = 2.0f;  // seen, white at the identity tonemap; on the wall, hardly anything
  return lamp;
}

scene::SceneDesc lampScene(float lampX) {
  SceneBuilder builder;
  builder.instance(builder.mesh(game::primitives::box({20.0f, 20.0f, 0.1f})),
                   greyMaterial(builder, 0.1f), at({0.0f, 0.0f, -5.0f}));
  scene::LightDesc light;
  light.position = glm::vec3(0.0f, 2.0f, 0.0f);
  light.intensity = 4.0f;
  builder.light(light);
  builder.light(lampAt(lampX));
  return builder.scene;
}

// A mirror 3 m ahead, 4 m wide (the view is 6 m wide there), before a grey wall. Behind the
// camera, 2 m off, a wall of vertical bars in two greys, which the camera sees only in the
// mirror, 8 m away along its rays: there a bar is 1.5 render pixels wide.
constexpr float kMirrorDepth = -3.0f, kBarsBehindCamera = 2.0f;

scene::SceneDesc mirrorScene() {
  SceneBuilder builder;
  const uint32_t wall = greyMaterial(builder, 0.3f), dark = greyMaterial(builder, 0.25f),
                 pale = greyMaterial(builder, 0.6f);
  builder.instance(builder.mesh(game::primitives::box({20.0f, 20.0f, 0.1f})), wall,
                   at({0.0f, 0.0f, -5.0f}));
  builder.instance(builder.mesh(game::primitives::box({4.0f, 2.0f, 0.05f})),
                   builder.material(test::mirrorMaterial()), at({0.0f, 0.0f, kMirrorDepth}));
  const float barWidth = 0.75f;
  const uint32_t bar = builder.mesh(game::primitives::box({barWidth, 20.0f, 0.1f}));
  for (int i = -24; i <= 24; ++i)
    builder.instance(bar, (i & 1) != 0 ? dark : pale,
                     at({barWidth * float(i), 0.0f, kBarsBehindCamera}));
  scene::LightDesc lamp;  // behind the mirror and above it: lights the wall and the bars
  lamp.position = glm::vec3(0.0f, 2.5f, -4.0f);
  lamp.intensity = 20.0f;
  builder.light(lamp);
  return builder.scene;
}

// A lamp 2 m above the camera, which lights what is ahead of it.
void lampAboveTheCamera(SceneBuilder& builder) {
  scene::LightDesc lamp;
  lamp.position = glm::vec3(0.0f, 2.0f, 0.0f);
  lamp.intensity = 20.0f;
  builder.light(lamp);
}

// Dark bars 0.6 samples wide and 3.3 apart, 4 m ahead, before a pale wall 5 m away: details
// thinner than the samples' spacing, which the four samples around a pixel mostly miss.
constexpr float kThinBarDepth = -4.0f;
const float kSampleAtThinBars = renderPixelAt(-kThinBarDepth);

scene::SceneDesc thinBarsScene() {
  SceneBuilder builder;
  const uint32_t pale = greyMaterial(builder, 0.8f), dark = greyMaterial(builder, 0.0f);
  builder.instance(builder.mesh(game::primitives::box({40.0f, 20.0f, 0.1f})), pale,
                   at({0.0f, 0.0f, -5.0f}));
  const uint32_t bar = builder.mesh(game::primitives::box({0.6f * kSampleAtThinBars, 2.0f, 0.05f}));
  for (int i = -12; i <= 12; ++i)
    builder.instance(bar, dark, at({3.3f * kSampleAtThinBars * float(i), 0.0f, kThinBarDepth}));
  lampAboveTheCamera(builder);
  return builder.scene;
}

// Boxes of `size`, pale and dark in turn, side by side along x: 2 * `count` + 1 of them, the
// middle one at `centre`.
void paleAndDarkInTurn(SceneBuilder& builder, glm::vec3 size, int count, glm::vec3 centre) {
  const uint32_t pale = greyMaterial(builder, 0.8f), dark = greyMaterial(builder, 0.1f);
  const uint32_t box = builder.mesh(game::primitives::box(size));
  for (int i = -count; i <= count; ++i)
    builder.instance(box, (i & 1) != 0 ? dark : pale,
                     at(centre + glm::vec3(size.x * float(i), 0.0f, 0.0f)));
}

// Vertical bars 1.5 samples wide, pale and dark in turn, on a wall 5 m ahead.
const float kSampleAtBars = renderPixelAt(5.0f);

scene::SceneDesc barsScene() {
  SceneBuilder builder;
  paleAndDarkInTurn(builder, {1.5f * kSampleAtBars, 20.0f, 0.1f}, 40, {0.0f, 0.0f, -5.0f});
  lampAboveTheCamera(builder);
  return builder.scene;
}

// A floor 1 m below the camera, striped along the view in pale and dark (a stripe is 4 samples
// wide 4 m away), out to a grey wall 9 m ahead. Seen looking down (kFloorPitch), the floor fills
// the picture and its depth changes from row to row.
constexpr float kStripeDepth = 4.0f, kFloorPitch = -60.0f;
const float kSampleAtStripes = renderPixelAt(kStripeDepth);

scene::SceneDesc stripedFloorScene() {
  SceneBuilder builder;
  paleAndDarkInTurn(builder, {4.0f * kSampleAtStripes, 0.1f, 9.0f}, 30, {0.0f, -1.05f, -4.5f});
  builder.instance(builder.mesh(game::primitives::box({40.0f, 20.0f, 0.1f})),
                   greyMaterial(builder, 0.3f), at({0.0f, 0.0f, -9.0f}));
  lampAboveTheCamera(builder);
  return builder.scene;
}

// A grey wall 6 m ahead and before it, 5 m ahead, one instance: a panel of bars one sample wide,
// pale and dark in turn (one mesh, a material per triangle).
constexpr float kPanelDepth = -5.0f, kPanelWallDepth = -6.0f;

// The wall's and the panel's transforms, the panel `panelX` to the right.
std::vector<glm::mat4> slidingPanelTransforms(float panelX) {
  return {at({0.0f, 0.0f, kPanelWallDepth}), at({panelX, 0.0f, kPanelDepth})};
}

scene::SceneDesc slidingPanelScene() {
  SceneBuilder builder;
  const uint32_t pale = greyMaterial(builder, 0.8f), dark = greyMaterial(builder, 0.1f);
  builder.instance(builder.mesh(game::primitives::box({60.0f, 20.0f, 0.1f})),
                   greyMaterial(builder, 0.3f), slidingPanelTransforms(0.0f)[0]);
  scene::MeshData panel;
  for (int i = -40; i <= 40; ++i) {
    const scene::MeshData bar = game::primitives::box({kSampleAtBars, 20.0f, 0.1f});
    const uint32_t first = uint32_t(panel.vertices.size());
    for (scene::Vertex vertex : bar.vertices) {
      vertex.position.x += kSampleAtBars * float(i);
      panel.vertices.push_back(vertex);
    }
    for (uint32_t index : bar.indices) panel.indices.push_back(first + index);
    panel.triangleMaterials.insert(panel.triangleMaterials.end(), bar.indices.size() / 3,
                                   (i & 1) != 0 ? 1u : 0u);
  }
  builder.instance(builder.mesh(panel), pale, slidingPanelTransforms(0.0f)[1]);
  builder.scene.instances.back().meshMaterials = {pale, dark};
  lampAboveTheCamera(builder);
  return builder.scene;
}

scene::FrameDesc frameAt(uint32_t index) {
  scene::FrameDesc frame;
  frame.tonemap = scene::Tonemap::Identity;
  frame.frameIndex = index;
  return frame;
}

// Green channel in [0, 1], rows top to bottom.
std::vector<float> green(const std::vector<uint8_t>& pixels) {
  std::vector<float> values;
  for (size_t i = 1; i < pixels.size(); i += 4) values.push_back(float(pixels[i]) / 255.0f);
  return values;
}

// The values of `values` where `where` holds.
std::vector<float> only(const std::vector<float>& values, const std::vector<bool>& where) {
  std::vector<float> kept;
  for (size_t i = 0; i < values.size(); ++i)
    if (where[i]) kept.push_back(values[i]);
  return kept;
}

class TemporalUpscaleTest : public test::VulkanTest {
 protected:
  static std::unique_ptr<render::Renderer> upscaler(const scene::SceneDesc& scene) {
    render::RendererOptions options;
    options.width = kRenderWidth;
    options.height = kRenderHeight;
    options.outputWidth = kOutputWidth;
    options.outputHeight = kOutputHeight;
    return std::make_unique<render::Renderer>(context(), compiler(), scene, options);
  }

  // The box scene at the output size, averaged in linear light over 16 jittered frames, seen
  // from the camera moved `cameraX` to the right.
  static std::vector<float> reference(float boxX, float cameraX = 0.0f) {
    return reference(boxScene(boxX), cameraX);
  }

  static std::vector<float> reference(const scene::SceneDesc& scene, float cameraX,
                                      const scene::CameraDesc& start = {}) {
    render::RendererOptions options;
    options.width = kOutputWidth;
    options.height = kOutputHeight;
    render::Renderer renderer(context(), compiler(), scene, options);
    constexpr uint32_t kSamples = 16;
    std::vector<double> sum(size_t(kOutputWidth) * kOutputHeight, 0.0);
    for (uint32_t i = 0; i < kSamples; ++i) {
      scene::FrameDesc frame = frameAt(i);
      frame.camera = start;
      frame.camera.position.x += cameraX;
      frame.jitter = render::TemporalUpscaler::jitter(i * 5u + 1u);
      renderer.renderFrame(frame);
      const std::vector<float> values = green(renderer.pixels());
      for (size_t k = 0; k < sum.size(); ++k) sum[k] += scene::srgbToLinear(values[k]);
    }
    std::vector<float> result;
    for (double value : sum) result.push_back(scene::linearToSrgb(float(value / kSamples)));
    return result;
  }

  struct StrafeErrors {
    double moving, still;
  };

  // `scene` upscaled over `frames` frames, the camera strafing `step` to the right a frame from
  // `start`, and held still where the strafe ends; the RMSE of each against the reference there.
  static StrafeErrors strafedAndHeldStill(const scene::SceneDesc& scene, float step,
                                          uint32_t frames = 16,
                                          const scene::CameraDesc& start = {}) {
    auto walking = upscaler(scene);
    auto still = upscaler(scene);
    for (uint32_t frame = 0; frame < frames; ++frame) {
      scene::FrameDesc walked = frameAt(frame), held = frameAt(frame);
      walked.camera = held.camera = start;
      walked.camera.position.x += step * float(frame);
      held.camera.position.x += step * float(frames - 1);
      walking->renderFrame(walked);
      still->renderFrame(held);
    }
    const std::vector<float> expected = reference(scene, step * float(frames - 1), start);
    const StrafeErrors errors{render::rootMeanSquareError(expected, green(walking->pixels())),
                              render::rootMeanSquareError(expected, green(still->pixels()))};
    std::printf("after %u frames: strafing RMSE %.5f, held still %.5f (%.2fx)\n", frames,
                errors.moving, errors.still, errors.moving / errors.still);
    return errors;
  }

  struct Trail {
    int longest = 0;  // output pixels
    int rows = 0;     // rows measured
  };

  // Along each row through a white shape moving right (`expected` is where it ends), not within
  // a render pixel (4 output pixels) of its top and bottom edges, where this frame's samples
  // blend the shape and the wall whatever the history: the pixels left of its trailing edge
  // that still differ from the wall by more than a tenth.
  static Trail trailBehind(const std::vector<float>& shown, const std::vector<float>& expected) {
    Trail trail;
    for (uint32_t y = 0; y < kOutputHeight; ++y) {
      const float* row = &expected[size_t(y) * kOutputWidth];
      uint32_t edge = 0;
      while (edge < kOutputWidth && row[edge] < 0.5f) ++edge;
      auto throughShape = [&](uint32_t at) {
        const float* other = &expected[size_t(at) * kOutputWidth];
        return *std::max_element(other, other + kOutputWidth) >= 0.95f;
      };
      if (edge == kOutputWidth || edge < 2 || y < 4 || y + 4 >= kOutputHeight ||
          !throughShape(y - 4) || !throughShape(y + 4))
        continue;
      ++trail.rows;
      int length = 0;
      for (int x = int(edge) - 1; x >= 0; --x) {
        const size_t i = size_t(y) * kOutputWidth + size_t(x);
        if (std::abs(shown[i] - expected[i]) <= 0.1f) break;
        ++length;
      }
      trail.longest = std::max(trail.longest, length);
    }
    std::printf("longest trail: %d output px over %d rows\n", trail.longest, trail.rows);
    return trail;
  }

  // A shape sliding one render pixel (at the box's depth) to the right a frame: its x at `frame`.
  static constexpr uint32_t kSlideFrames = 16;
  static float slidTo(uint32_t frame) { return -0.8f + renderPixelAt(-kBoxDepth) * float(frame); }

  static void moveBox(render::Renderer& renderer, float boxX) {
    const std::vector<glm::mat4> transforms = {at({0.0f, 0.0f, -5.0f}),
                                               at({boxX, 0.0f, kBoxDepth})};
    renderer.setInstanceTransforms(transforms);
  }
};

TEST_F(TemporalUpscaleTest, the_output_is_the_output_size_and_a_static_view_converges) {
  auto renderer = upscaler(boxScene(0.0f));
  EXPECT_EQ(renderer->outputWidth(), kOutputWidth);
  EXPECT_EQ(renderer->outputHeight(), kOutputHeight);
  const std::vector<float> expected = reference(0.0f);
  std::vector<double> errors;
  for (uint32_t frame = 1; frame <= 32; ++frame) {
    renderer->renderFrame(frameAt(frame));
    ASSERT_EQ(renderer->pixels().size(), size_t(kOutputWidth) * kOutputHeight * 4);
    if (frame == 1 || frame == 8 || frame == 32)
      errors.push_back(render::rootMeanSquareError(expected, green(renderer->pixels())));
  }
  std::printf("RMSE after 1, 8, 32 frames: %.5f %.5f %.5f\n", errors[0], errors[1], errors[2]);
  EXPECT_LT(errors[1], errors[0]);  // the jittered samples add detail the first frame lacks
  EXPECT_LE(errors[2], errors[1]);  // and it settles rather than drifting
}

TEST_F(TemporalUpscaleTest, a_moving_box_leaves_no_trail_longer_than_2_output_pixels) {
  // The box slides one render pixel (4 output pixels) to the right a frame for 16 frames.
  auto renderer = upscaler(boxScene(slidTo(0)));
  for (uint32_t frame = 0; frame < kSlideFrames; ++frame) {
    moveBox(*renderer, slidTo(frame));
    renderer->renderFrame(frameAt(frame));
  }
  const Trail trail = trailBehind(green(renderer->pixels()), reference(slidTo(kSlideFrames - 1)));
  EXPECT_GT(trail.rows, 5);
  EXPECT_LE(trail.longest, 2);
}

TEST_F(TemporalUpscaleTest, a_moving_lamp_leaves_no_trail_longer_than_2_output_pixels) {
  // The lamp (a light seen, not an instance) slides as the box does above: the history of its
  // pixels follows where the light was at the previous frame, and what it uncovers drops the
  // lamp's history as a moving instance's. 1 output pixel; with the sky's motion for a light
  // seen, as before session 30, 5.
  auto renderer = upscaler(lampScene(slidTo(0)));
  for (uint32_t frame = 0; frame < kSlideFrames; ++frame) {
    renderer->setLightPose(kLampLight, lampAt(slidTo(frame)).position, glm::vec3(0.0f));
    renderer->renderFrame(frameAt(frame));
  }
  const Trail trail =
      trailBehind(green(renderer->pixels()), reference(lampScene(slidTo(kSlideFrames - 1)), 0.0f));
  EXPECT_GT(trail.rows, 5);
  EXPECT_LE(trail.longest, 2);
}

TEST_F(TemporalUpscaleTest, a_strafing_view_is_within_1_5x_of_the_same_view_held_still) {
  // The camera strafes right 1.5 render pixels (at the box's depth) a frame for 16 frames, so
  // the box's edges move over the wall behind it (parallax) at a fraction of a sample a frame.
  const float pixelAtBox = renderPixelAt(-kBoxDepth);
  const float step = 1.5f * pixelAtBox;
  const StrafeErrors errors = strafedAndHeldStill(boxScene(0.0f), step);
  // Issue 20 asks for 1.5x. Reprojecting with the nearest-in-depth sample's motion kept it below
  // the still view's clamped history (0.90x; with the nearest sample's motion 1.08x). The still
  // view's history now goes unclamped once the scene has held 8 frames, which lowered its error
  // 0.00161 -> 0.00112 (the strafing view's is 0.00145 as before): 1.30x. Since session 27 a
  // moving history the clamp moved far keeps less of its weight: 0.00144, 1.28x; since session
  // 28 it keeps at most 16 frames' worth: 0.00145, 1.30x; since session 32 a silhouette's pixels
  // move as the surface continued towards the outline: 0.00142, 1.27x.
  EXPECT_LE(errors.moving, 1.5 * errors.still);
}

TEST_F(TemporalUpscaleTest, a_strafing_view_keeps_a_lamp_it_sees_whole) {
  // The camera strafes 0.3 samples a frame (at the lamp's depth) past the lamp, 3 m away before
  // the wall: a light seen moves on the screen as its point does. 1.23x the still view's error
  // (1.36x before session 31 interpolated the moves of the samples on the sphere, 1.30x before
  // session 32 continued them towards its outline); with the sky's motion for a light seen, as
  // before session 30, 2.26x (0.7 samples a frame: 1.81x, 2.77x).
  const float step = 0.3f * renderPixelAt(-kBoxDepth);
  const StrafeErrors errors = strafedAndHeldStill(lampScene(0.0f), step);
  EXPECT_LE(errors.moving, 1.5 * errors.still);
}

TEST_F(TemporalUpscaleTest, a_strafing_view_follows_what_a_mirror_shows_not_the_mirror) {
  // What a mirror shows moves as its virtual image (the bars behind the camera, 8 m off along the
  // camera rays), not as the mirror 3 m away: strafing 0.3 render pixels a frame at the image's
  // depth moves the mirror's surface 0.8. Ray-gen writes the reflection's motion inside the
  // mirror and the resolve takes the mirror's own along its outline.
  const float imageDepth = -kMirrorDepth + (kBarsBehindCamera - kMirrorDepth);
  const float step = 0.3f * renderPixelAt(imageDepth);
  const StrafeErrors errors = strafedAndHeldStill(mirrorScene(), step);
  // 1.25x; with the mirror's own motion inside it, as before session 26, 1.81x. (The outline's
  // rule is measured on 19 Last Light: docs/QUALITY.md.)
  EXPECT_LE(errors.moving, 1.5 * errors.still);
}

TEST_F(TemporalUpscaleTest, a_strafing_view_follows_a_lamp_seen_in_a_mirror) {
  // The lamp hangs 1.5 m behind the camera, seen in the mirror 7.5 m off along the camera rays:
  // its reflection moves as the point at the path's whole length, not as the sky.
  scene::SceneDesc scene = mirrorScene();
  scene::LightDesc lamp = lampAt(0.5f);
  lamp.position.z = 1.5f;
  lamp.radius = 0.6f;
  scene.lights.push_back(lamp);
  const float imageDepth = -kMirrorDepth + (lamp.position.z - kMirrorDepth);
  const StrafeErrors errors = strafedAndHeldStill(scene, 0.3f * renderPixelAt(imageDepth));
  // 1.42x; with the sky's motion for a light seen in a mirror, as before session 30, 1.77x.
  EXPECT_LE(errors.moving, 1.5 * errors.still);
}

TEST_F(TemporalUpscaleTest, a_strafing_view_lets_go_of_history_the_clamp_moved_far) {
  // Strafing 0.7 samples a frame past bars thinner than a sample, the history of a pixel a bar
  // has left (or reached) lies far outside this frame's samples' range; clamped, it is still
  // wrong, so it counts for less and the samples take over sooner. 1.75x the still view's error;
  // with the clamped history at its full weight, as before session 27, 2.08x. (Issue 20's 1.5x
  // is not met on this scene: docs/QUALITY.md, session 27, has the levels.)
  const StrafeErrors errors = strafedAndHeldStill(thinBarsScene(), 0.7f * kSampleAtThinBars);
  EXPECT_LE(errors.moving, 1.9 * errors.still);
}

TEST_F(TemporalUpscaleTest, a_long_strafe_is_within_1_5x_of_the_same_view_held_still) {
  // Strafing 0.45 samples a frame for 64 frames past bars 1.5 samples wide: each frame resamples
  // the history, so a history that kept every frame's samples is a blurred one. A moving history
  // keeps at most 16 frames' worth at 4x: 1.33x the still view's error; without that cap, as
  // before session 28, 1.57x.
  const StrafeErrors errors =
      strafedAndHeldStill(barsScene(), 0.45f * kSampleAtBars, /*frames=*/64);
  EXPECT_LE(errors.moving, 1.5 * errors.still);
}

TEST_F(TemporalUpscaleTest, a_strafing_view_keeps_a_floor_where_it_is) {
  // Strafing 0.3 samples a frame (at 4 m) over the striped floor, seen from above at a slant: the
  // four samples around a pixel lie at different depths, and the nearest of them in depth, the
  // one nearest the camera, moves further than the pixel's point. The samples' motions on one
  // surface are interpolated at the pixel: 1.46x the still view's error (1.45x since session 32
  // continues them towards an outline); with the nearest one's motion alone, as before
  // session 31, 1.58x.
  scene::CameraDesc lookingDown;
  lookingDown.pitchDegrees = kFloorPitch;
  const StrafeErrors errors =
      strafedAndHeldStill(stripedFloorScene(), 0.3f * kSampleAtStripes, 16, lookingDown);
  EXPECT_LE(errors.moving, 1.5 * errors.still);
}

TEST_F(TemporalUpscaleTest, a_strafing_view_keeps_the_far_edge_of_a_box_where_it_is) {
  // Strafing 0.3 samples (at the box) a frame for 32 frames, the camera sees the box's side
  // face at a slant, a sample or two wide, and the box's outline on that side is the face's far
  // edge, 0.8 m deeper than its front. Moving the pixels there as the sample nearest in depth,
  // nearer the camera than that edge, ran the edge 1.3 output pixels ahead: 1.56x the still
  // view's error. The move continued along the side face towards the outline: 1.33x (1.48x with
  // samples within 0.1 of each other's depth counted as one surface instead of 0.3).
  const float step = 0.3f * renderPixelAt(-kBoxDepth);
  const StrafeErrors errors = strafedAndHeldStill(boxScene(0.0f), step, /*frames=*/32);
  EXPECT_LE(errors.moving, 1.45 * errors.still);
}

TEST_F(TemporalUpscaleTest, a_panel_sliding_past_a_still_camera_keeps_16_frames_of_history) {
  // A panel of bars one sample wide slides 0.3 samples a frame for 64 frames before a still
  // camera: each frame resamples the history of the pixels it covers, as a moving camera does.
  // Against the panel held still where it ends: 1.94x the error; with the panel's history at
  // its full weight, as before session 28, 2.26x.
  const float step = 0.3f * kSampleAtBars;
  const uint32_t frames = 64;
  const scene::SceneDesc scene = slidingPanelScene();
  auto sliding = upscaler(scene), held = upscaler(scene);
  const float endX = step * float(frames - 1);
  for (uint32_t frame = 0; frame < frames; ++frame) {
    sliding->setInstanceTransforms(slidingPanelTransforms(step * float(frame)));
    held->setInstanceTransforms(slidingPanelTransforms(endX));
    sliding->renderFrame(frameAt(frame));
    held->renderFrame(frameAt(frame));
  }
  scene::SceneDesc ended = scene;
  ended.instances[1].objectToWorld = slidingPanelTransforms(endX)[1];
  const std::vector<float> expected = reference(ended, 0.0f);
  const double slidingError = render::rootMeanSquareError(expected, green(sliding->pixels()));
  const double heldError = render::rootMeanSquareError(expected, green(held->pixels()));
  std::printf("after %u frames: sliding RMSE %.5f, held still %.5f (%.2fx)\n", frames, slidingError,
              heldError, slidingError / heldError);
  EXPECT_LE(slidingError, 2.1 * heldError);
}

TEST_F(TemporalUpscaleTest, a_still_view_holds_steady_once_converged) {
  // An output pixel gets its samples' weight in lumps, when one lands near its centre. A still
  // view's history keeps averaging, so after many frames a new lump hardly moves it; a history
  // held to 32 frames' worth of weight took a third of each (at 4x) and the picture shimmered
  // along the box's edges with the jitter's 16-frame cycle.
  auto renderer = upscaler(boxScene(0.0f));
  std::vector<float> previous;
  double largest = 0.0;
  for (uint32_t frame = 0; frame < 240; ++frame) {
    renderer->renderFrame(frameAt(frame));
    const std::vector<float> shown = green(renderer->pixels());
    if (frame >= 224)  // the last 16 frames, one cycle of the jitter
      largest = std::max(largest, render::rootMeanSquareError(previous, shown));
    previous = shown;
  }
  std::printf("largest change between consecutive frames over the last 16: RMSE %.5f\n", largest);
  EXPECT_LT(largest, 0.002);  // 0.00062 as it is; 0.00479 with the history held to 32 frames
}

TEST_F(TemporalUpscaleTest,
       the_scene_counts_as_steady_until_the_camera_an_instance_or_a_light_changes) {
  // Setting what is already there changes nothing; every other value restarts the count, and a
  // probe frame neither counts nor restarts it.
  auto renderer = upscaler(boxScene(0.0f));
  uint32_t frame = 0;
  scene::FrameDesc desc = frameAt(0);
  auto steadyAfterFrame = [&] {
    desc.frameIndex = frame++;
    renderer->renderFrame(desc, false);
    return renderer->steadyFrames();
  };
  EXPECT_EQ(steadyAfterFrame(), 0u);  // the first frame has none before it
  EXPECT_EQ(steadyAfterFrame(), 1u);
  EXPECT_EQ(steadyAfterFrame(), 2u);
  renderer->renderProbeFrame(desc);
  EXPECT_EQ(steadyAfterFrame(), 3u);
  renderer->setInstanceGlow(1, 0.0f);
  EXPECT_EQ(steadyAfterFrame(), 4u);
  renderer->setInstanceGlow(1, 0.5f);
  EXPECT_EQ(steadyAfterFrame(), 0u);
  renderer->setLightEnabled(0, true);
  EXPECT_EQ(steadyAfterFrame(), 1u);
  renderer->setLightEnabled(0, false);
  EXPECT_EQ(steadyAfterFrame(), 0u);
  renderer->setLightTint(0, glm::vec3(1.0f));
  EXPECT_EQ(steadyAfterFrame(), 1u);
  renderer->setLightTint(0, glm::vec3(1.0f, 0.2f, 0.2f));
  EXPECT_EQ(steadyAfterFrame(), 0u);
  renderer->setLightPose(0, glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(0.0f));
  EXPECT_EQ(steadyAfterFrame(), 1u);
  renderer->setLightPose(0, glm::vec3(0.5f, 2.0f, 0.0f), glm::vec3(0.0f));
  EXPECT_EQ(steadyAfterFrame(), 0u);
  moveBox(*renderer, 0.0f);
  EXPECT_EQ(steadyAfterFrame(), 1u);
  moveBox(*renderer, 0.1f);
  EXPECT_EQ(steadyAfterFrame(), 0u);
  // A few micrometres off where the last change put it, as a body resting on the floor lands
  // from tick to tick, is no change, and the TLAS keeps what it has; straying further from
  // there is, however slowly.
  const uint64_t updates = renderer->tlasUpdates();
  moveBox(*renderer, 0.1f + 4.0e-6f);
  EXPECT_EQ(steadyAfterFrame(), 1u);
  moveBox(*renderer, 0.1f + 8.0e-6f);
  EXPECT_EQ(steadyAfterFrame(), 2u);
  EXPECT_EQ(renderer->tlasUpdates(), updates);
  moveBox(*renderer, 0.1f + 1.2e-5f);
  EXPECT_EQ(steadyAfterFrame(), 0u);
  EXPECT_EQ(renderer->tlasUpdates(), updates + 1);
  renderer->setInstanceVisible(1, true);
  EXPECT_EQ(steadyAfterFrame(), 1u);
  renderer->setInstanceVisible(1, false);
  EXPECT_EQ(steadyAfterFrame(), 0u);
  desc.camera.yawDegrees += 1.0f;
  EXPECT_EQ(steadyAfterFrame(), 0u);
  EXPECT_EQ(steadyAfterFrame(), 1u);
  desc.exposure = 2.0f;
  EXPECT_EQ(steadyAfterFrame(), 0u);
  EXPECT_EQ(steadyAfterFrame(), 1u);
  renderer->setPictureSize(kRenderWidth / 2, kRenderHeight / 2);
  EXPECT_EQ(steadyAfterFrame(), 0u);
  EXPECT_EQ(steadyAfterFrame(), 1u);
  desc.resetHistory = true;
  EXPECT_EQ(steadyAfterFrame(), 0u);
}

TEST_F(TemporalUpscaleTest, a_light_that_stopped_lets_the_scene_count_as_steady_again) {
  // A light seen moves with the motion the renderer keeps for it; once the light stops, that
  // motion goes back to none, which is no change of the scene (nor of the light's routes via the
  // mirror, which do not carry it).
  auto renderer = upscaler(mirrorScene());
  uint32_t frame = 0;
  auto steadyAfterFrame = [&] {
    renderer->renderFrame(frameAt(frame++), false);
    return renderer->steadyFrames();
  };
  EXPECT_EQ(steadyAfterFrame(), 0u);
  EXPECT_EQ(steadyAfterFrame(), 1u);
  renderer->setLightPose(0, glm::vec3(0.5f, 2.5f, -4.0f), glm::vec3(0.0f));
  EXPECT_EQ(steadyAfterFrame(), 0u);
  EXPECT_EQ(steadyAfterFrame(), 1u);
  EXPECT_EQ(steadyAfterFrame(), 2u);
}

TEST_F(TemporalUpscaleTest, a_still_view_shows_a_change_of_the_scene_as_a_fresh_view_does) {
  // 40 still frames, the history unclamped since the scene has held, then the light on the
  // wall goes out: the frames after the change clamp again, so the lit wall does not linger.
  constexpr uint32_t kAfter = 2 * UPSCALE_STEADY_FRAMES_UNCLAMPED;
  auto renderer = upscaler(boxScene(0.0f));
  for (uint32_t frame = 0; frame < 40; ++frame) renderer->renderFrame(frameAt(frame));
  EXPECT_GE(renderer->steadyFrames(), UPSCALE_STEADY_FRAMES_UNCLAMPED);
  const std::vector<float> lit = green(renderer->pixels());
  renderer->setLightEnabled(0, false);
  for (uint32_t frame = 40; frame < 40 + kAfter; ++frame) renderer->renderFrame(frameAt(frame));
  auto fresh = upscaler(boxScene(0.0f));
  fresh->setLightEnabled(0, false);
  for (uint32_t frame = 0; frame < 40 + kAfter; ++frame) fresh->renderFrame(frameAt(frame));
  const std::vector<float> expected = green(fresh->pixels());
  const double change = render::rootMeanSquareError(expected, lit);
  const double left = render::rootMeanSquareError(expected, green(renderer->pixels()));
  std::printf(
      "the light going out changed the picture by RMSE %.5f; %u frames later %.5f of it "
      "is left\n",
      change, kAfter, left);
  // 0.00491 of 0.03638 is left, as much as when every still frame clamped (the pixels along the
  // box's edges hold a mix of box and lit wall that the new range still takes in); 0.02596 with
  // the change not counted (a mutation run: the history stayed unclamped).
  EXPECT_GT(change, 0.03);
  EXPECT_LT(left, 0.25 * change);
}

TEST_F(TemporalUpscaleTest, a_disoccluded_region_is_within_the_static_error_after_8_frames) {
  // 32 frames with the box at -0.5 m, then it jumps to +0.7 m and 8 frames follow.
  auto renderer = upscaler(boxScene(-0.5f));
  for (uint32_t frame = 0; frame < 32; ++frame) renderer->renderFrame(frameAt(frame));
  const std::vector<float> before = green(renderer->pixels());
  moveBox(*renderer, 0.7f);
  for (uint32_t frame = 32; frame < 40; ++frame) renderer->renderFrame(frameAt(frame));
  const std::vector<float> after = green(renderer->pixels());
  const std::vector<float> expected = reference(0.7f);
  std::vector<bool> uncovered(expected.size());
  size_t uncoveredPixels = 0;
  for (size_t i = 0; i < expected.size(); ++i) {
    uncovered[i] = before[i] > 0.5f && expected[i] < 0.3f;  // the box was there, the wall is now
    uncoveredPixels += uncovered[i];
  }
  auto fresh = upscaler(boxScene(0.7f));
  for (uint32_t frame = 0; frame < 8; ++frame) fresh->renderFrame(frameAt(frame));
  const double staticError = render::rootMeanSquareError(expected, green(fresh->pixels()));
  const double uncoveredError =
      render::rootMeanSquareError(only(expected, uncovered), only(after, uncovered));
  std::printf("%zu uncovered pixels: RMSE %.5f; static after 8 frames %.5f\n", uncoveredPixels,
              uncoveredError, staticError);
  EXPECT_GT(uncoveredPixels, 100u);
  EXPECT_LE(uncoveredError, staticError);
}

TEST_F(TemporalUpscaleTest, the_fragment_and_compute_resolves_give_the_same_pictures) {
  // CPU drivers resolve in a fragment shader writing colour attachments, GPUs in a compute
  // shader storing to images. The same frames must come out byte for byte the same, with the
  // box and the camera moving, then both still long enough for the history to go unclamped, at
  // an output size (3x, 96x54) that leaves partial work-groups.
  constexpr uint32_t kMovingFrames = 12, kFrames = kMovingFrames + 12;
  constexpr uint32_t kWidth = 32, kHeight = 18;
  const auto render = [&](render::ResolveWrites writes) {
    render::RendererOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.outputWidth = 3 * kWidth;
    options.outputHeight = 3 * kHeight;
    options.resolveWrites = writes;
    render::Renderer renderer(context(), compiler(), boxScene(-0.6f), options);
    std::vector<std::vector<uint8_t>> frames;
    for (uint32_t frame = 0; frame < kFrames; ++frame) {
      const uint32_t moved = std::min(frame, kMovingFrames - 1);
      moveBox(renderer, -0.6f + 0.08f * float(moved));
      scene::FrameDesc desc = frameAt(frame);
      desc.camera.position.x = moved < kMovingFrames / 2 ? 0.0f : 0.03f * float(moved);
      renderer.renderFrame(desc);
      frames.push_back(renderer.pixels());
    }
    EXPECT_GE(renderer.steadyFrames(), UPSCALE_STEADY_FRAMES_UNCLAMPED + 2);
    return frames;
  };
  const auto attachments = render(render::ResolveWrites::Attachments);
  const auto imageStores = render(render::ResolveWrites::ImageStores);
  for (uint32_t frame = 0; frame < kFrames; ++frame) {
    ASSERT_EQ(attachments[frame].size(), size_t(3 * kWidth) * 3 * kHeight * 4);
    EXPECT_EQ(attachments[frame], imageStores[frame]) << "frame " << frame;
  }
  EXPECT_NE(attachments.front(), attachments.back());  // the pictures did change
}

TEST_F(TemporalUpscaleTest, probe_frames_count_as_plain_full_frames_do_jitter_or_not) {
  const scene::SceneDesc scene = boxScene(0.1f);
  scene::ProbeRequest request;
  request.focus.push_back({1, {0.5f, 0.5f}});
  request.focus.push_back({0, {0.3f, 0.2f}});
  render::RendererOptions options;
  options.width = kRenderWidth;
  options.height = kRenderHeight;
  render::Renderer plain(context(), compiler(), scene, options);
  plain.setProbes(request);
  plain.renderFrame(frameAt(0));
  const std::vector<uint32_t> full = plain.probeCounts().focusPixels;
  plain.renderProbeFrame(frameAt(1));
  EXPECT_EQ(plain.probeCounts().focusPixels, full);
  auto upscaled = upscaler(scene);
  upscaled->setProbes(request);
  for (uint32_t frame = 0; frame < 3; ++frame) {
    upscaled->renderFrame(frameAt(frame));  // jittered pictures between the probe frames
    upscaled->renderProbeFrame(frameAt(frame));
    EXPECT_EQ(upscaled->probeCounts().focusPixels, full) << "probe frame " << frame;
  }
  EXPECT_GT(full[0], 0u);
  EXPECT_GT(full[1], 0u);
}

TEST_F(TemporalUpscaleTest, a_still_camera_takes_a_pixel_around_which_nothing_moved_as_held) {
  // Under a camera held still, a pixel whose four samples show nothing that moved takes the
  // history under it without reading their motions (RendererOptions::heldPointResolve). The
  // pictures must be those of the general path, byte for byte: the box sliding right (its
  // edges, and the wall it uncovers, whose history is dropped), resting four frames, sliding
  // back, and the lamp (a light seen) doing the same. (Where the history is kept, the held path
  // records the instance its history showed, not the sample's nearest in depth: along the outline
  // of something at rest the two may differ, and once it moves a pixel there may keep or drop
  // one frame's history otherwise. Not in these scenes: recording the nearest in depth gives the
  // same bytes here.)
  const auto run = [&](bool heldPoints, const scene::SceneDesc& scene, bool lamp) {
    render::RendererOptions options;
    options.width = kRenderWidth;
    options.height = kRenderHeight;
    options.outputWidth = kOutputWidth;
    options.outputHeight = kOutputHeight;
    options.heldPointResolve = heldPoints;
    render::Renderer renderer(context(), compiler(), scene, options);
    std::vector<std::vector<uint8_t>> pictures;
    for (uint32_t frame = 0; frame < 2 * kSlideFrames; ++frame) {
      // Right for 16 frames, still for kRestFrames (fewer than a steady view's), then back left.
      constexpr uint32_t kRestFrames = 4;
      const uint32_t back =
          frame < kSlideFrames + kRestFrames ? 0 : frame - kSlideFrames - kRestFrames + 1;
      const float x = slidTo(std::min(frame, kSlideFrames - 1) - back);
      if (lamp)
        renderer.setLightPose(kLampLight, lampAt(x).position, glm::vec3(0.0f));
      else
        moveBox(renderer, x);
      renderer.renderFrame(frameAt(frame));
      pictures.push_back(renderer.pixels());
    }
    return pictures;
  };
  for (const bool lamp : {false, true}) {
    SCOPED_TRACE(lamp ? "the lamp" : "the box");
    const scene::SceneDesc scene = lamp ? lampScene(slidTo(0)) : boxScene(slidTo(0));
    const auto held = run(true, scene, lamp), general = run(false, scene, lamp);
    ASSERT_EQ(held.size(), general.size());
    for (size_t frame = 0; frame < held.size(); ++frame) {
      size_t differing = 0;
      for (size_t i = 0; i < held[frame].size(); ++i)
        differing += held[frame][i] != general[frame][i];
      EXPECT_EQ(differing, 0u) << "frame " << frame;
    }
  }
}

TEST_F(TemporalUpscaleTest, running_each_pipeline_once_first_changes_no_picture) {
  // Play has the renderer run each pipeline once while a level loads
  // (Renderer::runEachPicturePipelineOnce). The frames after must be those a renderer that did
  // not gives, byte for byte: the box sliding right under a sphere light (soft shadows, so the
  // denoiser's passes run too), then resting until the view is steady, the camera held.
  scene::SceneDesc scene = boxScene(slidTo(0));
  scene.lights[0].type = scene::LightType::Sphere;
  scene.lights[0].radius = 0.3f;
  auto prepared = upscaler(scene);
  auto plain = upscaler(scene);
  ASSERT_TRUE(prepared->softShadows());
  // A frame each for a moving view, a held camera and a steady view, each said when done (what
  // a loading screen's bar follows).
  std::vector<std::pair<uint32_t, uint32_t>> steps;
  prepared->runEachPicturePipelineOnce(
      frameAt(0), [&](uint32_t done, uint32_t frames) { steps.emplace_back(done, frames); });
  EXPECT_EQ(steps, (std::vector<std::pair<uint32_t, uint32_t>>{{1, 3}, {2, 3}, {3, 3}}));
  constexpr uint32_t kSliding = 4;
  const uint32_t frames = kSliding + UPSCALE_STEADY_FRAMES_UNCLAMPED + 3;
  for (uint32_t frame = 0; frame < frames; ++frame) {
    for (render::Renderer* renderer : {prepared.get(), plain.get()}) {
      moveBox(*renderer, slidTo(std::min(frame, kSliding)));
      renderer->renderFrame(frameAt(frame));
    }
    ASSERT_EQ(prepared->pixels(), plain->pixels()) << "frame " << frame;
  }
  EXPECT_GE(prepared->steadyFrames(), UPSCALE_STEADY_FRAMES_UNCLAMPED);
  // After the first full frame there is a history it would disturb.
  EXPECT_THROW(prepared->runEachPicturePipelineOnce(frameAt(frames)), render::RenderError);
}

}  // namespace
