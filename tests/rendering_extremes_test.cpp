// Rendering extremes (docs/ROBUSTNESS.md, "Rendering extremes"): a level far from the origin or
// at odd scales, extreme light intensities and sizes, grazing light and thin walls, extreme
// fields of view, the camera inside geometry, mirror corridors at the bounce cap, degenerate
// meshes. Each test prints its measured error next to the limit it asserts.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "game/primitives.hpp"
#include "level_transforms.hpp"
#include "scene/color.hpp"
#include "scene_builder.hpp"
#include "vulkan_fixture.hpp"

namespace {

using scene::LightDesc;
using scene::LightType;
using scene::MaterialDesc;
using test::at;
using test::channel;
using test::SceneBuilder;

constexpr uint32_t kWidth = 160, kHeight = 90;
// The bar for "renders like": at most 0.5 % of pixels differ by more than 2/255.
constexpr int kChannelTolerance = 2;
constexpr double kMaxDifferingShare = 0.005;
const glm::vec3 kFarOffset(1e5f, 1e5f, 1e5f);

const char* const kShippedLevels[] = {"01_first_light",   "02_penumbra",     "03_glass_and_mirrors",
                                      "04_stained_glass", "05_mirror_chain", "06_night_watch",
                                      "07_crossing"};

int expectedByte(double linear) {
  return int(std::lround(255.0 * scene::linearToSrgb(float(std::clamp(linear, 0.0, 1.0)))));
}

bool allFinite(const std::vector<glm::vec4>& texels) {
  return std::all_of(texels.begin(), texels.end(), [](const glm::vec4& texel) {
    return std::isfinite(texel.x) && std::isfinite(texel.y) && std::isfinite(texel.z) &&
           std::isfinite(texel.w);
  });
}

MaterialDesc diffuse(float albedo) {
  MaterialDesc material;
  material.baseColor = glm::vec3(albedo);
  return material;
}

LightDesc sunAlong(const glm::vec3& direction, float irradiance) {
  LightDesc sun;
  sun.type = LightType::Directional;
  sun.direction = direction;
  sun.intensity = irradiance;
  return sun;
}

scene::CameraDesc lookingDown(const glm::vec3& position, float fovDegrees = 60.0f) {
  scene::CameraDesc camera;
  camera.position = position;
  camera.pitchDegrees = -90.0f;
  camera.verticalFovDegrees = fovDegrees;
  return camera;
}

// Where the camera ray of pixel (x, y) meets the floor y = 0 for lookingDown(height) (the
// renderer's camera basis looking straight down: image right is +X, image down is +Z).
glm::dvec2 floorPointOfPixel(uint32_t x, uint32_t y, uint32_t width, uint32_t height,
                             double cameraHeight, double fovDegrees) {
  const double tanHalf = std::tan(fovDegrees * M_PI / 360.0);
  const double aspect = double(width) / double(height);
  const double ndcX = (x + 0.5) / width * 2.0 - 1.0, ndcY = (y + 0.5) / height * 2.0 - 1.0;
  return {ndcX * tanHalf * aspect * cameraHeight, ndcY * tanHalf * cameraHeight};
}

class RenderingExtremesTest : public test::VulkanTest {
 protected:
  struct Frame {
    render::Rgba8Image image;
    std::vector<render::gpu::PixelPath> paths;
    std::vector<glm::vec4> radiance;   // linear, before exposure
    std::vector<glm::vec4> softLight;  // soft lights' unshadowed light (empty without them)
  };

  // Renders `frames` frames of a static view (sample sequences advancing) and returns the last.
  static Frame renderScene(const scene::SceneDesc& scene, const scene::CameraDesc& camera,
                           uint32_t width, uint32_t height, uint32_t frames = 1,
                           scene::Tonemap tonemap = scene::Tonemap::Aces, float exposure = 1.0f,
                           bool referenceAccumulation = false) {
    render::RendererOptions options;
    options.width = width;
    options.height = height;
    render::Renderer renderer(context(), compiler(), scene, options);
    scene::FrameDesc frame;
    frame.camera = camera;
    frame.tonemap = tonemap;
    frame.exposure = exposure;
    frame.referenceAccumulation = referenceAccumulation;
    for (uint32_t i = 0; i < frames; ++i) {
      frame.frameIndex = i;
      renderer.renderFrame(frame, i + 1 == frames);
    }
    Frame result{
        {width, height, renderer.pixels()}, renderer.pixelPaths(), renderer.readRadiance(), {}};
    if (renderer.softShadows())
      result.softLight = renderer.readDenoiser(render::DenoiserImage::SoftLight);
    return result;
  }

