// Light routed by flat mirrors: sensors count light that arrives via mirrors (times their
// reflectance and tint) and through glass, colour sensors count one channel, and the patch a
// mirror throws on a diffuse surface is as bright as the sensor's reading says. Analytic
// expectations: a mirror image of a light is the light moved to its image position.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "game/primitives.hpp"
#include "render/light_routes.hpp"
#include "render/render_space.hpp"
#include "scene/flat_faces.hpp"
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

// A square mirror of side `size` centred at `centre` whose reflecting side faces `normal`
// (a plane mesh, which reflects on both sides), turned by `tiltDegrees` about the vertical
// axis.
glm::mat4 mirrorFacing(const glm::vec3& centre, const glm::vec3& normal, float tiltDegrees = 0.0f) {
  const float yaw = std::atan2(normal.x, normal.z) + glm::radians(tiltDegrees);
  glm::mat4 transform = glm::translate(glm::mat4(1.0f), centre);
  transform = glm::rotate(transform, yaw, glm::vec3(0, 1, 0));
  return glm::rotate(transform, glm::radians(90.0f), glm::vec3(1, 0, 0));  // +Y faces +Z
}

scene::LightDesc pointLight(const glm::vec3& position, float intensity = 1.0f) {
  scene::LightDesc light;
  light.type = scene::LightType::Point;
  light.position = position;
  light.intensity = intensity;
  return light;
}

scene::LightDesc sphereLight(const glm::vec3& position, float radius) {
  scene::LightDesc light;
  light.type = scene::LightType::Sphere;
  light.position = position;
  light.radius = radius;
  return light;
}

// 64 sample points on a square of side `side` around `centre`, facing `normal`.
std::vector<scene::ExposurePoint> plate(const glm::vec3& centre, const glm::vec3& normal,
                                        float side) {
  const glm::vec3 n = glm::normalize(normal);
  const glm::vec3 u = glm::normalize(glm::cross(n, glm::vec3(0, 1, 0)));
  const glm::vec3 v = glm::cross(u, n);
  std::vector<scene::ExposurePoint> points;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 position = centre + u * (side * ((float(i) + 0.5f) / 8.0f - 0.5f)) +
                                 v * (side * ((float(j) + 0.5f) / 8.0f - 0.5f)) + n * 1e-3f;
      points.push_back({position, n, true});
    }
  return points;
}

class LightRoutesTest : public test::VulkanTest {
 protected:
  // The exposure of `points` to light 0, one probe frame.
  // `tint`: the feedback tint the game may give the light (probes must not see it).
  static float exposure(const SceneBuilder& builder,
                        const std::vector<scene::ExposurePoint>& points,
                        scene::ExposureChannel channel = scene::ExposureChannel::Luminance,
                        const glm::vec3& tint = glm::vec3(1.0f)) {
    scene::SceneDesc scene = builder.scene;
    scene.exposureProbes = true;
    render::RendererOptions options;
    options.width = 16;
    options.height = 16;
    render::Renderer renderer(context(), compiler(), scene, options);
    scene::ExposureProbeDesc probe;
    probe.light = 0;
    probe.channel = channel;
    probe.points = points;
    renderer.setProbes({{}, {probe}});
    renderer.setLightTint(0, tint);
    scene::FrameDesc frame;
    frame.camera.position = glm::vec3(0.0f, 10.0f, 0.0f);
    renderer.renderFrame(frame, false);
    return renderer.probeCounts().exposure(0);
  }
};

// One mirror: the light at L, the sensor at S, a wall between them; the light reaches S only
// via the mirror M at the origin (facing +Z). Its image is L reflected in the plane z = 0.
const glm::vec3 kLight(-1.5f, 1.0f, 3.5f), kSensor(1.5f, 1.0f, 3.5f), kMirror(0.0f, 1.0f, 0.0f);
const glm::vec3 kLightImage(-1.5f, 1.0f, -3.5f);

// A bar in front of the sensor, towards the mirror, shading part of it (the same in both
// scenes, so the direct reading is not simply 1).
void addBar(SceneBuilder& builder) {
  const glm::vec3 towardsMirror = glm::normalize(kMirror - kSensor);
  builder.instance(builder.mesh(game::primitives::box({0.04f, 2.0f, 0.04f})),
                   builder.material(MaterialDesc{}), at(kSensor + towardsMirror * 0.3f));
}

