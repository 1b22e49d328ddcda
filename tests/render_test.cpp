// Image tests on the real Vulkan device (lavapipe in CI), validation layer on.
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "render/fence_wait.hpp"
#include "render/vulkan_error.hpp"
#include "scene/color.hpp"
#include "vulkan_fixture.hpp"

namespace {

using test::channel;
using test::VulkanTest;

// A camera 1 m above a large Lambert plane, looking straight down; no sky, no ambient.
std::string planeLevel(const std::string& colour, const std::string& lights,
                       const std::string& extraMeshes = "", const std::string& extraEntities = "") {
  return R"({
    "format": 1, "name": "analytic plane",
    "camera": {"position": [0, 1, 0], "pitch_degrees": -90, "fov_degrees": 60},
    "materials": {"lambert": {"color": )" +
         colour + R"(, "specular": 0}},
    "meshes": {"plane": {"plane": {"size": [100, 100]}})" +
         extraMeshes + R"(},
    "entities": {"floor": {"mesh": "plane", "material": "lambert"})" +
         extraEntities + R"(},
    "lights": {)" +
         lights + R"(}
  })";
}

// A 0.3 m block on the plane, its shadow cast sideways by a slanting sun.
game::Level blockOnPlaneLevel() {
  return game::parseLevel(
      planeLevel("[0.8, 0.8, 0.8]",
                 R"("sun": {"type": "directional", "direction": [1, -1, 0], "intensity": 2.0})",
                 R"(, "block": {"box": {"size": [0.3, 0.3, 0.3]}})",
                 R"(, "block": {"mesh": "block", "material": "lambert", "position": [0, 0.3, 0]})"),
      test::sourceDir() / "tests" / "inline_level.json");
}

int expectedByte(double linearRadiance) {
  return int(std::lround(255.0 * scene::linearToSrgb(float(std::min(linearRadiance, 1.0)))));
}

TEST_F(VulkanTest, lambert_plane_under_directional_light_matches_rho_e_over_pi) {
  const float encodedAlbedo = 0.8f;
  const double albedo = scene::srgbToLinear(encodedAlbedo);
  const double irradiance = 2.0;
  const auto image = renderLevelText(
      planeLevel("[0.8, 0.8, 0.8]",
                 R"("sun": {"type": "directional", "direction": [0, -1, 0], "intensity": 2.0})"),
      33, 33, scene::Tonemap::Identity);
  const int expected = expectedByte(albedo * irradiance / M_PI);  // 0.38439 -> 0.65529 -> 167
  EXPECT_EQ(expected, 167);
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(channel(image, x, y, c), expected, 1) << x << "," << y;
}

// glTF's metallic-roughness BRDF, written out here from the spec's appendix B: a metal plane
// seen straight down under a sun 30 degrees from the vertical keeps its base colour.
TEST_F(VulkanTest, metal_plane_renders_what_the_metallic_roughness_brdf_predicts) {
  const auto image = renderLevelText(R"({
    "format": 1, "name": "analytic metal",
    "camera": {"position": [0, 1, 0], "pitch_degrees": -90, "fov_degrees": 60},
    "materials": {"copper": {"color": [1.0, 0.5, 0.2], "metallic": 1, "roughness": 0.5}},
    "meshes": {"plane": {"plane": {"size": [100, 100]}}},
    "entities": {"floor": {"mesh": "plane", "material": "copper"}},
    "lights": {"sun": {"type": "directional", "direction": [-0.5, -0.8660254, 0], "intensity": 2.0}}
  })",
                                     33, 33, scene::Tonemap::Identity);
  const glm::dvec3 n(0, 1, 0), v(0, 1, 0), l(0.5, 0.8660254, 0);
  const glm::dvec3 h = glm::normalize(l + v);
  const double alpha = 0.5 * 0.5, alpha2 = alpha * alpha;
  const double nDotL = glm::dot(n, l), nDotV = 1.0, nDotH = glm::dot(n, h), vDotH = glm::dot(v, h);
  const double d = nDotH * nDotH * (alpha2 - 1.0) + 1.0;
  const double distribution = alpha2 / (M_PI * d * d);
  const double visibility = 0.5 / (nDotL * std::sqrt(nDotV * nDotV * (1.0 - alpha2) + alpha2) +
                                   nDotV * std::sqrt(nDotL * nDotL * (1.0 - alpha2) + alpha2));
  const double encoded[3] = {1.0, 0.5, 0.2};
  for (int c = 0; c < 3; ++c) {
    const double f0 = scene::srgbToLinear(float(encoded[c]));  // a metal: F0 is its colour
    const double fresnel = f0 + (1.0 - f0) * std::pow(1.0 - vDotH, 5.0);
    const double radiance = fresnel * distribution * visibility * 2.0 * nDotL;
    EXPECT_NEAR(channel(image, 16, 16, c), expectedByte(radiance), 2) << "channel " << c;
  }
  // The metal's colour survives: red over green over blue, as the base colour.
  EXPECT_GT(channel(image, 16, 16, 0), channel(image, 16, 16, 1) + 60);
  EXPECT_GT(channel(image, 16, 16, 1), channel(image, 16, 16, 2) + 30);
}

