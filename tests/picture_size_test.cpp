// A picture smaller than the render size (the dynamic render scale): full frames trace the
// top-left part of the images, probe frames keep the whole size, and the denoiser's and the
// upscaler's histories carry across a change of size.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "game/level_loader.hpp"
#include "game/primitives.hpp"
#include "render/image_metrics.hpp"
#include "render/temporal_upscaler.hpp"
#include "render/vulkan_error.hpp"
#include "scene_builder.hpp"
#include "shaders/shared_types.h"
#include "sim/simulation.hpp"
#include "vulkan_fixture.hpp"

namespace {

using render::DenoiserImage;
using test::at;
using test::SceneBuilder;

constexpr uint32_t kFull = 48;  // the render size (square)
constexpr uint32_t kHalf = 24;  // the smaller picture
constexpr float kFresh = float(DENOISER_FRESH_HISTORY_FRAMES);

// A white floor seen from above, a slab 0.5 m up shading it from a sphere light (soft shadows,
// so the denoiser runs), as tests/soft_shadow_test.cpp has it.
scene::SceneDesc slabScene() {
  SceneBuilder builder;
  scene::MaterialDesc white;
  white.baseColor = glm::vec3(1.0f);
  const uint32_t paint = builder.material(white);
  builder.instance(builder.mesh(game::primitives::plane(20, 20)), paint, glm::mat4(1.0f));
  builder.instance(builder.mesh(game::primitives::box({0.6f, 0.05f, 0.6f})), paint,
                   at({0.0f, 0.5f, 0.0f}));
  scene::LightDesc light;
  light.type = scene::LightType::Sphere;
  light.position = glm::vec3(0.3f, 2.0f, 0.0f);
  light.radius = 0.4f;
  light.intensity = 10.0f;
  builder.light(light);
  return builder.scene;
}

scene::FrameDesc topView(uint32_t index) {
  scene::FrameDesc frame;
  frame.camera.position = glm::vec3(0.0f, 1.6f, 0.0f);
  frame.camera.pitchDegrees = -90.0f;
  frame.camera.verticalFovDegrees = 70.0f;
  frame.tonemap = scene::Tonemap::Identity;
  frame.frameIndex = index;
  return frame;
}

std::vector<float> red(const std::vector<glm::vec4>& texels, uint32_t rowLength, uint32_t width,
                       uint32_t height) {
  std::vector<float> values;
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) values.push_back(texels[size_t(y) * rowLength + x].r);
  return values;
}

class PictureSizeTest : public test::VulkanTest {
 protected:
  static std::unique_ptr<render::Renderer> renderer(uint32_t size) {
    render::RendererOptions options;
    options.width = size;
    options.height = size;
    return std::make_unique<render::Renderer>(context(), compiler(), slabScene(), options);
  }
};

TEST_F(PictureSizeTest, a_smaller_picture_is_exactly_a_render_of_that_size) {
  auto large = renderer(kFull);
  auto native = renderer(kHalf);
  large->setPictureSize(kHalf, kHalf);
  EXPECT_EQ(large->shownWidth(), kFull);  // the image holds the last frame's picture until then
  for (uint32_t frame = 0; frame < 4; ++frame) {
    large->renderFrame(topView(frame));
    native->renderFrame(topView(frame));
    ASSERT_EQ(large->shownWidth(), kHalf);
    ASSERT_EQ(large->pixels().size(), size_t(kHalf) * kHalf * 4);
    // The same rays, samples, denoiser passes and tonemap, byte for byte.
    ASSERT_EQ(large->pixels(), native->pixels()) << "frame " << frame;
  }
}

TEST_F(PictureSizeTest, the_denoiser_keeps_its_history_across_a_change_of_picture_size) {
  constexpr uint32_t kFrames = 12;
  // The converged view at the smaller size: 64 frames of raw samples averaged.
  auto reference = renderer(kHalf);
  for (uint32_t frame = 0; frame < 64; ++frame) {
    scene::FrameDesc accumulate = topView(1000 + frame);
    accumulate.referenceAccumulation = true;
    reference->renderFrame(accumulate, false);
  }
  const std::vector<float> expected =
      red(reference->readDenoiser(DenoiserImage::Denoised), kHalf, kHalf, kHalf);
  auto errorOf = [&](const render::Renderer& r, uint32_t rowLength) {
    return render::rootMeanSquareError(
        expected, red(r.readDenoiser(DenoiserImage::Denoised), rowLength, kHalf, kHalf));
  };
  // The first frame at the smaller size after 12 at the whole size, against the first frame of
  // a renderer that starts at the smaller size (no history: it traces several frames' worth).
  auto changed = renderer(kFull);
  for (uint32_t frame = 0; frame < kFrames; ++frame) changed->renderFrame(topView(frame), false);
  changed->setPictureSize(kHalf, kHalf);
  changed->renderFrame(topView(kFrames), false);
  auto fresh = renderer(kHalf);
  fresh->renderFrame(topView(kFrames), false);
  const double changedError = errorOf(*changed, kFull);
  const double freshError = errorOf(*fresh, kHalf);
  std::printf(
      "RMSE against 64 frames' samples: the first frame after the change %.5f, a fresh "
      "start's %.5f\n",
      changedError, freshError);
  // Each pixel finds the point it shows in the larger picture's history, resampled: better than
  // a fresh start with its several frames' worth of samples.
  EXPECT_LT(changedError, freshError);
}