  static render::Rgba8Image renderLevelImage(const game::Level& level, uint32_t frames = 1) {
    return renderScene(game::buildSceneDesc(level), level.camera, kWidth, kHeight, frames).image;
  }

  static game::Level shippedLevel(const std::string& name) {
    return game::loadLevel(test::sourceDir() / "levels" / (name + ".json"));
  }

  static double differingShare(const render::Rgba8Image& expected,
                               const render::Rgba8Image& actual) {
    return render::compareImages(expected, actual, kChannelTolerance).differingFraction();
  }
};

// ----- Far from the origin and odd scales -----

// Render space is camera-relative (render/render_space.hpp), so what is left is the level's own
// rounding: at 1e5 a float holds positions only to 1/128 m, so each object and the camera move
// by up to 3.9 mm. The same rounded level moved back to the origin renders bit for bit the same.
TEST_F(RenderingExtremesTest,
       shipped_levels_translated_1e5_on_every_axis_render_like_at_the_origin) {
  for (const char* name : kShippedLevels) {
    const game::Level level = shippedLevel(name);
    const game::Level far = test::translatedLevel(level, kFarOffset);
    const render::Rgba8Image farImage = renderLevelImage(far);
    const double share = differingShare(renderLevelImage(level), farImage);
    std::printf("%s at +1e5: %.3f %% of pixels differ by more than 2/255 (limit 0.5 %%)\n", name,
                100.0 * share);
    EXPECT_LE(share, kMaxDifferingShare) << name;
    // The far level's floats, moved back: the same render-space numbers, so the same image.
    const game::Level roundedAtOrigin = test::translatedLevel(far, -kFarOffset);
    EXPECT_EQ(renderLevelImage(roundedAtOrigin).pixels, farImage.pixels) << name;
  }
}

// Soft shadows over frames while the camera walks and turns: reprojection works in render
// space (the previous camera relative to this one, instance motion conjugated to the origin).
TEST_F(RenderingExtremesTest, soft_shadow_level_far_from_the_origin_denoises_a_moving_view_alike) {
  const game::Level level = shippedLevel("02_penumbra");
  auto renderWalk = [&](const game::Level& walked) {
    render::RendererOptions options;
    options.width = kWidth;
    options.height = kHeight;
    render::Renderer renderer(context(), compiler(), game::buildSceneDesc(walked), options);
    scene::FrameDesc frame;
    frame.camera = walked.camera;
    for (uint32_t i = 0; i < 8; ++i) {
      frame.frameIndex = i;
      frame.camera.position.z -= 0.0625f;  // a walking pace, exact in floats at 1e5 too
      frame.camera.yawDegrees += 0.5f;
      renderer.renderFrame(frame, i == 7);
    }
    // Most of the view keeps its history through the walk (the rest is sky or disoccluded): a
    // restarted history has length 1, a reprojected one while moving at least 4.
    size_t kept = 0;
    for (const glm::vec4& moments : renderer.readDenoiser(render::DenoiserImage::Moments))
      kept += moments.z >= 4.0f;
    std::printf("history kept over 8 frames: %.1f %% of pixels\n",
                100.0 * double(kept) / double(kWidth * kHeight));
    EXPECT_GT(kept, kWidth * kHeight / 2) << "the history was not reprojected";
    return render::Rgba8Image{kWidth, kHeight, renderer.pixels()};
  };
  const double share =
      differingShare(renderWalk(level), renderWalk(test::translatedLevel(level, kFarOffset)));
  std::printf("02_penumbra walking at +1e5, 8 frames: %.3f %% differ (limit 0.5 %%)\n",
              100.0 * share);
  EXPECT_LE(share, kMaxDifferingShare);
}

// Lengths times 1e-3 or 1e4 (point lights times the square, so irradiance is unchanged): ray
// offsets scale with the hit's distance and the denoiser's depth tests are relative, so no
// fixed epsilon is too large for a small level or too small for a large one.
TEST_F(RenderingExtremesTest, shipped_levels_scaled_1e_minus_3_and_1e4_render_like_scale_1) {
  for (const char* name : kShippedLevels) {
    const game::Level level = shippedLevel(name);
    const render::Rgba8Image reference = renderLevelImage(level);
    for (const float factor : {1e-3f, 1e4f}) {
      const double share =
          differingShare(reference, renderLevelImage(test::scaledLevel(level, factor)));
      std::printf("%s scaled %g: %.3f %% differ (limit 0.5 %%)\n", name, factor, 100.0 * share);
      EXPECT_LE(share, kMaxDifferingShare) << name << " scaled " << factor;
    }
  }
}

// ----- Light -----

// Every light and emitter times 1e-6 .. 1e6. Radiance and the soft lights' unshadowed light stay
// finite, no pixel gets darker as the lights get brighter, everything the lights reach
// saturates to white at 1e6, and at 1e-6 the picture is the one with the lights off (ambient
// and sky only). Exposure brings either end back to the normal picture: nothing is clipped on
// the way (the soft lights' light was stored in half floats, which end at 65504 and lose
// precision below 6e-5).
TEST_F(RenderingExtremesTest, light_intensities_from_1e_minus_6_to_1e6_stay_finite_and_saturate) {
  for (const char* name : {"01_first_light", "02_penumbra", "06_night_watch"}) {
    const game::Level level = shippedLevel(name);
    const auto scaled = [&](float factor) {
      game::Level bright = level;
      for (LightDesc& light : bright.lights) light.intensity *= factor;
      for (MaterialDesc& material : bright.materials) material.emissive *= factor;
      return renderScene(game::buildSceneDesc(bright), level.camera, 64, 36, 2);
    };
    const Frame dark = scaled(0.0f);
    const Frame normal = scaled(1.0f);
    Frame previous = dark;
    size_t darkened = 0, unsaturated = 0, lowDifferences = 0;
    for (const float factor : {1e-6f, 1e-3f, 1.0f, 1e3f, 1e6f}) {
      const Frame frame = scaled(factor);
      EXPECT_TRUE(allFinite(frame.radiance)) << name << " x" << factor;
      EXPECT_TRUE(allFinite(frame.softLight)) << name << " x" << factor;
      for (size_t i = 0; i < frame.image.pixels.size(); ++i) {
        if (i % 4 == 3) continue;
        darkened += frame.image.pixels[i] < previous.image.pixels[i];
        if (factor == 1e-6f)
          lowDifferences += std::abs(frame.image.pixels[i] - dark.image.pixels[i]) > 1;
        if (factor == 1e6f && normal.image.pixels[i] > dark.image.pixels[i])
          unsaturated += frame.image.pixels[i] != 255;
      }
      previous = frame;
    }
    std::printf(
        "%s: %zu channels darker at a brighter step, %zu lit channels short of 255 at "
        "1e6, %zu channels off the lights-off picture by > 1/255 at 1e-6 (limits 0)\n",
        name, darkened, unsaturated, lowDifferences);
    EXPECT_EQ(darkened, 0u) << name;
    EXPECT_EQ(unsaturated, 0u) << name;
    EXPECT_EQ(lowDifferences, 0u) << name;
    // The whole range is kept, not clipped: all light (sky and ambient too) times 1e6 or 1e-6
    // under an exposure of the inverse is the normal picture.
    for (const float factor : {1e-6f, 1e6f}) {
      game::Level scaledLevel = level;
      for (LightDesc& light : scaledLevel.lights) light.intensity *= factor;
      for (MaterialDesc& material : scaledLevel.materials) material.emissive *= factor;
      scaledLevel.environment.skyZenith *= factor;
      scaledLevel.environment.skyHorizon *= factor;
      scaledLevel.environment.ambient *= factor;
      const Frame exposed = renderScene(game::buildSceneDesc(scaledLevel), level.camera, 64, 36, 2,
                                        scene::Tonemap::Aces, 1.0f / factor);
      const double share = differingShare(normal.image, exposed.image);
      std::printf("%s: all light x%g under exposure 1/%g: %.3f %% differ from x1 (limit 0.5 %%)\n",
                  name, factor, factor, 100.0 * share);
      EXPECT_LE(share, kMaxDifferingShare) << name << " x" << factor;
    }
  }
}

// A white floor under a slab, lit from above-left; the camera looks straight down.
scene::SceneDesc slabOnFloor(const LightDesc& light) {
  SceneBuilder builder;
  const uint32_t white = builder.material(diffuse(1.0f));
  builder.instance(builder.mesh(game::primitives::plane(40, 40)), white, glm::mat4(1.0f));
  builder.instance(builder.mesh(game::primitives::box({0.6f, 0.05f, 0.6f})), white,
                   at({0, 0.5f, 0}));
  builder.light(light);
  return builder.scene;
}

// Sphere, disk and rectangle lights 1 mm across carrying the same intensity as a point light
// at their centre give its light and its hard shadow: on the floor each pixel's linear
// radiance (unshadowed light times the plain average of the visibility samples) equals the
// point light's, times the emission cosine for the one-sided disk and rectangle.
TEST_F(RenderingExtremesTest, area_lights_of_size_1mm_match_the_point_light_and_its_hard_shadow) {
  const glm::vec3 centre(0.4f, 2.0f, 0.0f);
  const float intensity = 4.0f;  // W/sr
  LightDesc point;
  point.position = centre;
  point.intensity = intensity;
  const scene::CameraDesc camera = lookingDown({0, 1.6f, 0}, 60.0f);
  const Frame hard = renderScene(slabOnFloor(point), camera, 64, 64, 1, scene::Tonemap::Identity);
  const float size = 1e-3f;
  for (const LightType type : {LightType::Sphere, LightType::Disk, LightType::Rectangle}) {
    LightDesc area = point;
    area.type = type;
    area.radius = 0.5f * size;
    area.size = glm::vec2(size);
    area.direction = glm::vec3(0, -1, 0);
    const float lightArea =
        type == LightType::Rectangle ? size * size : float(M_PI) * 0.25f * size * size;
    area.intensity = intensity / lightArea;  // radiance times area: the point light's intensity
    // Plain averages of the visibility samples: the light's own shadow, not the denoiser's
    // first frames (which soften any edge until its history builds up).
    render::RendererOptions options;
    options.width = options.height = 64;
    render::Renderer renderer(context(), compiler(), slabOnFloor(area), options);
    scene::FrameDesc frame;
    frame.camera = camera;
    frame.referenceAccumulation = true;
    for (uint32_t i = 0; i < 4; ++i) {
      frame.frameIndex = i;
      renderer.renderFrame(frame, false);
    }
    const auto softLight = renderer.readDenoiser(render::DenoiserImage::SoftLight);
    const auto visibility = renderer.readDenoiser(render::DenoiserImage::Denoised);
    size_t compared = 0, shadowed = 0, differing = 0;
    double worst = 0.0;
    for (uint32_t y = 0; y < 64; ++y) {
      for (uint32_t x = 0; x < 64; ++x) {
        const glm::dvec2 floor = floorPointOfPixel(x, y, 64, 64, 1.6, 60.0);
        // The slab's top hides the floor out to 0.3 * 1.6 / (1.6 - 0.525) = 0.45 m.
        if (std::abs(floor.x) < 0.46 && std::abs(floor.y) < 0.46) continue;
        const glm::dvec3 toLight = glm::dvec3(centre) - glm::dvec3(floor.x, 0.0, floor.y);
        const double emission = type == LightType::Sphere ? 1.0 : 2.0 / glm::length(toLight);
        const size_t i = size_t(y) * 64 + x;
        const double expected = hard.radiance[i].x * emission;
        const double actual = double(softLight[i].x) * visibility[i].x;
        ++compared;
        shadowed += expected == 0.0;
        const double error = std::abs(actual - expected) / std::max(expected, 1e-3);
        worst = std::max(worst, error);
        differing += error > 1e-4;
      }
    }
    std::printf(
        "light type %u of 1 mm: %zu of %zu floor pixels (%zu in shadow) differ from the point "
        "light by over 0.01 %%, largest %.2g (limit 0)\n",
        unsigned(type), differing, compared, shadowed, worst);
    EXPECT_GT(compared, 1000u);
    EXPECT_GT(shadowed, 50u);
    EXPECT_EQ(differing, 0u) << unsigned(type);
  }
}
// A sphere light 1 km in radius 3 m above the floor fills the sky down to 4.4 degrees: light
// arrives evenly from everywhere, like ambient light, and the slab only occludes part of it.
// Visibility is the unoccluded share of the sampled cone (uniform in solid angle): under the
// slab's centre the slab hides 4 asin(a^2 / (a^2 + 4h^2)) sr of the cone's 2 pi (1 - cos).
TEST_F(RenderingExtremesTest, huge_sphere_light_lights_evenly_and_its_shadow_is_ambient_occlusion) {
  LightDesc sky;
  sky.type = LightType::Sphere;
  sky.radius = 1000.0f;
  sky.position = glm::vec3(0.0f, 1003.0f, 0.0f);
  sky.intensity = 1.0f;  // radiance
  const scene::SceneDesc scene = slabOnFloor(sky);
  render::RendererOptions options;
  options.width = 48;
  options.height = 48;
  render::Renderer renderer(context(), compiler(), scene, options);
  scene::FrameDesc frame;
  frame.camera = lookingDown({0, 0.45f, 0}, 150.0f);  // under the slab, seeing the floor around
  frame.tonemap = scene::Tonemap::Identity;
  frame.referenceAccumulation = true;
  for (uint32_t i = 0; i < 256; ++i) {
    frame.frameIndex = i;
    renderer.renderFrame(frame, false);
  }
  const auto visibility = renderer.readDenoiser(render::DenoiserImage::Denoised);
  const auto softLight = renderer.readDenoiser(render::DenoiserImage::SoftLight);
  ASSERT_TRUE(allFinite(softLight));
  const double slabHalf = 0.3, height = 0.5 - 0.025;
  const double hidden =
      4.0 * std::asin((4 * slabHalf * slabHalf) / (4 * slabHalf * slabHalf + 4 * height * height));
  const double sinMax = 1000.0 / 1003.0;
  const double cone = 2.0 * M_PI * (1.0 - std::sqrt(1.0 - sinMax * sinMax));
  const double expected = 1.0 - hidden / cone;
  const float centre = visibility[24 * 48 + 24].g;
  // Unshadowed light: pi L sin^2 at normal incidence; within 1 % wherever the floor is seen.
  const double unshadowed = sinMax * sinMax;  // albedo 1: radiance = E / pi = L sin^2
  double worstLight = 0.0;
  for (uint32_t y = 0; y < 48; ++y) {
    for (uint32_t x = 0; x < 48; ++x) {
      worstLight = std::max(worstLight, std::abs(softLight[y * 48 + x].g / unshadowed - 1.0));
    }
  }
  std::printf(
      "huge sphere light: visibility under the slab %.4f (expected %.4f, limit +-0.03); "
      "unshadowed light within %.3f %% of pi L sin^2 (limit 1 %%)\n",
      centre, expected, 100.0 * worstLight);
  EXPECT_NEAR(centre, expected, 0.03);
  EXPECT_LE(worstLight, 0.01);
}

// A sun 0.1 degrees above the horizon (89.9 degrees from the floor's normal) lights the floor
// at cos 89.9 = 1.745e-3 of its irradiance, without self-shadowing acne; a 1 mm wall casts a
// shadow the light does not leak through. At the origin and 1e5 away.
TEST_F(RenderingExtremesTest, grazing_sun_at_89_9_degrees_gives_no_acne_and_a_1mm_wall_no_leak) {
  const double grazing = glm::radians(89.9);
  const glm::vec3 travel(float(std::sin(grazing)), -float(std::cos(grazing)), 0.0f);
  const double lit = std::cos(grazing) / M_PI;  // albedo 1, irradiance 1
  const float exposure = float(0.5 / lit);
  for (const glm::vec3 offset : {glm::vec3(0.0f), kFarOffset}) {
    SceneBuilder builder;
    const uint32_t white = builder.material(diffuse(1.0f));
    builder.instance(builder.mesh(game::primitives::plane(40, 40)), white, at(offset));
    // A 1 mm wall across the light, at x = 0 from z = -20 to 20, 0.5 m high; its shadow
    // reaches 286 m along +X, past everything the camera sees.
    builder.instance(builder.mesh(game::primitives::box({0.001f, 0.5f, 40.0f})), white,
                     at(offset + glm::vec3(0.0f, 0.25f, 0.0f)));
    builder.light(sunAlong(travel, 1.0f));
    const scene::CameraDesc camera = lookingDown(offset + glm::vec3(0.0f, 2.0f, 0.0f), 60.0f);
    const Frame frame =
        renderScene(builder.scene, camera, 64, 36, 1, scene::Tonemap::Identity, exposure);
    const int litByte = expectedByte(0.5);
    size_t acne = 0, leaks = 0, litPixels = 0, shadowPixels = 0;
    for (uint32_t y = 0; y < 36; ++y) {
      for (uint32_t x = 0; x < 64; ++x) {
        const glm::dvec2 floor = floorPointOfPixel(x, y, 64, 36, 2.0, 60.0);
        if (std::abs(floor.x) < 0.02) continue;  // the wall's top and its pixel column
        const int value = channel(frame.image, x, y, 0);
        if (floor.x < 0.0) {
          ++litPixels;
          acne += std::abs(value - litByte) > 1;
        } else {
          ++shadowPixels;
          leaks += value != 0;
        }
      }
    }
    std::printf(
        "grazing sun at offset %g: %zu of %zu lit pixels off the analytic value by > 1/255,"
        " %zu of %zu shadowed pixels not black (limits 0)\n",
        offset.x, acne, litPixels, leaks, shadowPixels);
    EXPECT_GT(litPixels, 500u);
    EXPECT_GT(shadowPixels, 500u);
    EXPECT_EQ(acne, 0u);
    EXPECT_EQ(leaks, 0u);
  }
}

// ----- Cameras -----

// A point light 2 m above a white floor seen from 1 m straight down: every pixel is the
// analytic I cos / d^2 / pi, with a vertical field of view of 170 degrees (the image reaches
// 20 m sideways, rays nearly parallel to the floor) and of 1 degree (the image is 3 cm wide;
// a hard shadow edge placed in it lands on the predicted pixel column).
TEST_F(RenderingExtremesTest, fields_of_view_of_1_and_170_degrees_match_the_analytic_floor) {
  const uint32_t width = 96, height = 54;
  SceneBuilder builder;
  const uint32_t white = builder.material(diffuse(1.0f));
  builder.instance(builder.mesh(game::primitives::plane(200, 200)), white, glm::mat4(1.0f));
  LightDesc bulb;
  bulb.position = glm::vec3(0, 2, 0);
  bulb.intensity = 10.0f;
  builder.light(bulb);
  const float exposure = 0.25f;
  for (const double fov : {170.0, 60.0}) {
    const Frame frame = renderScene(builder.scene, lookingDown({0, 1, 0}, float(fov)), width,
                                    height, 1, scene::Tonemap::Identity, exposure);
    int worst = 0;
    for (uint32_t y = 0; y < height; ++y) {
      for (uint32_t x = 0; x < width; ++x) {
        const glm::dvec2 floor = floorPointOfPixel(x, y, width, height, 1.0, fov);
        const double squaredDistance = glm::dot(floor, floor) + 4.0;
        const double radiance = 10.0 * (2.0 / std::sqrt(squaredDistance)) / squaredDistance / M_PI;
        worst = std::max(
            worst, std::abs(channel(frame.image, x, y, 0) - expectedByte(exposure * radiance)));
      }
    }
    std::printf("field of view %g: largest difference from the analytic floor %d/255 (limit 1)\n",
                fov, worst);
    EXPECT_LE(worst, 1) << fov;
  }
  // 1 degree: a slab's hard shadow edge at floor x = 5 mm (the image spans +-15.5 mm), sun
  // along (1, -1, 0).
  SceneBuilder shadowed;
  const uint32_t paint = shadowed.material(diffuse(1.0f));
  shadowed.instance(shadowed.mesh(game::primitives::plane(40, 40)), paint, glm::mat4(1.0f));
  shadowed.instance(shadowed.mesh(game::primitives::box({1.0f, 0.02f, 1.0f})), paint,
                    at({-0.305f - 0.5f, 0.3f, 0.0f}));  // right edge x = -0.305, top 0.31
  shadowed.light(sunAlong({1, -1, 0}, 1.0f));
  const Frame narrow = renderScene(shadowed.scene, lookingDown({0, 1, 0}, 1.0f), width, height, 1,
                                   scene::Tonemap::Identity);
  size_t misplaced = 0;
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const double floorX = floorPointOfPixel(x, y, width, height, 1.0, 1.0).x;
      // Rays to the light along (-1, 1, 0) pass the slab's top corner at floor x = 0.005.
      const double edge = -0.305 + 0.31;
      if (std::abs(floorX - edge) < 1e-5) continue;  // on the edge itself
      const bool shadow = floorX < edge;
      misplaced += (channel(narrow.image, x, y, 0) == 0) != shadow;
    }
  }
  std::printf("field of view 1: %zu pixels on the wrong side of a shadow edge (limit 0)\n",
              misplaced);
  EXPECT_EQ(misplaced, 0u);
}

