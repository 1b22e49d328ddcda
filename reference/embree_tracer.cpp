#include "reference/embree_tracer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include <embree3/rtcore.h>
#if defined(__x86_64__) || defined(__i386__)
#include <xmmintrin.h>
#endif
#include <glm/glm.hpp>

#include "render/gpu_types.hpp"
#include "render/render_space.hpp"

namespace reference {
namespace {

using scene::LightType;
using scene::MaterialKind;

constexpr float kFar = 1.0e30f;  // FAR in raygen.rgen

// Glass rays see every glass surface up to tMax and stop at none, like the any-hit shader that
// ignores each intersection.
void passThroughGlass(const RTCFilterFunctionNArguments* args) {
  for (unsigned i = 0; i < args->N; ++i) args->valid[i] = 0;
}

// ray_offset.glsl: the largest quantity a hit position was computed from (its ray's origin
// coordinates and the distance travelled), and the step off the surface scaled to it.
float rayOffsetMagnitude(const glm::vec3& origin, float distance) {
  const glm::vec3 size = glm::abs(origin);
  return std::max(std::max(size.x, size.y), std::max(size.z, distance));
}

glm::vec3 offsetRayOrigin(const glm::vec3& position, const glm::vec3& geometricNormal,
                          const glm::vec3& arriving, float magnitude) {
  constexpr float kRelativeStep = 1.0f / 65536.0f;
  return position + (geometricNormal - arriving) * std::max(magnitude * kRelativeStep, 1.0e-30f);
}

struct Light {
  LightType type = LightType::Point;
  glm::vec3 worldPosition{0.0f};
  glm::vec3 position{0.0f};                // camera-relative
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // unit
  float radius = 0.0f;
  glm::vec2 size{0.0f};
  bool enabled = true;
  bool soft = false;  // traced as a soft light in this variant
};

struct Instance {
  const scene::MeshData* mesh = nullptr;
  MaterialKind kind = MaterialKind::Diffuse;
  glm::mat3 normalToWorld{1.0f};  // inverse transpose of the object-to-world rotation part
};

// Where a surface ray stopped and the normals the shader derives there.
struct SurfaceHit {
  float t = -1.0f;  // < 0: missed
  uint32_t instance = kReachedNothing;
  glm::vec3 geometricNormal{0.0f};  // unit, world space, towards the ray's origin
  glm::vec3 normal{0.0f};           // shading normal, unit, on the geometric normal's side
};

}  // namespace

struct EmbreeTracer::Scene {
  RTCDevice device = nullptr;
  std::vector<RTCScene> meshScenes;  // owned: the bottom levels
  RTCScene top = nullptr;
  std::vector<scene::MeshData> meshes;  // a copy: normals are read at every hit
  std::vector<Instance> instances;
  std::vector<std::pair<uint32_t, glm::mat4>> placed;  // attached instance IDs, object-to-world
  std::vector<Light> lights;
  render::PipelineFeatures features;
  std::optional<glm::dvec3> origin;  // of camera-relative space: the camera of the last frame

  // Moves every instance and light to coordinates relative to `camera` (world minus camera, in
  // double, then float), as the renderer's render space places them.
  void moveOrigin(const glm::dvec3& camera) {
    if (origin == camera) return;
    origin = camera;
    for (const auto& [id, objectToWorld] : placed) {
      const glm::mat4 transform = render::toRenderSpace(objectToWorld, camera);
      RTCGeometry geometry = rtcGetGeometry(top, id);
      rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &transform[0][0]);
      rtcCommitGeometry(geometry);
    }
    rtcCommitScene(top);
    check("moving the instances");
    for (Light& light : lights) light.position = render::toRenderSpace(light.worldPosition, camera);
  }

  ~Scene() {
    if (top) rtcReleaseScene(top);
    for (RTCScene scene : meshScenes) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  void check(const char* what) const {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE)
      throw std::runtime_error(std::string("Embree: ") + what + " failed (error " +
                               std::to_string(int(error)) + ")");
  }

  RTCScene buildMeshScene(const scene::MeshData& mesh, bool glass) {
    RTCScene scene = rtcNewScene(device);
    meshScenes.push_back(scene);
    // Robust: watertight edges, as Vulkan requires of ray-triangle tests.
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* positions = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), mesh.vertices.size()));
    for (size_t i = 0; i < mesh.vertices.size(); ++i)
      std::copy_n(&mesh.vertices[i].position.x, 3, positions + 3 * i);
    auto* indices = static_cast<uint32_t*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(uint32_t), mesh.indices.size() / 3));
    std::copy(mesh.indices.begin(), mesh.indices.end(), indices);
    if (glass) rtcSetGeometryIntersectFilterFunction(geometry, passThroughGlass);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene);
    check("building a mesh's BVH");
    return scene;
  }
};