TEST_F(PictureSizeTest, a_picture_size_outside_the_render_size_is_refused) {
  auto r = renderer(kHalf);
  EXPECT_THROW(r->setPictureSize(kHalf + 1, kHalf), render::RenderError);
  EXPECT_THROW(r->setPictureSize(kHalf, 0), render::RenderError);
  r->setPictureSize(1, 1);
  EXPECT_EQ(r->pictureWidth(), 1u);
}

// The upscaler's history is at the output size: changing the picture size under it keeps what
// it has gathered (a static view stays about as close to the reference as held at one size).
TEST_F(PictureSizeTest, temporal_upscaling_keeps_its_history_while_the_picture_size_changes) {
  auto upscaler = [&] {
    render::RendererOptions options;
    options.width = kFull;
    options.height = kFull;
    options.outputWidth = 2 * kFull;
    options.outputHeight = 2 * kFull;
    return std::make_unique<render::Renderer>(context(), compiler(), slabScene(), options);
  };
  auto green = [](const std::vector<uint8_t>& pixels) {
    std::vector<float> values;
    for (size_t i = 1; i < pixels.size(); i += 4) values.push_back(float(pixels[i]) / 255.0f);
    return values;
  };
  auto held = upscaler();
  auto changing = upscaler();
  constexpr uint32_t kStill = 16, kChanging = 8;
  for (uint32_t frame = 0; frame < kStill; ++frame) {
    held->renderFrame(topView(frame));
    changing->renderFrame(topView(frame));
  }
  const std::vector<float> settled = green(held->pixels());
  for (uint32_t frame = kStill; frame < kStill + kChanging; ++frame) {
    const uint32_t size = frame % 2 ? kHalf : kHalf + kHalf / 2;
    changing->setPictureSize(size, size);
    changing->renderFrame(topView(frame));
    held->renderFrame(topView(frame));
  }
  // The same output as a picture that kept its size would give after a plain upscale of the
  // smallest picture, for scale.
  auto plain = upscaler();
  plain->setPictureSize(kHalf, kHalf);
  plain->renderFrame(topView(0));
  const std::vector<float> target = green(held->pixels());
  const double changingError = render::rootMeanSquareError(target, green(changing->pixels()));
  const double plainError = render::rootMeanSquareError(target, green(plain->pixels()));
  const double drift = render::rootMeanSquareError(target, settled);
  std::printf(
      "RMSE against the held view: changing sizes %.5f, one plain frame %.5f (held "
      "view's own drift %.5f)\n",
      changingError, plainError, drift);
  ASSERT_EQ(changing->pixels().size(), size_t(4 * kFull * kFull) * 4);
  EXPECT_LT(changingError, 0.5 * plainError);
}

// What the rules read comes from probe frames at the whole render size, whatever size the
// pictures between them had (upscaled temporally, as play does, or not).
TEST_F(PictureSizeTest, probe_readings_do_not_depend_on_the_picture_size) {
  const game::Level level = game::loadLevel(test::sourceDir() / "levels" / "01_first_light.json");
  auto run = [&](bool changeSizes, bool upscale) {
    sim::SimulationOptions options{32, 18, 2, 1};
    if (upscale) {
      options.outputWidth = 64;
      options.outputHeight = 36;
    }
    sim::Simulation simulation(context(), compiler(), level, options);
    std::vector<float> trace;
    for (uint32_t step = 0; step < 40; ++step) {
      game::TickInput input;
      input.move = {0.1f, 1.0f};
      input.yawDeltaDegrees = step < 20 ? 0.4f : -0.3f;
      simulation.step(input);
      if (changeSizes) simulation.renderer().setPictureSize(8 + step % 24, 5 + step % 13);
      simulation.renderPicture(false);
      if (simulation.latestReadings())
        trace.insert(trace.end(), simulation.latestReadings()->focusCoverage.begin(),
                     simulation.latestReadings()->focusCoverage.end());
    }
    return trace;
  };
  const std::vector<float> whole = run(false, false);
  ASSERT_FALSE(whole.empty());
  float highest = 0.0f;
  for (float coverage : whole) highest = std::max(highest, coverage);
  EXPECT_GT(highest, 0.0f);  // the orb is in view: the comparison below compares something
  EXPECT_EQ(run(true, false), whole);
  EXPECT_EQ(run(true, true), whole);
}

}  // namespace