// The camera inside a closed box (sun and lamp outside): every ray hits the box's inside,
// every shadow ray is blocked by it, so each pixel is exactly albedo times ambient.
TEST_F(RenderingExtremesTest, camera_inside_a_closed_box_sees_its_inside_lit_only_by_ambient) {
  SceneBuilder builder;
  const uint32_t box = builder.instance(builder.mesh(game::primitives::box({2, 2, 2})),
                                        builder.material(diffuse(0.5f)), at({0, 1, 0}));
  builder.light(sunAlong({0.3f, -1, 0.2f}, 5.0f));
  LightDesc lamp;
  lamp.position = glm::vec3(0, 3, 0);
  lamp.intensity = 50.0f;
  builder.light(lamp);
  builder.scene.environment.ambient = glm::vec3(0.4f);
  builder.scene.environment.skyHorizon = glm::vec3(1.0f);
  scene::CameraDesc camera;
  camera.position = glm::vec3(0.2f, 1.0f, 0.1f);
  camera.yawDegrees = 30.0f;
  camera.verticalFovDegrees = 120.0f;
  const Frame frame = renderScene(builder.scene, camera, 48, 32, 1, scene::Tonemap::Identity);
  const int expected = expectedByte(0.5 * 0.4);
  size_t wrong = 0;
  for (uint32_t i = 0; i < 48 * 32; ++i) {
    wrong += frame.paths[i].finalInstance != box;
    for (int c = 0; c < 3; ++c) wrong += std::abs(frame.image.pixels[i * 4 + c] - expected) > 1;
  }
  std::printf("camera inside a box: %zu wrong pixels or paths (limit 0)\n", wrong);
  EXPECT_EQ(wrong, 0u);
}