EmbreeTracer::EmbreeTracer(const scene::SceneDesc& scene, const render::PipelineFeatures& features,
                           uint32_t threads)
    : scene_(std::make_unique<Scene>()), threads_(std::max(threads, 1u)) {
  Scene& s = *scene_;
  s.features = features;
  s.meshes = scene.meshes;
  const std::string config = "threads=" + std::to_string(threads_);
  s.device = rtcNewDevice(config.c_str());
  if (!s.device) throw std::runtime_error("Embree: rtcNewDevice failed");

  const auto start = std::chrono::steady_clock::now();
  // One bottom level per mesh and use: glass instances need the pass-through filter.
  std::vector<RTCScene> opaqueScenes(scene.meshes.size(), nullptr);
  std::vector<RTCScene> glassScenes(scene.meshes.size(), nullptr);
  s.top = rtcNewScene(s.device);
  rtcSetSceneBuildQuality(s.top, RTC_BUILD_QUALITY_HIGH);
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const scene::InstanceDesc& desc = scene.instances[i];
    if (desc.mesh >= scene.meshes.size() || desc.material >= scene.materials.size())
      throw std::runtime_error("Embree: instance " + std::to_string(i) +
                               " names a mesh or material that does not exist");
    const scene::MeshData& mesh = s.meshes[desc.mesh];
    const MaterialKind kind = scene.materials[desc.material].kind;
    s.instances.push_back(
        {&mesh, kind, glm::transpose(glm::inverse(glm::mat3(desc.objectToWorld)))});
    if (mesh.indices.size() < 3) continue;  // nothing to hit
    const bool glass = kind == MaterialKind::Glass;
    RTCScene& meshScene = glass ? glassScenes[desc.mesh] : opaqueScenes[desc.mesh];
    if (!meshScene) meshScene = s.buildMeshScene(mesh, glass);
    RTCGeometry instance = rtcNewGeometry(s.device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(instance, meshScene);
    rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR,
                            &desc.objectToWorld[0][0]);
    rtcSetGeometryMask(instance, render::gpu::instanceMask(glass, desc.castsShadow, false,
                                                           desc.shadowsDirectionalOnly));
    rtcCommitGeometry(instance);
    rtcAttachGeometryByID(s.top, instance, i);  // instID = the scene's instance index
    s.placed.emplace_back(i, desc.objectToWorld);
    rtcReleaseGeometry(instance);
  }
  rtcCommitScene(s.top);
  s.check("building the instance BVH");
  buildMilliseconds_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  for (const scene::LightDesc& desc : scene.lights) {
    Light light;
    light.type = desc.type;
    light.worldPosition = desc.position;
    light.position = desc.position;
    light.direction = glm::length(desc.direction) > 0.0f ? glm::normalize(desc.direction)
                                                         : glm::vec3(0.0f, -1.0f, 0.0f);
    light.radius = desc.radius;
    light.size = desc.size;
    light.enabled = desc.enabled;
    light.soft = features.softShadows && desc.type != LightType::Point;
    s.lights.push_back(light);
  }
}

EmbreeTracer::~EmbreeTracer() = default;