SceneBuilder viaOneMirror(float reflectance, float tiltDegrees, const scene::LightDesc& light) {
  SceneBuilder builder;
  builder.instance(builder.mesh(game::primitives::plane(0.3f, 0.3f)),
                   builder.material(mirrorMaterial(glm::vec3(reflectance))),
                   mirrorFacing(kMirror, {0, 0, 1}, tiltDegrees));
  builder.instance(builder.mesh(game::primitives::box({0.2f, 2.0f, 0.5f})),
                   builder.material(MaterialDesc{}), at({0.0f, 1.0f, 3.5f}));
  addBar(builder);
  builder.light(light);
  return builder;
}

// The same sensor with the light at its mirror image, nothing else but the bar.
SceneBuilder imageDirect(const scene::LightDesc& light) {
  SceneBuilder builder;
  addBar(builder);
  builder.light(light);
  return builder;
}

std::vector<scene::ExposurePoint> sensorPlate() {
  return plate(kSensor, kMirror - kSensor, 0.1f);
}

TEST(LightRoutesGeometry, a_thin_box_has_two_flat_faces_a_quad_two_sides_and_a_sphere_none) {
  const std::vector<scene::FlatFace> box = scene::flatFaces(game::primitives::box({2, 2, 0.05f}));
  ASSERT_EQ(box.size(), 2u);  // the four thin edges are under a tenth of the largest face
  for (const scene::FlatFace& face : box) {
    EXPECT_NEAR(std::abs(face.normal.z), 1.0f, 1e-6f);
    EXPECT_NEAR(face.centre.z, 0.025f * face.normal.z, 1e-6f);
    EXPECT_NEAR(glm::length(face.halfU) * glm::length(face.halfV), 1.0f, 1e-5f);
  }
  const std::vector<scene::FlatFace> quad = scene::flatFaces(game::primitives::plane(1, 1));
  ASSERT_EQ(quad.size(), 2u);  // one plane, both sides
  EXPECT_EQ(quad[0].normal, -quad[1].normal);
  EXPECT_TRUE(scene::flatFaces(game::primitives::sphere(1.0f, 16, 8)).empty());
}

TEST(LightRoutesGeometry, two_facing_mirrors_chain_and_a_light_behind_a_mirror_has_no_route) {
  render::MirrorFace left{{1, 0, 0}, {-1, 0, 0}, {0, 0.5f, 0}, {0, 0, 0.5f}, glm::vec3(0.5f)};
  render::MirrorFace right{{-1, 0, 0}, {1, 0, 0}, {0, 0.5f, 0}, {0, 0, 0.5f}, glm::vec3(0.5f)};
  render::gpu::GpuLight light{glm::vec4(0, 0, 0, float(LIGHT_POINT)), glm::vec4(0, -1, 0, 1),
                              glm::vec4(1, 1, 1, 0), glm::vec4(0), glm::vec4(0)};
  const std::vector<render::MirrorFace> faces = {left, right};
  const std::vector<render::gpu::GpuLightRoute> routes =
      render::findLightRoutes(faces, std::span(&light, 1), 3);
  // Between two facing mirrors: L-R, R-L (one face), then alternating sequences of 2 and 3.
  ASSERT_EQ(routes.size(), 6u);
  EXPECT_EQ(routes[0].lightMirrors.y, 1u);
  EXPECT_EQ(glm::vec3(routes[0].image.positionType), glm::vec3(-2, 0, 0));
  EXPECT_EQ(routes[2].lightMirrors.y, 2u);
  // Light -> left (x = -2 image) -> right: the image of the image, at x = 4.
  EXPECT_EQ(glm::vec3(routes[2].image.positionType), glm::vec3(4, 0, 0));
  EXPECT_EQ(glm::vec3(routes[2].tint), glm::vec3(0.25f));
  EXPECT_EQ(routes[4].lightMirrors.y, 3u);

  // Behind a mirror (x < -1, its back), a light has no route via it.
  light.positionType.x = -3.0f;
  EXPECT_TRUE(render::findLightRoutes(std::span(&left, 1), std::span(&light, 1), 3).empty());
}