TEST_F(VulkanTest, exposure_scales_linear_radiance_before_encoding) {
  const double albedo = scene::srgbToLinear(0.8f);
  const auto image = renderLevelText(
      planeLevel("[0.8, 0.8, 0.8]",
                 R"("sun": {"type": "directional", "direction": [0, -1, 0], "intensity": 2.0})"),
      9, 9, scene::Tonemap::Identity, 0.25f);
  EXPECT_NEAR(channel(image, 4, 4, 1), expectedByte(0.25 * albedo * 2.0 / M_PI), 1);
}

TEST_F(VulkanTest, point_light_follows_inverse_square_and_cosine) {
  // Light 2 m above the plane's point under the camera: E = I / d^2 there, and at the image
  // edge the cosine and distance fall off as cos^3 / h^2.
  const double albedo = scene::srgbToLinear(1.0f);
  const double intensity = 10.0;
  const auto image = renderLevelText(
      planeLevel("[1, 1, 1]",
                 R"("bulb": {"type": "point", "position": [0, 2, 0], "intensity": 10.0})"),
      33, 33, scene::Tonemap::Identity, 0.5f);
  EXPECT_NEAR(channel(image, 16, 16, 0), expectedByte(0.5 * albedo / M_PI * intensity / 4.0), 1);
  // Centre of the rightmost column: the ray hits x = tan(30 deg) * (32.5/33 * 2 - 1)... at y=0.
  const double ndcX = (32.5 / 33.0) * 2.0 - 1.0;
  const double hitX = ndcX * std::tan(M_PI / 6.0);
  const double squaredDistance = hitX * hitX + 4.0;
  const double cosine = 2.0 / std::sqrt(squaredDistance);
  EXPECT_NEAR(channel(image, 32, 16, 0),
              expectedByte(0.5 * albedo / M_PI * intensity * cosine / squaredDistance), 1);
}

TEST_F(VulkanTest, slab_between_sun_and_plane_casts_a_hard_shadow_beside_it) {
  // A 0.2 m slab 0.3 m above the floor, sun travelling along (1, -1, 0): its shadow lands at
  // x in [0.2, 0.4]. The camera looks straight down, image x along world +X.
  const auto image = renderLevelText(
      planeLevel("[0.8, 0.8, 0.8]",
                 R"("sun": {"type": "directional", "direction": [1, -1, 0], "intensity": 2.0})",
                 R"(, "slab": {"box": {"size": [0.2, 0.02, 0.2]}})",
                 R"(, "slab": {"mesh": "slab", "material": "lambert", "position": [0, 0.3, 0]})"),
      33, 33, scene::Tonemap::Identity);
  auto columnForFloorX = [](double x) {
    return uint32_t(std::floor((x / std::tan(M_PI / 6.0) + 1.0) * 0.5 * 33.0));
  };
  const int lit = expectedByte(scene::srgbToLinear(0.8f) * 2.0 * std::sqrt(0.5) / M_PI);
  EXPECT_NEAR(channel(image, columnForFloorX(-0.3), 16, 1), lit, 1);  // open floor
  EXPECT_EQ(channel(image, columnForFloorX(0.3), 16, 1), 0);          // in the shadow
  EXPECT_NEAR(channel(image, columnForFloorX(0.5), 16, 1), lit, 1);   // past the shadow
}