namespace {

// Rays traced by one thread.
struct RayCounts {
  uint64_t surface = 0, secondary = 0;
};

// Whether `light` reaches the front of a surface point, as unshadowedLight in raygen.rgen
// decides it, with the direction to the light's centre and the shadow ray's length.
bool lightReaches(const Light& light, const glm::vec3& position, const glm::vec3& normal,
                  const glm::vec3& geometricNormal, glm::vec3& toLight, float& distance) {
  constexpr float kPi = 3.14159265358979f;
  if (!light.enabled) return false;
  if (light.type == LightType::Directional) {
    toLight = -light.direction;
    distance = kFar;
  } else {
    const glm::vec3 offset = light.position - position;
    distance = std::sqrt(std::max(glm::dot(offset, offset), 1e-12f));
    toLight = offset / distance;
    if (light.type == LightType::Rectangle || light.type == LightType::Disk) {
      const float area = light.type == LightType::Disk ? kPi * light.radius * light.radius
                                                       : light.size.x * light.size.y;
      if (area * std::max(glm::dot(light.direction, -toLight), 0.0f) <= 0.0f) return false;
    }
    distance *= 0.9999f;  // stop short of the light itself
  }
  return glm::dot(normal, toLight) > 0.0f && glm::dot(geometricNormal, toLight) > 0.0f;
}

RTCRay makeRay(const glm::vec3& origin, const glm::vec3& direction, float tMax, uint32_t mask) {
  RTCRay ray{};
  ray.org_x = origin.x;
  ray.org_y = origin.y;
  ray.org_z = origin.z;
  ray.tnear = 0.0f;
  ray.dir_x = direction.x;
  ray.dir_y = direction.y;
  ray.dir_z = direction.z;
  ray.tfar = tMax;
  ray.mask = mask;
  return ray;
}

// Embree runs fastest with denormals flushed; set per worker thread only, so the caller's
// floating-point mode is untouched.
void flushDenormals() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_setcsr(_mm_getcsr() | 0x8040);  // FTZ (bit 15) and DAZ (bit 6)
#endif
}

// One pixel's path, as the ray-gen shader's main loop walks it.
class PixelTracer {
 public:
  PixelTracer(RTCScene top, const std::vector<Instance>& instances,
              const std::vector<Light>& lights, const render::PipelineFeatures& features)
      : top_(top), instances_(instances), lights_(lights), features_(features) {}

  uint32_t trace(glm::vec3 origin, glm::vec3 direction) {
    uint32_t bounces = 0;
    for (;;) {
      const SurfaceHit hit = traceSurface(origin, direction);
      ++counts.surface;
      if (features_.glass) traceGlass(origin, direction, hit.t < 0.0f ? kFar : hit.t, MASK_GLASS);
      if (hit.t < 0.0f) return kReachedNothing;
      const glm::vec3 position = origin + direction * hit.t;
      const float offsetMagnitude = rayOffsetMagnitude(origin, hit.t);
      if (features_.mirrors && instances_[hit.instance].kind == MaterialKind::Mirror) {
        // At the cap the path ends black, on nothing.
        if (bounces >= features_.maxMirrorBounces) return kReachedNothing;
        origin = offsetRayOrigin(position, hit.geometricNormal, direction, offsetMagnitude);
        direction = glm::reflect(direction, hit.normal);
        ++bounces;
        continue;
      }
      traceShadows(position, hit,
                   offsetRayOrigin(position, hit.geometricNormal, direction, offsetMagnitude));
      return hit.instance;
    }
  }

  RayCounts counts;