TEST_F(LightRoutesTest,
       a_sensor_lit_only_via_a_mirror_reads_its_reflectance_times_the_direct_reading) {
  const scene::LightDesc light = sphereLight(kLight, 0.05f);
  scene::LightDesc image = light;
  image.position = kLightImage;
  const float direct = exposure(imageDirect(image), sensorPlate());
  const float mirrored = exposure(viaOneMirror(0.8f, 0.0f, light), sensorPlate());
  EXPECT_GT(direct, 0.2f);
  EXPECT_LT(direct, 0.95f);  // the bar shades part of the plate
  EXPECT_NEAR(mirrored, 0.8f * direct, 0.02f * 0.8f * direct);
  // Without the mirror the wall leaves the sensor dark.
  SceneBuilder noMirror = viaOneMirror(0.8f, 0.0f, light);
  noMirror.scene.materials[0] = MaterialDesc{};
  EXPECT_EQ(exposure(noMirror, sensorPlate()), 0.0f);
}

TEST_F(LightRoutesTest, turning_the_mirror_5_degrees_moves_the_light_off_the_sensor) {
  const scene::LightDesc light = sphereLight(kLight, 0.05f);
  EXPECT_GT(exposure(viaOneMirror(0.8f, 0.0f, light), sensorPlate()), 0.3f);
  EXPECT_EQ(exposure(viaOneMirror(0.8f, 5.0f, light), sensorPlate()), 0.0f);
  EXPECT_EQ(exposure(viaOneMirror(0.8f, -5.0f, light), sensorPlate()), 0.0f);
}

// Two mirrors at 45 degrees: L = (0, 1, 2) shines down -Z onto M1 at (0, 1, 0), which sends it
// along +X to M2 at (2, 1, 0), which sends it along +Z to the sensor at (2, 1, 2); a wall blocks
// the straight way from L to the sensor.
TEST_F(LightRoutesTest, two_mirrors_in_sequence_multiply_their_reflectances) {
  SceneBuilder builder;
  const uint32_t square = builder.mesh(game::primitives::plane(0.3f, 0.3f));
  builder.instance(square, builder.material(mirrorMaterial(glm::vec3(0.8f))),
                   mirrorFacing({0, 1, 0}, {1, 0, 1}));
  builder.instance(square, builder.material(mirrorMaterial(glm::vec3(0.5f))),
                   mirrorFacing({2, 1, 0}, {-1, 0, 1}));
  builder.instance(builder.mesh(game::primitives::box({0.2f, 2.0f, 0.6f})),
                   builder.material(MaterialDesc{}), at({1, 1, 2}));
  builder.light(pointLight({0, 1, 2}));
  const std::vector<scene::ExposurePoint> points = plate({2, 1, 2}, {0, 0, -1}, 0.05f);
  // Every point sees the light at 0.8 x 0.5, rounded to the 1/1024 fixed point per sample.
  EXPECT_FLOAT_EQ(exposure(builder, points), std::round(0.4f * 1024.0f) / 1024.0f);
}

TEST_F(LightRoutesTest, a_red_sensor_reads_nothing_behind_green_glass_and_all_behind_red_glass) {
  scene::LightDesc redLamp = pointLight({0, 1, 2});
  redLamp.color = {1.0f, 0.0f, 0.0f};
  auto behindGlass = [&](const glm::vec3& tint, const scene::LightDesc& light) {
    SceneBuilder builder;
    builder.instance(builder.mesh(game::primitives::box({1.0f, 1.0f, 0.02f})),
                     builder.material(glassMaterial(tint)), at({0, 1, 1}));
    builder.light(light);
    return builder;
  };
  const std::vector<scene::ExposurePoint> points = plate({0, 1, 0}, {0, 0, 1}, 0.1f);
  const auto red = scene::ExposureChannel::Red;
  SceneBuilder open;
  open.light(redLamp);
  const float direct = exposure(open, points, red);
  EXPECT_EQ(direct, 1.0f);
  EXPECT_EQ(exposure(behindGlass({0, 1, 0}, redLamp), points, red), 0.0f);
  EXPECT_EQ(exposure(behindGlass({1, 0, 0}, redLamp), points, red), direct);
  // White light is not red light; through red glass it is.
  const scene::LightDesc whiteLamp = pointLight({0, 1, 2});
  SceneBuilder white;
  white.light(whiteLamp);
  EXPECT_EQ(exposure(white, points, red), 0.0f);
  EXPECT_EQ(exposure(behindGlass({1, 0, 0}, whiteLamp), points, red), 1.0f);
  // A watcher's feedback tint (warming towards red) changes the picture, not the readings.
  EXPECT_EQ(exposure(white, points, red, {1.6f, 0.55f, 0.35f}), 0.0f);
  // A sensor of any colour counts the luminance: red glass passes 0.2126 of white light.
  EXPECT_NEAR(exposure(behindGlass({1, 0, 0}, whiteLamp), points), 0.2126f, 1.0f / 1024.0f);
}