TEST_F(VulkanTest, same_level_renders_bit_identical_with_and_without_row_interleaving) {
  const game::Level level = game::loadLevel(test::sourceDir() / "levels" / "01_first_light.json");
  const auto interleaved = renderLevel(level, 64, 37, scene::Tonemap::Aces, 1.0f, 8);
  const auto again = renderLevel(level, 64, 37, scene::Tonemap::Aces, 1.0f, 8);
  const auto plain = renderLevel(level, 64, 37, scene::Tonemap::Aces, 1.0f, 1);
  EXPECT_EQ(interleaved.pixels, again.pixels);
  EXPECT_EQ(interleaved.pixels, plain.pixels);
}

TEST_F(VulkanTest, first_level_matches_golden_image_within_tolerance) {
  const std::filesystem::path golden =
      test::sourceDir() / "tests" / "golden" / "01_first_light_160x90.png";
  const game::Level level = game::loadLevel(test::sourceDir() / "levels" / "01_first_light.json");
  const auto image = renderLevel(level, 160, 90, scene::Tonemap::Aces);
  if (const char* update = std::getenv("SIGHTLINE_UPDATE_GOLDEN"); update && *update == '1') {
    render::writePng(golden, image);
    GTEST_SKIP() << "golden image rewritten: " << golden;
  }
  const render::Rgba8Image expected = render::readPng(golden);
  const render::ImageDifference difference = render::compareImages(expected, image, 2);
  if (difference.differingFraction() > 0.005) {
    render::writePng("test-output/01_first_light_160x90.actual.png", image);
    render::writePng("test-output/01_first_light_160x90.diff.png", difference.visualization);
  }
  EXPECT_LE(difference.differingFraction(), 0.005)
      << difference.differingPixels << " of " << difference.totalPixels
      << " pixels differ by more than 2/255 (largest " << difference.largestChannelDifference
      << "); see test-output/01_first_light_160x90.{actual,diff}.png in the build directory";
}

TEST_F(VulkanTest, moving_an_instance_updates_the_tlas_and_moving_it_back_restores_the_image) {
  const game::Level level = blockOnPlaneLevel();
  const scene::SceneDesc scene = game::buildSceneDesc(level);
  render::RendererOptions options;
  options.width = 17;
  options.height = 17;
  render::Renderer renderer(context(), compiler(), scene, options);
  scene::FrameDesc frame;
  frame.camera = level.camera;
  frame.tonemap = scene::Tonemap::Identity;
  renderer.renderFrame(frame);
  const std::vector<uint8_t> before = renderer.pixels();
  // With the block far away, its shadow beside it disappears from the image.
  std::vector<glm::mat4> transforms;
  for (const auto& instance : scene.instances) transforms.push_back(instance.objectToWorld);
  transforms[1] = glm::translate(glm::mat4(1.0f), glm::vec3(50.0f, 0.3f, 0.0f));
  renderer.setInstanceTransforms(transforms);
  renderer.renderFrame(frame);
  const std::vector<uint8_t> moved = renderer.pixels();
  EXPECT_NE(before, moved);
  transforms[1] = scene.instances[1].objectToWorld;
  renderer.setInstanceTransforms(transforms);
  renderer.renderFrame(frame);
  EXPECT_EQ(before, renderer.pixels());
}