// A corridor of two facing mirrors, 2 m apart, with a lit floor: rays glance down it and bounce
// up to the 31-bounce cap (the pipeline's deepest). Nothing non-finite, the cap holds, and
// 1e5 from the origin it renders like at the origin. Its positions are multiples of 1/128, exact
// in floats at 1e5 too: over 31 bounces the level's own rounding (up to 3.9 mm a wall) would
// add up to centimetres, and this measures the renderer.
TEST_F(RenderingExtremesTest, mirror_corridor_at_the_31_bounce_cap_renders_alike_far_away) {
  auto corridor = [](const glm::vec3& offset) {
    SceneBuilder builder;
    MaterialDesc silver;
    silver.kind = scene::MaterialKind::Mirror;
    silver.mirrorTint = glm::vec3(0.95f);
    const uint32_t mirror = builder.material(silver);
    const uint32_t wall = builder.mesh(game::primitives::box({0.25f, 4.0f, 400.0f}));
    builder.instance(wall, mirror, at(offset + glm::vec3(-1.125f, 2.0f, 0.0f)));
    builder.instance(wall, mirror, at(offset + glm::vec3(1.125f, 2.0f, 0.0f)));
    builder.instance(builder.mesh(game::primitives::plane(2.0f, 400.0f)),
                     builder.material(diffuse(0.8f)), at(offset));
    builder.light(sunAlong({0.2f, -1.0f, -0.3f}, 3.0f));
    builder.scene.environment.skyHorizon = glm::vec3(0.3f);
    builder.scene.environment.ambient = glm::vec3(0.05f);
    builder.scene.maxMirrorBounces = 31;
    return builder.scene;
  };
  scene::CameraDesc camera;
  camera.yawDegrees = 80.0f;  // mostly across the corridor, so rays bounce many times
  camera.pitchDegrees = -3.0f;
  camera.position = glm::vec3(0.0f, 1.75f, 0.0f);
  const Frame near = renderScene(corridor(glm::vec3(0.0f)), camera, 96, 54);
  camera.position += kFarOffset;
  const Frame far = renderScene(corridor(kFarOffset), camera, 96, 54);
  uint32_t deepest = 0;
  size_t capped = 0;
  for (const auto& path : far.paths) {
    deepest = std::max(deepest, path.bounces);
    capped += path.bounces == 31;
  }
  const double share = differingShare(near.image, far.image);
  std::printf(
      "mirror corridor: deepest path %u bounces, %zu pixels at the cap; at +1e5 %.3f %% "
      "differ (limit 0.5 %%)\n",
      deepest, capped, 100.0 * share);
  EXPECT_TRUE(allFinite(near.radiance));
  EXPECT_TRUE(allFinite(far.radiance));
  EXPECT_EQ(deepest, 31u);
  EXPECT_GT(capped, 0u);
  EXPECT_LE(share, kMaxDifferingShare);
}