// The patch: a point light at L = (0, 2, 3) shines on a mirror at (0, 1, 0) facing +Z, whose
// reflection lands on the floor around P = (0, 0, 3), where a plate above P keeps the direct
// light off. The camera looks at P; its radiance must be albedo / pi times the irradiance from
// the light's image (0, 2, -3) times the sensor's reading there.
TEST_F(LightRoutesTest, the_patch_a_mirror_throws_is_as_bright_as_the_sensor_reading_there) {
  SceneBuilder builder;
  MaterialDesc floor;
  floor.baseColor = glm::vec3(0.5f);
  builder.instance(builder.mesh(game::primitives::plane(20.0f, 20.0f)), builder.material(floor),
                   glm::mat4(1.0f));
  builder.instance(builder.mesh(game::primitives::plane(1.0f, 1.0f)),
                   builder.material(mirrorMaterial(glm::vec3(0.8f))),
                   mirrorFacing({0, 1, 0}, {0, 0, 1}));
  builder.instance(builder.mesh(game::primitives::box({0.6f, 0.02f, 0.6f})),
                   builder.material(MaterialDesc{}), at({0, 1, 3}));
  const float intensity = 100.0f;
  builder.light(pointLight({0, 2, 3}, intensity));
  builder.scene.exposureProbes = true;

  const uint32_t width = 64, height = 36;
  scene::FrameDesc frame;
  frame.camera.position = {0.0f, 1.5f, 6.0f};
  frame.camera.pitchDegrees = -glm::degrees(std::atan(0.5f));
  frame.tonemap = scene::Tonemap::Identity;
  // The floor point the centre pixel (32, 18) sees.
  const render::CameraBasis basis = render::cameraBasis(frame.camera, float(width) / height);
  const glm::vec2 ndc = (glm::vec2(32.5f, 18.5f) / glm::vec2(width, height)) * 2.0f - 1.0f;
  const glm::vec3 direction =
      glm::normalize(basis.forward + ndc.x * basis.right - ndc.y * basis.up);
  const glm::vec3 point =
      frame.camera.position + direction * (-frame.camera.position.y / direction.y);

  render::RendererOptions options;
  options.width = width;
  options.height = height;
  render::Renderer renderer(context(), compiler(), builder.scene, options);
  scene::ExposureProbeDesc probe;
  probe.points = {{point + glm::vec3(0, 1e-3f, 0), {0, 1, 0}, true}};
  renderer.setProbes({{}, {probe}});
  renderer.renderFrame(frame, false);
  const float reading = renderer.probeCounts().exposure(0);
  EXPECT_FLOAT_EQ(reading, std::round(0.8f * 1024.0f) / 1024.0f);
  const glm::vec4 rendered = renderer.readRadiance()[18 * width + 32];

  const glm::vec3 toImage = glm::vec3(0, 2, -3) - point;
  const float irradiance = intensity * glm::normalize(toImage).y / glm::dot(toImage, toImage);
  const float expected = 0.5f / kPi * irradiance * reading;
  EXPECT_GT(expected, 0.05f);
  EXPECT_NEAR(rendered.g, expected, 0.05f * expected) << "at " << point.x << ", " << point.z;
}

}  // namespace