// play answers the window's events while a frame is waited for (RendererOptions::whileWaiting),
// since a level's first frames on a CPU driver compile for seconds: the wait goes in slices,
// calling between them until the fence is signalled. Here the first call signals it (an empty
// submit), so there is at least one.
TEST_F(VulkanTest, a_fence_waited_for_in_slices_calls_between_them_until_it_is_signalled) {
  VkFenceCreateInfo info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  ASSERT_EQ(vkCreateFence(context().device(), &info, nullptr, &fence), VK_SUCCESS);
  std::mutex queue;  // the submits below may come from two threads
  auto signal = [&] {
    const std::lock_guard lock(queue);
    EXPECT_EQ(vkQueueSubmit(context().queue(), 0, nullptr, fence), VK_SUCCESS);
  };
  std::atomic<uint32_t> calls = 0;
  {
    // Should no call come, the fence is signalled after 5 s all the same, so the test fails
    // rather than waits for ever.
    std::jthread watchdog([&](std::stop_token stop) {
      for (int i = 0; i < 500 && !stop.stop_requested(); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      if (calls == 0) signal();
    });
    render::waitForFence(context().device(), fence, std::chrono::milliseconds(0), [&] {
      if (++calls == 1) signal();
    });
  }
  EXPECT_GE(calls, 1u);
  EXPECT_EQ(vkGetFenceStatus(context().device(), fence), VK_SUCCESS);
  vkDestroyFence(context().device(), fence, nullptr);
}

// The frames waited for in slices are the frames waited for at once.
TEST_F(VulkanTest, a_frame_waited_for_in_slices_renders_the_same) {
  const game::Level level = blockOnPlaneLevel();
  const scene::SceneDesc scene = game::buildSceneDesc(level);
  scene::FrameDesc frame;
  frame.camera = level.camera;
  render::RendererOptions options;
  options.width = 64;
  options.height = 64;
  render::Renderer plain(context(), compiler(), scene, options);
  plain.renderFrame(frame);
  options.whileWaiting = [] {};
  options.waitSlice = std::chrono::milliseconds(0);
  render::Renderer sliced(context(), compiler(), scene, options);
  sliced.renderFrame(frame);
  EXPECT_EQ(plain.pixels(), sliced.pixels());
}

TEST_F(VulkanTest, ray_gen_counts_one_primary_ray_per_pixel_and_one_shadow_ray_per_lit_hit) {
  game::Level level = game::parseLevel(
      planeLevel("[0.8, 0.8, 0.8]",
                 R"("sun": {"type": "directional", "direction": [0, -1, 0], "intensity": 2.0})"),
      test::sourceDir() / "tests" / "inline_level.json");
  render::RendererOptions options;
  options.width = 20;
  options.height = 10;
  render::Renderer renderer(context(), compiler(), game::buildSceneDesc(level), options);
  scene::FrameDesc frame;
  frame.camera = level.camera;
  const render::FrameStats stats = renderer.renderFrame(frame, false);
  EXPECT_EQ(stats.surfaceRays, 200u);
  EXPECT_EQ(stats.secondaryRays, 200u);  // every pixel sees the floor, lit from above
}

TEST(VulkanValidation, layer_is_loaded_and_reports_a_provoked_error) {
  render::ContextOptions options;
  options.validate = true;
  options.echoValidation = false;
  render::Context context(options);
  ASSERT_TRUE(context.validationEnabled());
  // Size 0 is invalid (VUID-VkBufferCreateInfo-size-00912); the layer must say so.
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 0;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  if (vkCreateBuffer(context.device(), &info, nullptr, &buffer) == VK_SUCCESS && buffer)
    vkDestroyBuffer(context.device(), buffer, nullptr);
  const auto messages = context.validationMessages();
  ASSERT_FALSE(messages.empty());
  EXPECT_NE(messages.front().find("VUID-VkBufferCreateInfo-size-00912"), std::string::npos)
      << messages.front();
}

TEST(VulkanDevice, missing_extension_names_it_and_how_to_get_ray_tracing) {
  render::ContextOptions options;
  options.extraDeviceExtensions = {"VK_KHR_sightline_test_missing"};
  try {
    render::Context context(options);
    FAIL() << "a device without the required extension was accepted";
  } catch (const render::RenderError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("no Vulkan device with ray tracing"), std::string::npos) << message;
    EXPECT_NE(message.find("lacks VK_KHR_sightline_test_missing"), std::string::npos) << message;
  }
}

TEST(VulkanDevice, old_lavapipe_is_told_to_install_mesa_24_1) {
  render::DeviceInfo device;
  device.name = "llvmpipe (LLVM 15.0.6, 256 bits)";
  device.driver = "llvmpipe: Mesa 22.3.6 (LLVM 15.0.6)";
  device.type = VK_PHYSICAL_DEVICE_TYPE_CPU;
  device.missingExtensions = {"VK_KHR_acceleration_structure", "VK_KHR_ray_tracing_pipeline"};
  const std::string message = render::describeMissingRayTracing(device);
  EXPECT_NE(message.find("lacks VK_KHR_acceleration_structure, VK_KHR_ray_tracing_pipeline"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("lavapipe from Mesa 22.3 has no ray tracing; install Mesa >= 24.1"),
            std::string::npos)
      << message;
}

TEST(VulkanDevice, unknown_device_selector_is_a_clear_error) {
  render::ContextOptions options;
  options.deviceSelector = "no-such-gpu";
  EXPECT_THROW(
      {
        try {
          render::Context context(options);
        } catch (const render::RenderError& error) {
          EXPECT_NE(std::string(error.what()).find("--device no-such-gpu matches no device"),
                    std::string::npos);
          throw;
        }
      },
      render::RenderError);
}

}  // namespace