 private:
  SurfaceHit traceSurface(const glm::vec3& origin, const glm::vec3& direction) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayHit{};
    rayHit.ray = makeRay(origin, direction, kFar, MASK_VISIBLE);
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(top_, &context, &rayHit);
    SurfaceHit hit;
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
    hit.t = rayHit.ray.tfar;
    hit.instance = rayHit.hit.instID[0];
    // The normals as surface.rchit makes them: from the triangle's corners and vertex normals,
    // to world space by the inverse transpose.
    const Instance& instance = instances_[hit.instance];
    const scene::MeshData& mesh = *instance.mesh;
    const uint32_t first = 3 * rayHit.hit.primID;
    const scene::Vertex& v0 = mesh.vertices[mesh.indices[first]];
    const scene::Vertex& v1 = mesh.vertices[mesh.indices[first + 1]];
    const scene::Vertex& v2 = mesh.vertices[mesh.indices[first + 2]];
    const float u = rayHit.hit.u, v = rayHit.hit.v;
    glm::vec3 geometric =
        instance.normalToWorld * glm::cross(v1.position - v0.position, v2.position - v0.position);
    glm::vec3 shading =
        instance.normalToWorld * (v0.normal * (1.0f - u - v) + v1.normal * u + v2.normal * v);
    const float geometricLength = glm::length(geometric);
    const float shadingLength = glm::length(shading);
    geometric = geometricLength > 0.0f ? geometric / geometricLength : -direction;
    shading = shadingLength > 0.0f ? shading / shadingLength : geometric;
    // raygen.rgen: the geometric normal faces the ray's origin, the shading normal its side.
    hit.geometricNormal = glm::dot(geometric, direction) > 0.0f ? -geometric : geometric;
    hit.normal = glm::dot(shading, hit.geometricNormal) < 0.0f ? -shading : shading;
    return hit;
  }

  void traceGlass(const glm::vec3& origin, const glm::vec3& direction, float tMax, uint32_t mask) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayHit{};
    rayHit.ray = makeRay(origin, direction, tMax, mask);
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(top_, &context, &rayHit);
    ++counts.secondary;
  }

  // `directional`: towards a directional light, whose rays also meet the casters of directional
  // shadows alone (as shadow_rays.glsl masks them).
  void traceShadow(const glm::vec3& origin, const glm::vec3& toLight, float distance,
                   bool directional) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray = makeRay(origin, toLight, distance, render::gpu::shadowRayMask(directional));
    rtcOccluded1(top_, &context, &ray);
    ++counts.secondary;
    const bool blocked = !(ray.tfar >= 0.0f);  // Embree sets tfar to -inf on a hit
    if (!blocked && features_.glass)
      traceGlass(origin, toLight, distance, render::gpu::glassShadowRayMask(directional));
  }

  // shadeSurface: hard lights one ray each; soft lights share the variant's samples.
  void traceShadows(const glm::vec3& position, const SurfaceHit& hit,
                    const glm::vec3& shadowOrigin) {
    bool softLightReaches = false;
    glm::vec3 softDirection{0.0f};
    float softDistance = 0.0f;
    bool softDirectional = false;
    for (const Light& light : lights_) {
      glm::vec3 toLight;
      float distance;
      if (!lightReaches(light, position, hit.normal, hit.geometricNormal, toLight, distance))
        continue;
      if (light.soft) {
        if (!softLightReaches) {
          softLightReaches = true;
          softDirection = toLight;
          softDistance = distance;
          softDirectional = light.type == LightType::Directional;
        }
        continue;
      }
      traceShadow(shadowOrigin, toLight, distance, light.type == LightType::Directional);
    }
    if (!softLightReaches) return;
    for (uint32_t s = 0; s < features_.softShadowSamples; ++s)
      traceShadow(shadowOrigin, softDirection, softDistance * 0.9999f, softDirectional);
  }

  RTCScene top_;
  const std::vector<Instance>& instances_;
  const std::vector<Light>& lights_;
  const render::PipelineFeatures& features_;
};

}  // namespace

ReferenceFrame EmbreeTracer::traceFrame(const scene::CameraDesc& camera, uint32_t width,
                                        uint32_t height) {
  if (width == 0 || height == 0) throw std::invalid_argument("traceFrame: empty image");
  Scene& s = *scene_;
  s.moveOrigin(glm::dvec3(camera.position));  // a refit of the top level, not timed
  // The renderer's camera, at the origin of camera-relative space.
  const render::CameraBasis basis = render::cameraBasis(camera, float(width) / float(height));
  ReferenceFrame frame;
  frame.width = width;
  frame.height = height;
  frame.finalInstances.assign(size_t(width) * height, kReachedNothing);
  std::atomic<uint32_t> nextRow{0};
  std::vector<RayCounts> counts(threads_);
  auto work = [&](uint32_t thread) {
    flushDenormals();
    PixelTracer tracer(s.top, s.instances, s.lights, s.features);
    for (uint32_t y = nextRow++; y < height; y = nextRow++) {
      for (uint32_t x = 0; x < width; ++x) {
        // raygen.rgen's camera ray through the pixel centre.
        const glm::vec2 ndc =
            (glm::vec2(float(x), float(y)) + 0.5f) / glm::vec2(float(width), float(height)) * 2.0f -
            1.0f;
        const glm::vec3 direction =
            glm::normalize(basis.forward + ndc.x * basis.right - ndc.y * basis.up);
        frame.finalInstances[size_t(y) * width + x] = tracer.trace(glm::vec3(0.0f), direction);
      }
    }
    counts[thread] = tracer.counts;
  };
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> workers;
  for (uint32_t t = 0; t < threads_; ++t) workers.emplace_back(work, t);
  for (std::thread& worker : workers) worker.join();
  frame.milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  for (const RayCounts& count : counts) {
    frame.surfaceRays += count.surface;
    frame.secondaryRays += count.secondary;
  }
  return frame;
}

uint32_t countFocusPixels(const ReferenceFrame& frame, uint32_t instance,
                          const scene::PixelBox& box) {
  uint32_t count = 0;
  for (uint32_t y = box.y0; y < std::min(box.y1, frame.height); ++y)
    for (uint32_t x = box.x0; x < std::min(box.x1, frame.width); ++x)
      count += frame.finalInstances[size_t(y) * frame.width + x] == instance ? 1u : 0u;
  return count;
}

}  // namespace reference