// ----- Meshes -----

// A floor mesh handed to the renderer with zero-area triangles (a repeated index, collinear
// corners, three corners at one point), every triangle again over duplicated vertices, and
// zero vertex normals: it renders exactly like the clean quad with its normals. (The glTF
// loader drops degenerate triangles and computes missing normals before this point:
// tests/gltf_model_test.cpp.)
TEST_F(RenderingExtremesTest, degenerate_triangles_duplicates_and_zero_normals_render_like_clean) {
  auto scene = [](const scene::MeshData& floor) {
    SceneBuilder builder;
    const uint32_t paint = builder.material(diffuse(0.8f));
    builder.instance(builder.mesh(floor), paint, glm::mat4(1.0f));
    builder.instance(builder.mesh(game::primitives::box({0.4f, 0.02f, 0.4f})), paint,
                     at({0, 0.3f, 0}));
    builder.light(sunAlong({1, -1, 0.5f}, 2.0f));
    builder.scene.environment.ambient = glm::vec3(0.1f);
    return builder.scene;
  };
  const scene::MeshData clean = game::primitives::plane(10, 10);
  scene::MeshData messy = clean;
  for (scene::Vertex& vertex : messy.vertices) vertex.normal = glm::vec3(0.0f);
  const uint32_t base = uint32_t(messy.vertices.size());
  for (const uint32_t index : clean.indices) messy.vertices.push_back(messy.vertices[index]);
  for (uint32_t i = 0; i < clean.indices.size(); ++i) messy.indices.push_back(base + i);
  // Halfway along the edge from vertex 0 to vertex 1: collinear with both.
  messy.vertices.push_back({0.5f * (clean.vertices[0].position + clean.vertices[1].position)});
  const uint32_t onEdge = uint32_t(messy.vertices.size() - 1);
  messy.indices.insert(messy.indices.end(), {0, 0, 2, 0, 1, onEdge, 3, 3, 3});
  const scene::CameraDesc camera = lookingDown({0.1f, 1.5f, 0.2f}, 70.0f);
  const Frame expected = renderScene(scene(clean), camera, 64, 64, 1, scene::Tonemap::Identity);
  const Frame actual = renderScene(scene(messy), camera, 64, 64, 1, scene::Tonemap::Identity);
  const render::ImageDifference difference = render::compareImages(expected.image, actual.image, 0);
  std::printf("degenerate, duplicated, normal-less floor: %llu pixels differ at all (limit 0)\n",
              static_cast<unsigned long long>(difference.differingPixels));
  EXPECT_EQ(difference.differingPixels, 0u);
  EXPECT_TRUE(allFinite(actual.radiance));
}

}  // namespace
