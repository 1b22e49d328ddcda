#include "render/renderer.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstring>

#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/packing.hpp>

#include "render/barriers.hpp"
#include "render/blue_noise.hpp"
#include "render/bvh_order.hpp"
#include "render/context.hpp"
#include "render/fence_wait.hpp"
#include "render/gpu_types.hpp"
#include "render/ray_tracing_pipeline.hpp"
#include "render/render_space.hpp"
#include "render/shader_compiler.hpp"
#include "render/storage_image.hpp"
#include "render/texture.hpp"
#include "render/vulkan_error.hpp"
#include "scene/box_transform.hpp"

namespace render {
namespace {

static_assert(sizeof(scene::Vertex) == VERTEX_FLOATS * sizeof(float),
              "vertex layout matches shaders");

// Steady frames after a change of an instance or a light before the denoiser's history may grow
// past DENOISER_MAX_HISTORY unclamped: the test scene's sphere light moved 0.67 m in a still view
// left RMSE 0.0107 of the old shadow after 128 frames with 32 here, 0.0058 with 64, and 0.0071
// where the history never grows longer (docs/QUALITY.md, session 25).
constexpr uint32_t kSteadyFramesToForgetAChange = 2 * DENOISER_MAX_HISTORY;
static_assert(scene::kTextureRoles == TEXTURE_ROLES &&
                  uint32_t(scene::TextureRole::Emissive) == TEXTURE_EMISSIVE &&
                  uint32_t(scene::TextureRole::Occlusion) == TEXTURE_OCCLUSION &&
                  uint32_t(scene::TextureRole::MetallicRoughness) == TEXTURE_METALLIC_ROUGHNESS &&
                  uint32_t(scene::TextureRole::Normal) == TEXTURE_NORMAL &&
                  uint32_t(scene::TextureRole::BaseColor) == TEXTURE_BASE_COLOR,
              "texture roles match shaders");

// How far a transform's elements may stray (metres, or the rotation and scale's plain numbers)
// from the instance's transform in the TLAS and the instance not count as moved: the TLAS keeps
// what it has, no motion is written and the scene counts as steady. play's player body, resting
// on the floor, lands 0 and 7.5e-9 m high in turn, tick after tick; each of those used to update
// the TLAS and make the denoiser and the upscaler read every instance's motion.
constexpr float kUnseenTransformChange = 1.0e-5f;

bool withinUnseenChange(const std::vector<glm::mat4>& transforms,
                        const std::vector<glm::mat4>& reference) {
  for (size_t i = 0; i < transforms.size(); ++i) {
    for (int column = 0; column < 4; ++column) {
      const glm::vec4 difference = glm::abs(transforms[i][column] - reference[i][column]);
      if (glm::any(glm::greaterThan(difference, glm::vec4(kUnseenTransformChange)))) return false;
    }
  }
  return true;
}

constexpr VkShaderStageFlags kRayStages =
    VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR |
    VK_SHADER_STAGE_MISS_BIT_KHR | VK_SHADER_STAGE_ANY_HIT_BIT_KHR;
// The fragment stage: the temporal upscaler's resolve.
constexpr VkShaderStageFlags kAllStages =
    kRayStages | VK_SHADER_STAGE_COMPUTE_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr VkBufferUsageFlags kGeometryUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
    VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;

// Start, after tracing, after denoising, after the tonemap, after the readback.
constexpr uint32_t kTimestampCount = 5;

template <typename T>
Buffer makeStorage(const Context& context, const std::vector<T>& items, VkBufferUsageFlags usage,
                   const char* name) {
  // Zero-length buffers are invalid; an empty list still gets one (unread) element.
  const VkDeviceSize bytes = std::max<VkDeviceSize>(items.size(), 1) * sizeof(T);
  Buffer buffer(context, bytes, usage, MemoryUse::Upload, name);
  if (!items.empty()) buffer.write(items.data(), items.size() * sizeof(T));
  return buffer;
}

bool alphaMasked(const scene::SceneDesc& scene, const scene::InstanceDesc& instance) {
  if (scene.materials[instance.material].alphaCutoff > 0.0f) return true;
  for (const uint32_t material : instance.meshMaterials)
    if (material < scene.materials.size() && scene.materials[material].alphaCutoff > 0.0f)
      return true;
  return false;
}

// Row r of KHR_texture_transform's offset x rotation x scale, for uv' = dot(row, (uv, 1)).
std::array<glm::vec4, 2> transformRows(const scene::TextureMapping& mapping) {
  const float cosine = std::cos(mapping.rotationRadians);
  const float sine = std::sin(mapping.rotationRadians);
  return {glm::vec4(cosine * mapping.scale.x, sine * mapping.scale.y, mapping.offset.x, 0.0f),
          glm::vec4(-sine * mapping.scale.x, cosine * mapping.scale.y, mapping.offset.y, 0.0f)};
}

template <typename TextureSlot>
gpu::GpuMaterial toGpuMaterial(const scene::MaterialDesc& material,
                               const TextureSlot& textureSlot) {
  gpu::GpuMaterial result{};
  result.baseColorSpecular = glm::vec4(material.baseColor, material.specular);
  result.emissiveRoughness = glm::vec4(material.emissive, material.roughness);
  result.mirrorTint = glm::vec4(material.mirrorTint, material.metallic);
  result.glassTint = glm::vec4(
      material.glassTint,
      material.alphaCutoff > 0.0f ? material.alphaCutoff / std::max(material.alpha, 1e-6f) : 0.0f);
  uint32_t secondUvSet = 0;
  for (uint32_t role = 0; role < scene::kTextureRoles; ++role) {
    const scene::TextureMapping& mapping = material.textureMappings[role];
    if (mapping.uvSet == 1) secondUvSet |= 1u << role;
    const std::array<glm::vec4, 2> rows = transformRows(mapping);
    result.textureTransforms[2 * role] = rows[0];
    result.textureTransforms[2 * role + 1] = rows[1];
  }
  result.kindShading =
      glm::uvec4(static_cast<uint32_t>(material.kind),
                 material.metallicRoughness ? SHADING_METALLIC_ROUGHNESS : SHADING_BLINN_PHONG,
                 secondUvSet, material.alphaBlend ? MATERIAL_FLAG_ALPHA_BLEND : 0u);
  result.textureSlots[0] = glm::uvec4(
      textureSlot(material.colorTexture), textureSlot(material.normalTexture),
      textureSlot(material.metallicRoughnessTexture), textureSlot(material.occlusionTexture));
  result.textureSlots[1] = glm::uvec4(textureSlot(material.emissiveTexture), 0u, 0u, 0u);
  result.textureFactors =
      glm::vec4(material.alpha, material.normalScale, material.occlusionStrength, 0.0f);
  return result;
}

gpu::GpuLight toGpuLight(const scene::LightDesc& light) {
  const glm::vec3 direction = glm::length(light.direction) > 0.0f ? glm::normalize(light.direction)
                                                                  : glm::vec3(0.0f, -1.0f, 0.0f);
  return {glm::vec4(light.position, static_cast<float>(light.type)),
          glm::vec4(direction, light.enabled ? 1.0f : 0.0f),
          glm::vec4(light.color * light.intensity, light.radius),
          glm::vec4(light.size, light.angularDiameterRadians, 0.0f),
          glm::vec4(light.position, 0.0f)};
}

}  // namespace

Renderer::Renderer(const Context& context, ShaderCompiler& compiler, const scene::SceneDesc& scene,
                   const RendererOptions& options)
    : context_(context),
      options_(options),
      pictureWidth_(options.width),
      pictureHeight_(options.height),
      shownPicture_(options.width, options.height),
      environment_(scene.environment) {
  // Interleaving pays on CPU drivers (each thread's block of rows sees every part of the image);
  // on a GPU it only costs coherence: 2-8 % at 4K on the H100 (docs/PERFORMANCE.md).
  if (options_.rowGroups == 0) options_.rowGroups = context.isCpuDevice() ? 8 : 1;
  // A constructor that throws (a lost device, exhausted memory) gets no destructor call: this
  // destroys the handles made so far instead (members with destructors release themselves).
  struct DestroyHandlesOnThrow {
    Renderer* renderer;
    ~DestroyHandlesOnThrow() {
      if (renderer) renderer->destroyHandles();
    }
  } destroyHandlesOnThrow{this};
  if (options.width == 0 || options.height == 0 || options.width > 16384 ||
      options.height > 16384) {
    throw RenderError("image size must be between 1x1 and 16384x16384");
  }
  // The upscaler names what a pixel shows by its instance + 1, or by SEEN_LIGHT_BASE + a light.
  if (scene.instances.size() >= SEEN_LIGHT_BASE || scene.lights.size() >= SEEN_LIGHT_BASE)
    throw RenderError("a scene has at most " + std::to_string(SEEN_LIGHT_BASE - 1) +
                      " instances and as many lights");
  // One vertex and index buffer for all meshes; each instance records where its mesh starts.
  std::vector<scene::Vertex> allVertices;
  std::vector<uint32_t> allIndices;
  struct MeshRange {
    uint32_t firstIndex, vertexOffset, indexCount, vertexCount;
  };
  std::vector<MeshRange> ranges;
  // Each mesh's triangles in an order whose halvings split space (render/bvh_order.hpp): the
  // triangle at position i of the index buffer is the mesh's triangle triangleOrders[mesh][i].
  std::vector<std::vector<uint32_t>> triangleOrders;
  std::vector<LeafBounds> meshBounds;
  for (const scene::MeshData& mesh : scene.meshes) {
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0 || mesh.vertices.empty())
      throw RenderError("mesh '" + mesh.name + "' has no triangles");
    for (uint32_t index : mesh.indices) {
      if (index >= mesh.vertices.size())
        throw RenderError("mesh '" + mesh.name + "' has an index past its vertices");
    }
    ranges.push_back(
        {static_cast<uint32_t>(allIndices.size()), static_cast<uint32_t>(allVertices.size()),
         static_cast<uint32_t>(mesh.indices.size()), static_cast<uint32_t>(mesh.vertices.size())});
    allVertices.insert(allVertices.end(), mesh.vertices.begin(), mesh.vertices.end());
    std::vector<LeafBounds> triangles;
    LeafBounds meshBox{mesh.vertices[0].position, mesh.vertices[0].position};
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
      LeafBounds triangle{mesh.vertices[mesh.indices[t]].position,
                          mesh.vertices[mesh.indices[t]].position};
      for (size_t corner = 1; corner < 3; ++corner) {
        const glm::vec3 position = mesh.vertices[mesh.indices[t + corner]].position;
        triangle.min = glm::min(triangle.min, position);
        triangle.max = glm::max(triangle.max, position);
      }
      meshBox.min = glm::min(meshBox.min, triangle.min);
      meshBox.max = glm::max(meshBox.max, triangle.max);
      triangles.push_back(triangle);
    }
    meshBounds.push_back(meshBox);
    std::vector<uint32_t> order = halvingOrder(triangles);
    for (const uint32_t triangle : order) {
      for (size_t corner = 0; corner < 3; ++corner)
        allIndices.push_back(mesh.indices[size_t(triangle) * 3 + corner]);
    }
    triangleOrders.push_back(std::move(order));
  }
  triangleCount_ = 0;
  std::vector<gpu::GpuInstance> gpuInstances;
  std::vector<uint32_t> triangleMaterials;
  for (const scene::InstanceDesc& instance : scene.instances) {
    if (instance.mesh >= ranges.size() || instance.material >= scene.materials.size())
      throw RenderError("an instance refers to a mesh or material that does not exist");
    const MeshRange& range = ranges[instance.mesh];
    uint32_t material = instance.material;
    const std::vector<uint32_t>& perTriangle = scene.meshes[instance.mesh].triangleMaterials;
    if (!instance.meshMaterials.empty() && !perTriangle.empty()) {
      if (perTriangle.size() != range.indexCount / 3)
        throw RenderError("mesh '" + scene.meshes[instance.mesh].name +
                          "' has a material for other than every triangle");
      material = MATERIAL_PER_TRIANGLE | static_cast<uint32_t>(triangleMaterials.size());
      for (const uint32_t triangle : triangleOrders[instance.mesh]) {
        const uint32_t own = perTriangle[triangle];
        if (own >= instance.meshMaterials.size() ||
            instance.meshMaterials[own] >= scene.materials.size())
          throw RenderError("an instance refers to a mesh material that does not exist");
        triangleMaterials.push_back(instance.meshMaterials[own]);
      }
    }
    gpuInstances.push_back({glm::uvec4(range.firstIndex, range.vertexOffset, material, 0),
                            {glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, 1, 0)}});
    currentTransforms_.push_back(instance.objectToWorld);
    historyTransforms_.push_back(instance.objectToWorld);
    instanceVisible_.push_back(true);
    instanceGlow_.push_back(0.0f);
    triangleCount_ += range.indexCount / 3;
  }
  auto textureSlot = [&](int32_t index) -> uint32_t {
    if (index < -1 || index >= int32_t(scene.textures.size()))
      throw RenderError("a material refers to a texture that does not exist");
    return static_cast<uint32_t>(index + 1);
  };
  std::vector<gpu::GpuMaterial> gpuMaterials;
  for (const scene::MaterialDesc& material : scene.materials)
    gpuMaterials.push_back(toGpuMaterial(material, textureSlot));
  for (const scene::LightDesc& light : scene.lights) {
    gpuLights_.push_back(toGpuLight(light));
    lightRadiances_.push_back(glm::vec3(gpuLights_.back().radianceRadius));
    lightPositions_.push_back(light.position);
  }
  lightPreviousPositions_ = lightPositions_;
  lightHistoryPositions_ = lightPositions_;
  lightCount_ = static_cast<uint32_t>(gpuLights_.size());

  vertices_ = makeStorage(context, allVertices, kGeometryUsage, "vertices");
  indices_ = makeStorage(context, allIndices, kGeometryUsage, "indices");
  instances_ = makeStorage(context, gpuInstances, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "instances");
  materials_ = makeStorage(context, gpuMaterials, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "materials");
  lights_ = makeStorage(context, gpuLights_, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "lights");
  triangleMaterials_ = makeStorage(context, triangleMaterials, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                   "triangle materials");
  // The texture array is never empty: a white texel stands in when the scene has none.
  if (scene.textures.empty()) {
    textures_.push_back(std::make_unique<Texture>(
        context, scene::TextureDesc{"white", 1, 1, false, {255, 255, 255, 255}}));
  }
  for (const scene::TextureDesc& texture : scene.textures)
    textures_.push_back(std::make_unique<Texture>(context, texture));
  VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  samplerInfo.magFilter = VK_FILTER_LINEAR;
  samplerInfo.minFilter = VK_FILTER_LINEAR;
  samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  samplerInfo.addressModeU = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  samplerInfo.addressModeV = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  samplerInfo.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  samplerInfo.maxLod = 0.0f;
  vkCheck(vkCreateSampler(context.device(), &samplerInfo, nullptr, &sampler_), "vkCreateSampler");
  frameUniforms_ = Buffer(context, sizeof(gpu::FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                          MemoryUse::Upload, "frame uniforms");
  // Shaders write counters and paths in device memory; the host reads copies.
  constexpr VkDeviceSize kCounterBytes =
      sizeof(gpu::FrameCounters) * COUNTER_SLOTS + sizeof(gpu::ProbeResults);
  counters_ = Buffer(context, kCounterBytes,
                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                         VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                     MemoryUse::DeviceOnly, "frame counters");
  countersReadback_ = Buffer(context, kCounterBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                             MemoryUse::Readback, "frame counters readback");
  paths_ = Buffer(context, VkDeviceSize(options.width) * options.height * sizeof(gpu::PixelPath),
                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                  MemoryUse::DeviceOnly, "pixel paths");
  // Probe setup and points: host-written each time the request changes; zero = no probes.
  probeSetup_ = Buffer(
      context,
      sizeof(gpu::ProbeSetup) + sizeof(gpu::ProbePoint) * MAX_EXPOSURE_PROBES * EXPOSURE_SAMPLES,
      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload, "probe setup");
  const gpu::ProbeSetup noProbes{};
  probeSetup_.write(&noProbes, sizeof noProbes);
  if (options.outputWidth > 0 && options.outputHeight > 0) {
    upscaler_ = std::make_unique<TemporalUpscaler>(context, options.width, options.height,
                                                   options.outputWidth, options.outputHeight,
                                                   options.resolveWrites);
  }
  readback_ = Buffer(context, VkDeviceSize(outputWidth()) * outputHeight() * 4,
                     VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback, "pixel readback");

  std::vector<TriangleGeometry> geometries;
  for (const MeshRange& range : ranges) {
    geometries.push_back(
        {vertices_.address() + VkDeviceSize(range.vertexOffset) * sizeof(scene::Vertex),
         sizeof(scene::Vertex), range.vertexCount,
         indices_.address() + VkDeviceSize(range.firstIndex) * sizeof(uint32_t),
         range.indexCount / 3});
  }
  bottomLevels_ = buildBottomLevels(context, geometries);
  std::vector<TlasInstance> tlasInstances;
  std::vector<uint32_t> glassMembers, seenFromEye;
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const scene::InstanceDesc& instance = scene.instances[i];
    const bool glass = scene.materials[instance.material].kind == scene::MaterialKind::Glass;
    TlasInstance tlasInstance{&bottomLevels_[instance.mesh], instance.objectToWorld, i};
    tlasInstance.bounds = scene::transformBox(meshBounds[instance.mesh], instance.objectToWorld);
    tlasInstance.mask = gpu::instanceMask(glass, instance.castsShadow, instance.playerBody,
                                          instance.shadowsDirectionalOnly);
    if (alphaMasked(scene, instance)) {
      // Not opaque, so the alpha test (alpha.rahit) runs for every ray that meets it.
      tlasInstance.hitGroup = HIT_GROUP_SURFACE;
      tlasInstance.flags = VK_GEOMETRY_INSTANCE_FORCE_NO_OPAQUE_BIT_KHR;
    } else if (glass) {
      // Non-opaque, so the glass any-hit shader runs; only glass rays see it.
      tlasInstance.hitGroup = HIT_GROUP_GLASS;
      tlasInstance.flags = VK_GEOMETRY_INSTANCE_FORCE_NO_OPAQUE_BIT_KHR;
    } else {
      tlasInstance.hitGroup = HIT_GROUP_SURFACE;
      tlasInstance.flags = VK_GEOMETRY_INSTANCE_FORCE_OPAQUE_BIT_KHR;
    }
    tlasInstances.push_back(tlasInstance);
    if (glass) glassMembers.push_back(i);
    if (!instance.playerBody) seenFromEye.push_back(i);
  }
  topLevel_ = std::make_unique<TopLevel>(context, tlasInstances);
  if (!glassMembers.empty())
    glassLevel_ = std::make_unique<TopLevelSubset>(context, tlasInstances, std::move(glassMembers));
  if (!seenFromEye.empty() && seenFromEye.size() < tlasInstances.size())
    eyeLevel_ = std::make_unique<TopLevelSubset>(context, tlasInstances, std::move(seenFromEye));

  radiance_ =
      pixelBuffer(context, options.width, options.height, sizeof(glm::vec4), "linear radiance");
  outputImage_ = std::make_unique<StorageImage>(
      context, options.width, options.height, VK_FORMAT_R8G8B8A8_UNORM,
      VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, "display image");
  PipelineFeatures features =
      options.allFeatures ? allFeatures(scene.maxMirrorBounces) : featuresOf(scene);
  features.softShadowSamples = std::clamp(options.softShadowSamples, 1u, 16u);
  // Routing follows the scene even in the all-features variant (a level may turn it off).
  features.lightRoutes = featuresOf(scene).lightRoutes && options.lightRoutes;
  features.alphaMask = featuresOf(scene).alphaMask;  // all-features too: the scene needs it
  // No denoiser, no images or passes for it, in levels with hard shadows only.
  if (features.softShadows)
    denoiser_ = std::make_unique<Denoiser>(context, options.width, options.height);
  routeLight_ = features.lightRoutes;
  mirrorBounces_ = features.maxMirrorBounces;
  mirrorFaces_.resize(scene.instances.size());
  mirrorTints_.resize(scene.instances.size(), glm::vec3(0.0f));
  for (size_t i = 0; routeLight_ && i < scene.instances.size(); ++i) {
    const scene::MaterialDesc& material = scene.materials[scene.instances[i].material];
    if (material.kind != scene::MaterialKind::Mirror) continue;
    mirrorFaces_[i] = scene::flatFaces(scene.meshes[scene.instances[i].mesh]);
    mirrorTints_[i] = material.mirrorTint;
  }
  lightRoutes_ = Buffer(
      context, sizeof(gpu::LightRoutesHeader) + sizeof(gpu::GpuLightRoute) * MAX_LIGHT_ROUTES,
      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload, "light routes");
  const gpu::LightRoutesHeader noRoutes{};
  lightRoutes_.write(&noRoutes, sizeof noRoutes);
  // The tiles are made (once per process) only for a variant with soft shadows, the one that
  // reads them; any other binds zeros.
  const size_t sampleNoiseBytes = size_t(SAMPLE_NOISE_SIZE) * SAMPLE_NOISE_SIZE * sizeof(uint32_t);
  sampleNoise_ = Buffer(context, sampleNoiseBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                        MemoryUse::Upload, "sample noise");
  if (features.softShadows) {
    sampleNoise_.write(softShadowSampleNoise().data(), sampleNoiseBytes);
  } else {
    const std::vector<uint32_t> zeros(sampleNoiseBytes / sizeof(uint32_t), 0u);
    sampleNoise_.write(zeros.data(), sampleNoiseBytes);
  }
  createDescriptors();
  createPipelines(compiler, features, scene.exposureProbes);

  commands_ = context.allocateCommandBuffer();
  if (context.timestampsSupported()) {
    VkQueryPoolCreateInfo queryInfo{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    queryInfo.queryType = VK_QUERY_TYPE_TIMESTAMP;
    queryInfo.queryCount = kTimestampCount;
    vkCheck(vkCreateQueryPool(context.device(), &queryInfo, nullptr, &timestamps_),
            "vkCreateQueryPool");
  }
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  vkCheck(vkCreateFence(context.device(), &fenceInfo, nullptr, &frameDone_), "vkCreateFence");
  destroyHandlesOnThrow.renderer = nullptr;
}

Renderer::~Renderer() {
  destroyHandles();
}

void Renderer::destroyHandles() {
  VkDevice device = context_.device();
  vkDeviceWaitIdle(device);
  if (frameDone_) vkDestroyFence(device, frameDone_, nullptr);
  if (timestamps_) vkDestroyQueryPool(device, timestamps_, nullptr);
  if (commands_) vkFreeCommandBuffers(device, context_.commandPool(), 1, &commands_);
  if (tonemapPipeline_) vkDestroyPipeline(device, tonemapPipeline_, nullptr);
  if (sampler_) vkDestroySampler(device, sampler_, nullptr);
  rayTracingPipeline_.reset();
  if (pipelineLayout_) vkDestroyPipelineLayout(device, pipelineLayout_, nullptr);
  if (descriptorPool_) vkDestroyDescriptorPool(device, descriptorPool_, nullptr);
  if (setLayout_) vkDestroyDescriptorSetLayout(device, setLayout_, nullptr);
}

void Renderer::createDescriptors() {
  VkDevice device = context_.device();
  const std::array<std::pair<uint32_t, VkDescriptorType>, 16> bindings = {{
      {BINDING_TLAS, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR},
      {BINDING_GLASS_TLAS, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR},
      {BINDING_RADIANCE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {BINDING_OUTPUT_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
      {BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
      {BINDING_INSTANCES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {BINDING_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {BINDING_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {BINDING_VERTICES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {BINDING_INDICES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {BINDING_COUNTERS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {BINDING_PATHS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {BINDING_PROBE_SETUP, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {BINDING_LIGHT_ROUTES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {BINDING_TRIANGLE_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      {BINDING_SAMPLE_NOISE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
  }};
  constexpr uint32_t kSets = 2;
  std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
  std::vector<VkDescriptorPoolSize> poolSizes;
  for (const auto& [binding, type] : bindings) {
    layoutBindings.push_back({binding, type, 1, kAllStages, nullptr});
    poolSizes.push_back({type, kSets});
  }
  const uint32_t textureCount = static_cast<uint32_t>(textures_.size());
  layoutBindings.push_back({BINDING_TEXTURES, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                            textureCount, kRayStages, nullptr});
  poolSizes.push_back({VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, textureCount * kSets});
  std::vector<std::pair<uint32_t, VkImageView>> passImages;
  if (denoiser_) passImages = denoiser_->bindings(0);
  if (upscaler_) {
    for (const auto& entry : upscaler_->bindings(0)) passImages.push_back(entry);
  }
  for (const auto& [binding, view] : passImages) {
    layoutBindings.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, kAllStages, nullptr});
    poolSizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kSets});
  }
  std::vector<std::pair<uint32_t, const Buffer*>> passBuffers;
  if (denoiser_) passBuffers = denoiser_->bufferBindings();
  if (upscaler_) {
    for (const auto& entry : upscaler_->bufferBindings()) passBuffers.push_back(entry);
  }
  for (const auto& [binding, buffer] : passBuffers) {
    layoutBindings.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kAllStages, nullptr});
    poolSizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kSets});
  }
  VkDescriptorSetLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  layoutInfo.bindingCount = static_cast<uint32_t>(layoutBindings.size());
  layoutInfo.pBindings = layoutBindings.data();
  vkCheck(vkCreateDescriptorSetLayout(device, &layoutInfo, nullptr, &setLayout_),
          "vkCreateDescriptorSetLayout");
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = kSets;
  poolInfo.poolSizeCount = static_cast<uint32_t>(poolSizes.size());
  poolInfo.pPoolSizes = poolSizes.data();
  vkCheck(vkCreateDescriptorPool(device, &poolInfo, nullptr, &descriptorPool_),
          "vkCreateDescriptorPool");
  const std::array<VkDescriptorSetLayout, kSets> setLayouts = {setLayout_, setLayout_};
  VkDescriptorSetAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  allocateInfo.descriptorPool = descriptorPool_;
  allocateInfo.descriptorSetCount = kSets;
  allocateInfo.pSetLayouts = setLayouts.data();
  vkCheck(vkAllocateDescriptorSets(device, &allocateInfo, descriptorSets_.data()),
          "vkAllocateDescriptorSets");

  VkAccelerationStructureKHR tlas = topLevel_->structure().handle();
  VkWriteDescriptorSetAccelerationStructureKHR tlasWrite{
      VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
  tlasWrite.accelerationStructureCount = 1;
  tlasWrite.pAccelerationStructures = &tlas;
  VkAccelerationStructureKHR glassTlas = glassLevel_ ? glassLevel_->structure().handle() : tlas;
  VkWriteDescriptorSetAccelerationStructureKHR glassTlasWrite = tlasWrite;
  glassTlasWrite.pAccelerationStructures = &glassTlas;
  const std::array<std::pair<uint32_t, const Buffer*>, 13> buffers = {{
      {BINDING_RADIANCE, &radiance_},
      {BINDING_FRAME, &frameUniforms_},
      {BINDING_INSTANCES, &instances_},
      {BINDING_MATERIALS, &materials_},
      {BINDING_LIGHTS, &lights_},
      {BINDING_VERTICES, &vertices_},
      {BINDING_INDICES, &indices_},
      {BINDING_COUNTERS, &counters_},
      {BINDING_PATHS, &paths_},
      {BINDING_PROBE_SETUP, &probeSetup_},
      {BINDING_LIGHT_ROUTES, &lightRoutes_},
      {BINDING_TRIANGLE_MATERIALS, &triangleMaterials_},
      {BINDING_SAMPLE_NOISE, &sampleNoise_},
  }};
  std::vector<VkDescriptorImageInfo> textureInfos;
  for (const auto& texture : textures_)
    textureInfos.push_back({sampler_, texture->view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
  std::vector<std::pair<uint32_t, const Buffer*>> allBuffers(buffers.begin(), buffers.end());
  allBuffers.insert(allBuffers.end(), passBuffers.begin(), passBuffers.end());
  for (uint32_t parity = 0; parity < kSets; ++parity) {
    std::vector<std::pair<uint32_t, VkImageView>> storageImages = {
        {BINDING_OUTPUT_IMAGE, outputImage_->view()}};
    if (denoiser_) {
      for (const auto& entry : denoiser_->bindings(parity)) storageImages.push_back(entry);
    }
    if (upscaler_) {
      for (const auto& entry : upscaler_->bindings(parity)) storageImages.push_back(entry);
    }
    // Infos are sized up front: writes point into them.
    std::vector<VkDescriptorImageInfo> imageInfos;
    for (const auto& [binding, view] : storageImages)
      imageInfos.push_back({VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL});
    std::vector<VkDescriptorBufferInfo> bufferInfos;
    for (const auto& [binding, buffer] : allBuffers)
      bufferInfos.push_back({buffer->handle(), 0, VK_WHOLE_SIZE});
    std::vector<VkWriteDescriptorSet> writes;
    auto write = [&](uint32_t binding, VkDescriptorType type, uint32_t count) {
      VkWriteDescriptorSet entry{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      entry.dstSet = descriptorSets_[parity];
      entry.dstBinding = binding;
      entry.descriptorCount = count;
      entry.descriptorType = type;
      writes.push_back(entry);
      return writes.size() - 1;
    };
    writes[write(BINDING_TLAS, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1)].pNext =
        &tlasWrite;
    writes[write(BINDING_GLASS_TLAS, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1)].pNext =
        &glassTlasWrite;
    for (size_t i = 0; i < storageImages.size(); ++i) {
      writes[write(storageImages[i].first, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1)].pImageInfo =
          &imageInfos[i];
    }
    for (size_t i = 0; i < allBuffers.size(); ++i) {
      const VkDescriptorType type = allBuffers[i].first == BINDING_FRAME
                                        ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER
                                        : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      writes[write(allBuffers[i].first, type, 1)].pBufferInfo = &bufferInfos[i];
    }
    writes[write(BINDING_TEXTURES, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, textureCount)]
        .pImageInfo = textureInfos.data();
    vkUpdateDescriptorSets(device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
  }

  const VkPushConstantRange pushConstants{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(DenoiserPass)};
  VkPipelineLayoutCreateInfo pipelineLayoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pipelineLayoutInfo.setLayoutCount = 1;
  pipelineLayoutInfo.pSetLayouts = &setLayout_;
  pipelineLayoutInfo.pushConstantRangeCount = 1;
  pipelineLayoutInfo.pPushConstantRanges = &pushConstants;
  vkCheck(vkCreatePipelineLayout(device, &pipelineLayoutInfo, nullptr, &pipelineLayout_),
          "vkCreatePipelineLayout");
}

void Renderer::createPipelines(ShaderCompiler& compiler, const PipelineFeatures& features,
                               bool exposureProbes) {
  pipelineDescription_ = describePipeline(features);
  const bool subgroupCounters = options_.subgroupCounters && context_.raygenSubgroupArithmetic();
  pipelineDescription_.defines.push_back({"SUBGROUP_COUNTERS", subgroupCounters ? "1" : "0"});
  pipelineDescription_.defines.push_back({"TEMPORAL_UPSCALE", upscaler_ ? "1" : "0"});
  pipelineDescription_.defines.push_back(
      {"BUFFERED_IMAGE_WRITES", denoiser_ && denoiser_->writesThroughBuffers() ? "1" : "0"});
  const ShaderDefines& defines = pipelineDescription_.defines;
  auto load = [&](const std::string& file) {
    return ShaderCode{file, compiler.compile(file, defines).spirv};
  };
  RayTracingProgram program;
  program.raygen = load("raygen.rgen");
  for (const std::string& miss : pipelineDescription_.misses) program.misses.push_back(load(miss));
  for (const std::string& group : pipelineDescription_.hitGroups) {
    HitGroup hitGroup{group, {}, {}};
    // "closest.rchit", "any.rahit" or both joined by '+'.
    for (std::size_t start = 0; start < group.size();) {
      const std::size_t end = std::min(group.find('+', start), group.size());
      const std::string file = group.substr(start, end - start);
      (file.ends_with(".rahit") ? hitGroup.anyHit : hitGroup.closestHit) = load(file);
      start = end + 1;
    }
    program.hitGroups.push_back(std::move(hitGroup));
  }
  program.recursionDepth = pipelineDescription_.recursionDepth;
  if (exposureProbes) program.probeRaygen = load("probe.rgen");
  rayTracingPipeline_ = std::make_unique<RayTracingPipeline>(context_, pipelineLayout_, program);

  tonemapPipeline_ = createComputePipeline(
      context_, pipelineLayout_,
      compiler.compile("tonemap.comp", {{"SOFT_SHADOWS", features.softShadows ? "1" : "0"}}).spirv,
      "tonemap");
  // Without glass every shadow ray reports 0 or 1 in all three channels alike.
  const bool greyVisibility =
      !features.glass && options_.visibilityChannels == VisibilityChannels::Auto;
  if (denoiser_)
    denoiser_->createPipelines(compiler, pipelineLayout_, options_.neighbourhoodReads,
                               greyVisibility);
  if (upscaler_)
    upscaler_->createPipeline(compiler, pipelineLayout_, features.mirrors,
                              options_.heldPointResolve);
}

void Renderer::setInstanceTransforms(std::span<const glm::mat4> objectToWorld) {
  if (objectToWorld.size() != topLevel_->instanceCount())
    throw RenderError("setInstanceTransforms: expected one transform per instance");
  pendingTransforms_.assign(objectToWorld.begin(), objectToWorld.end());
}

// New transforms go to the TLAS with the next frame, unless none strayed further than
// kUnseenTransformChange from what the TLAS has. A full frame also gets each instance's
// previous-from-current transform: what moved since the last full frame, so the denoiser
// reprojects moving objects; identity again once they stop.
void Renderer::writeInstanceMotion(bool fullFrame) {
  if (!pendingTransforms_.empty()) {
    if (!withinUnseenChange(pendingTransforms_, currentTransforms_)) {
      sceneChanged_ = true;
      currentTransforms_ = pendingTransforms_;
      tlasStale_ = true;
      movedSinceHistory_ = true;
    }
    pendingTransforms_.clear();
  }
  if (!fullFrame || (!movedSinceHistory_ && !instancesMoved_)) return;
  for (size_t i = 0; i < currentTransforms_.size(); ++i) {
    const glm::mat4 previousFromCurrent =
        movedSinceHistory_
            ? motionInRenderSpace(historyTransforms_[i], currentTransforms_[i], *renderOrigin_)
            : glm::mat4(1.0f);
    glm::vec4 rows[3];
    for (int row = 0; row < 3; ++row) rows[row] = glm::row(previousFromCurrent, row);
    instances_.write(rows, sizeof rows, i * sizeof(gpu::GpuInstance) + sizeof(glm::uvec4));
  }
  instancesMoved_ = movedSinceHistory_;
  movedSinceHistory_ = false;
  historyTransforms_ = currentTransforms_;
}

// A full frame also gets where each light was at the last full frame, the motion of a light
// seen (the light's point carried by its centre's move): identity again once the lights stop.
void Renderer::writeLightMotion(bool fullFrame) {
  if (!fullFrame || (!lightsMovedSinceHistory_ && !lightsMoved_)) return;
  lightPreviousPositions_ = lightsMovedSinceHistory_ ? lightHistoryPositions_ : lightPositions_;
  // After moveRenderOrigin, so render space is this frame's.
  for (size_t i = 0; i < gpuLights_.size(); ++i)
    gpuLights_[i].previousPosition =
        glm::vec4(toRenderSpace(lightPreviousPositions_[i], *renderOrigin_), 0.0f);
  lights_.write(gpuLights_.data(), gpuLights_.size() * sizeof(gpuLights_[0]));
  lightsMoved_ = lightsMovedSinceHistory_;
  lightsMovedSinceHistory_ = false;
  lightHistoryPositions_ = lightPositions_;
}

std::vector<gpu::PixelPath> Renderer::pixelPaths() const {
  return readDeviceBuffer<gpu::PixelPath>(context_, paths_);
}

void Renderer::setProbes(const scene::ProbeRequest& request) {
  if (request.focus.size() > MAX_FOCUS_PROBES || request.exposure.size() > MAX_EXPOSURE_PROBES)
    throw RenderError("setProbes: at most 16 focus and 16 exposure probes");
  if (!request.exposure.empty() && !rayTracingPipeline_->hasProbeRaygen())
    throw RenderError("setProbes: exposure probes need a scene made with exposureProbes");
  gpu::ProbeSetup setup{};
  setup.counts = glm::uvec4(request.focus.size(), request.exposure.size(), 0, 0);
  scene::ProbeCounts counts;
  for (size_t i = 0; i < request.focus.size(); ++i) {
    const scene::FocusProbeDesc& focus = request.focus[i];
    if (focus.instance >= currentTransforms_.size())
      throw RenderError("setProbes: a focus probe names an instance that does not exist");
    const scene::PixelBox box = scene::focusPixelBox(focus.region, options_.width, options_.height);
    setup.focus[i] =
        glm::uvec4(focus.instance, box.x0 | (box.y0 << 16), box.x1 | (box.y1 << 16), 0);
    counts.focusRegionPixels.push_back(box.pixels());
  }
  for (size_t i = 0; i < request.exposure.size(); ++i) {
    const scene::ExposureProbeDesc& exposure = request.exposure[i];
    if (exposure.light >= gpuLights_.size() || exposure.points.size() > EXPOSURE_SAMPLES)
      throw RenderError("setProbes: an exposure probe names no light or has over 64 points");
    // The light's colour as the level made it, so a feedback tint changes no colour reading.
    const glm::vec3 radiance = lightRadiances_[exposure.light];
    const float brightest = std::max({radiance.r, radiance.g, radiance.b});
    const glm::vec3 chroma = brightest > 0.0f ? radiance / brightest : glm::vec3(0.0f);
    setup.exposure[i] =
        glm::uvec4(exposure.light, exposure.points.size(),
                   static_cast<uint32_t>(exposure.channel) | (exposure.onPlayerBody ? 0x100u : 0u),
                   glm::packUnorm4x8(glm::vec4(chroma, 0.0f)));
    counts.exposurePoints.push_back(uint32_t(exposure.points.size()));
  }
  focusBox_.reset();
  for (size_t i = 0; i < request.focus.size(); ++i) {
    const scene::PixelBox box =
        scene::focusPixelBox(request.focus[i].region, options_.width, options_.height);
    focusBox_ =
        focusBox_
            ? scene::PixelBox{std::min(focusBox_->x0, box.x0), std::min(focusBox_->y0, box.y0),
                              std::max(focusBox_->x1, box.x1), std::max(focusBox_->y1, box.y1)}
            : box;
  }
  counts.focusPixels.assign(request.focus.size(), 0);
  counts.exposureFixed.assign(request.exposure.size(), 0);
  probeSetup_.write(&setup, sizeof setup);
  probeRequest_ = request;
  probeCounts_ = std::move(counts);
  writeProbePoints();
}

// The exposure probes' points in render space (after a new request or a new origin).
void Renderer::writeProbePoints() {
  if (probeRequest_.exposure.empty()) return;
  const glm::dvec3 origin = renderOrigin_.value_or(glm::dvec3(0.0));
  std::vector<gpu::ProbePoint> points(size_t(MAX_EXPOSURE_PROBES) * EXPOSURE_SAMPLES);
  for (size_t i = 0; i < probeRequest_.exposure.size(); ++i) {
    const scene::ExposureProbeDesc& exposure = probeRequest_.exposure[i];
    for (size_t p = 0; p < exposure.points.size(); ++p) {
      const scene::ExposurePoint& point = exposure.points[p];
      points[i * EXPOSURE_SAMPLES + p] = {glm::vec4(toRenderSpace(point.position, origin), 1.0f),
                                          glm::vec4(point.normal, point.oneSided ? 1.0f : 0.0f)};
    }
  }
  probeSetup_.write(points.data(), points.size() * sizeof(gpu::ProbePoint),
                    sizeof(gpu::ProbeSetup));
}

// Centres render space on `origin` (the frame's camera): lights, probe points and, with the
// next TLAS update, instances move to it. Nothing changes while the camera stands still.
void Renderer::moveRenderOrigin(const glm::dvec3& origin) {
  if (renderOrigin_ == origin) return;
  renderOrigin_ = origin;
  tlasStale_ = true;
  for (size_t i = 0; i < gpuLights_.size(); ++i) {
    gpuLights_[i].positionType =
        glm::vec4(toRenderSpace(lightPositions_[i], origin), gpuLights_[i].positionType.w);
    gpuLights_[i].previousPosition =
        glm::vec4(toRenderSpace(lightPreviousPositions_[i], origin), 0.0f);
  }
  if (!gpuLights_.empty())
    lights_.write(gpuLights_.data(), gpuLights_.size() * sizeof(gpuLights_[0]));
  writeProbePoints();
}

// The routes of this frame's lights via the visible mirrors' faces, in render space.
void Renderer::writeLightRoutes() {
  if (!routeLight_) return;
  const glm::dvec3 origin = *renderOrigin_;
  std::vector<MirrorFace> faces;
  for (size_t i = 0; i < mirrorFaces_.size(); ++i) {
    if (mirrorFaces_[i].empty() || !instanceVisible_[i]) continue;
    const glm::mat4 transform = toRenderSpace(currentTransforms_[i], origin);
    const glm::mat3 linear(transform);
    const glm::mat3 normalTransform = glm::transpose(glm::inverse(linear));
    for (const scene::FlatFace& face : mirrorFaces_[i]) {
      const glm::vec3 normal = normalTransform * face.normal;
      if (!(glm::length(normal) > 0.0f)) continue;  // a mirror scaled flat
      faces.push_back({glm::normalize(normal), glm::vec3(transform * glm::vec4(face.centre, 1.0f)),
                       linear * face.halfU, linear * face.halfV, mirrorTints_[i]});
    }
  }
  std::vector<gpu::GpuLightRoute> routes = findLightRoutes(faces, gpuLights_, mirrorBounces_);
  const bool same = routes.size() == routes_.size() &&
                    std::equal(routes.begin(), routes.end(), routes_.begin(),
                               [](const gpu::GpuLightRoute& a, const gpu::GpuLightRoute& b) {
                                 return std::memcmp(&a, &b, sizeof a) == 0;
                               });
  if (same) return;
  sceneChanged_ = true;
  routes_ = std::move(routes);
  const gpu::LightRoutesHeader header{glm::uvec4(routes_.size(), 0, 0, 0)};
  lightRoutes_.write(&header, sizeof header);
  if (!routes_.empty())
    lightRoutes_.write(routes_.data(), routes_.size() * sizeof(gpu::GpuLightRoute), sizeof header);
}

void Renderer::setInstanceVisible(uint32_t instance, bool visible) {
  if (instance >= topLevel_->instanceCount())
    throw RenderError("setInstanceVisible: no such instance");
  if (instanceVisible_[instance] == visible) return;
  topLevel_->setVisible(instance, visible);
  if (glassLevel_) glassLevel_->setVisible(instance, visible);
  if (eyeLevel_) eyeLevel_->setVisible(instance, visible);
  instanceVisible_[instance] = visible;
  tlasStale_ = true;
  sceneChanged_ = true;
}

void Renderer::setInstanceGlow(uint32_t instance, float glow) {
  if (instance >= topLevel_->instanceCount())
    throw RenderError("setInstanceGlow: no such instance");
  if (instanceGlow_[instance] == glow) return;
  instanceGlow_[instance] = glow;
  sceneChanged_ = true;
  const uint32_t bits = std::bit_cast<uint32_t>(glow);
  instances_.write(&bits, sizeof bits,
                   instance * sizeof(gpu::GpuInstance) + offsetof(gpu::GpuInstance, geometry) +
                       3 * sizeof(uint32_t));
}

void Renderer::setLightTint(uint32_t light, const glm::vec3& tint) {
  if (light >= gpuLights_.size()) throw RenderError("setLightTint: no such light");
  const glm::vec3 radiance = lightRadiances_[light] * tint;
  if (glm::vec3(gpuLights_[light].radianceRadius) == radiance) return;
  sceneChanged_ = true;
  gpuLights_[light].radianceRadius = glm::vec4(radiance, gpuLights_[light].radianceRadius.w);
  lights_.write(&gpuLights_[light], sizeof(gpu::GpuLight), light * sizeof(gpu::GpuLight));
}

void Renderer::setLightPose(uint32_t light, const glm::vec3& position, const glm::vec3& direction) {
  if (light >= gpuLights_.size()) throw RenderError("setLightPose: no such light");
  const bool turned = glm::length(direction) > 0.0f &&
                      glm::vec3(gpuLights_[light].directionEnabled) != glm::normalize(direction);
  if (lightPositions_[light] == position && !turned) return;
  sceneChanged_ = true;
  // A turn alone is not motion: a light seen moves with its centre (writeLightMotion).
  if (lightPositions_[light] != position) lightsMovedSinceHistory_ = true;
  lightPositions_[light] = position;
  const glm::vec3 origin = renderOrigin_ ? toRenderSpace(position, *renderOrigin_) : position;
  gpuLights_[light].positionType = glm::vec4(origin, gpuLights_[light].positionType.w);
  if (glm::length(direction) > 0.0f) {
    gpuLights_[light].directionEnabled =
        glm::vec4(glm::normalize(direction), gpuLights_[light].directionEnabled.w);
  }
  lights_.write(&gpuLights_[light], sizeof(gpu::GpuLight), light * sizeof(gpu::GpuLight));
}

void Renderer::setLightEnabled(uint32_t light, bool enabled) {
  if (light >= gpuLights_.size()) throw RenderError("setLightEnabled: no such light");
  if ((gpuLights_[light].directionEnabled.w != 0.0f) == enabled) return;
  sceneChanged_ = true;
  gpuLights_[light].directionEnabled.w = enabled ? 1.0f : 0.0f;
  lights_.write(&gpuLights_[light], sizeof(gpu::GpuLight), light * sizeof(gpu::GpuLight));
}

void Renderer::setPictureSize(uint32_t width, uint32_t height) {
  if (width == 0 || height == 0 || width > options_.width || height > options_.height)
    throw RenderError("setPictureSize: " + std::to_string(width) + "x" + std::to_string(height) +
                      " is not within the render size " + std::to_string(options_.width) + "x" +
                      std::to_string(options_.height));
  pictureWidth_ = width;
  pictureHeight_ = height;
}

void Renderer::writeFrameUniforms(const scene::FrameDesc& frame, bool probeOnly) {
  // The render size's aspect for every picture size: the same view with fewer pixels.
  const CameraBasis camera =
      cameraBasis(frame.camera, float(options_.width) / float(options_.height));

  gpu::FrameUniforms uniforms{};
  uniforms.cameraPosition = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);  // render space is camera-centred
  uniforms.cameraRight = glm::vec4(camera.right, 0.0f);
  uniforms.cameraUp = glm::vec4(camera.up, 0.0f);
  uniforms.cameraForward = glm::vec4(camera.forward, 0.0f);
  uniforms.skyZenith = glm::vec4(environment_.skyZenith, 0.0f);
  uniforms.skyHorizon = glm::vec4(environment_.skyHorizon, 0.0f);
  uniforms.ambient = glm::vec4(environment_.ambient, 0.0f);
  const glm::uvec2 size = probeOnly ? glm::uvec2(options_.width, options_.height)
                                    : glm::uvec2(pictureWidth_, pictureHeight_);
  uniforms.sizeFrameLights = glm::uvec4(size, frame.frameIndex, lightCount_);
  uniforms.exposureTonemap = glm::vec4(frame.exposure, static_cast<float>(frame.tonemap),
                                       static_cast<float>(std::max(options_.rowGroups, 1u)), 0.0f);
  uniforms.mirrorBounces = glm::uvec4(mirrorBounces_, 0u, 0u, 0u);
  uniforms.pixelBuffers = glm::uvec4(options_.width, options_.height, 0u, 0u);
  const VkDeviceAddress sceneLevel = topLevel_->structure().address();
  const VkDeviceAddress eyeLevel = eyeLevel_ ? eyeLevel_->structure().address() : sceneLevel;
  uniforms.topLevels = glm::uvec4(uint32_t(sceneLevel), uint32_t(sceneLevel >> 32),
                                  uint32_t(eyeLevel), uint32_t(eyeLevel >> 32));
  // Reprojection needs the previous frame's camera; without one the history starts afresh.
  // A jump of the camera (a cut or teleport) is treated like an explicit reset: reprojecting
  // across it would only smear the old view.
  constexpr double kCutDistance = 1.0;
  constexpr float kCutCosine = 0.7f;
  const glm::dvec3 origin = renderOrigin_.value_or(glm::dvec3(0.0));
  const glm::dvec3 previousOrigin = historyOrigin_.value_or(origin);
  const bool cut = previousUniforms_ && (glm::distance(previousOrigin, origin) > kCutDistance ||
                                         glm::dot(glm::vec3(previousUniforms_->cameraForward),
                                                  camera.forward) < kCutCosine);
  const bool reset = frame.resetHistory || !previousUniforms_ || cut;
  const gpu::FrameUniforms& previous = previousUniforms_ ? *previousUniforms_ : uniforms;
  // The previous camera in this frame's render space.
  uniforms.previousCameraPosition = glm::vec4(glm::vec3(previousOrigin - origin), 1.0f);
  uniforms.previousCameraRight = previous.cameraRight;
  uniforms.previousCameraUp = previous.cameraUp;
  uniforms.previousCameraForward = previous.cameraForward;
  uniforms.previousSize =
      glm::uvec4(previous.sizeFrameLights.x, previous.sizeFrameLights.y, 0u, 0u);
  uniforms.denoise =
      glm::uvec4(reset ? 1u : 0u, frame.referenceAccumulation ? 1u : 0u, denoiserIterations(frame),
                 instancesMoved_ || lightsMoved_ ? 1u : 0u);
  if (probeOnly) {  // un-jittered, launched over the focus regions' box
    uniforms.probeLaunch =
        focusBox_ ? glm::uvec4(focusBox_->x0, focusBox_->y0, 1u, 0u) : glm::uvec4(0u, 0u, 1u, 0u);
  } else {
    const glm::vec2 jitter = upscaler_ ? TemporalUpscaler::jitter(jitterIndex_++) : frame.jitter;
    uniforms.upscale = glm::vec4(jitter, float(outputWidth()), float(outputHeight()));
  }
  if (!probeOnly) {
    // The camera in world space (its origin and basis) and the picture as the last full frame's.
    const bool viewHeld = !reset && origin == previousOrigin &&
                          uniforms.cameraRight == previous.cameraRight &&
                          uniforms.cameraUp == previous.cameraUp &&
                          uniforms.cameraForward == previous.cameraForward &&
                          uniforms.sizeFrameLights.x == previous.sizeFrameLights.x &&
                          uniforms.sizeFrameLights.y == previous.sizeFrameLights.y;
    // Steady: the exposure too, and no instance or light set to something else since.
    const bool steady =
        viewHeld && !sceneChanged_ && uniforms.exposureTonemap == previous.exposureTonemap;
    steadyFrames_ = steady ? steadyFrames_ + 1 : 0;
    viewHeld_ = viewHeld;
    const bool changed = sceneChanged_;
    sceneChanged_ = false;
    // Still (for the denoiser): no instance moved; lights may have changed.
    stillView_ =
        options_.stillViewDenoiser && viewHeld && !instancesMoved_ && !frame.referenceAccumulation;
    // A still view of a steady scene: penumbrae trace more samples, into a longer history that
    // is not clamped. After a change of an instance or a light, only once the usual history has
    // had time to forget what was before (a moving camera reprojects the history: no change).
    unchangedSinceReset_ = reset || (unchangedSinceReset_ && !changed);
    const bool nothingStale = unchangedSinceReset_ || steadyFrames_ >= kSteadyFramesToForgetAChange;
    uniforms.previousSize.z =
        options_.steadyPenumbraSamples && stillView_ && steady && nothingStale ? 1u : 0u;
  }
  frameUniforms_.write(&uniforms, sizeof uniforms);
  if (probeOnly) return;  // the next full frame reprojects from the last full one
  previousUniforms_ = uniforms;
  historyOrigin_ = origin;
}

void Renderer::recordFrame(VkCommandBuffer commands, bool readback, bool probeOnly) {
  auto stamp = [&](uint32_t query) {
    if (timestamps_)
      vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, timestamps_, query);
  };
  if (timestamps_) vkCmdResetQueryPool(commands, timestamps_, 0, kTimestampCount);
  stamp(0);
  // The previous frame's copy read the counters this fill clears.
  memoryBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, 0);
  vkCmdFillBuffer(commands, counters_.handle(), 0, VK_WHOLE_SIZE, 0);
  memoryBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
                VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
  if (tlasStale_) {
    // The previous trace read the TLAS; the update rewrites it.
    memoryBarrier(commands, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, 0,
                  VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, 0);
    std::vector<glm::mat4> renderTransforms;
    renderTransforms.reserve(currentTransforms_.size());
    for (const glm::mat4& transform : currentTransforms_)
      renderTransforms.push_back(toRenderSpace(transform, *renderOrigin_));
    topLevel_->recordUpdate(commands, renderTransforms);
    if (glassLevel_) glassLevel_->recordUpdate(commands, renderTransforms);
    if (eyeLevel_) eyeLevel_->recordUpdate(commands, renderTransforms);
    tlasStale_ = false;
    ++tlasUpdates_;
    memoryBarrier(commands, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                  VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR,
                  VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
                  VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR);
  }
  // Earlier frames' passes read and wrote what this frame's trace and passes overwrite.
  memoryBarrier(commands,
                VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT |
                    VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR |
                    VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                VK_ACCESS_SHADER_WRITE_BIT,
                VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
  vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR,
                    rayTracingPipeline_->handle());
  vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, pipelineLayout_, 0, 1,
                          &descriptorSets_[parity_], 0, nullptr);
  if (!probeOnly) {
    rayTracingPipeline_->recordTrace(commands, pictureWidth_, pictureHeight_);
    shownPicture_ = glm::uvec2(pictureWidth_, pictureHeight_);
  } else if (focusBox_) {
    rayTracingPipeline_->recordTrace(commands, focusBox_->x1 - focusBox_->x0,
                                     focusBox_->y1 - focusBox_->y0);
  }
  if (!probeRequest_.exposure.empty()) {
    // Both launches add into the probe results.
    memoryBarrier(commands, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
                  VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
                  VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    rayTracingPipeline_->recordProbeTrace(commands, EXPOSURE_SAMPLES,
                                          uint32_t(probeRequest_.exposure.size()));
  }
  memoryBarrier(commands, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_WRITE_BIT,
                VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_HOST_BIT,
                VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_HOST_READ_BIT);
  stamp(1);
  if (denoiser_ && !probeOnly) {
    denoiser_->recordInputCopies(commands, parity_, pictureWidth_, pictureHeight_);
    denoiser_->record(commands, pipelineLayout_, descriptorSets_[parity_], parity_, lastIterations_,
                      pictureWidth_, pictureHeight_, stillView_);
    memoryBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                  VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
  }
  stamp(2);
  if (!probeOnly) {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, tonemapPipeline_);
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayout_, 0, 1,
                            &descriptorSets_[parity_], 0, nullptr);
    vkCmdDispatch(commands, (pictureWidth_ + 7) / 8, (pictureHeight_ + 7) / 8, 1);
    if (upscaler_)
      upscaler_->record(commands, pipelineLayout_, descriptorSets_[parity_], parity_,
                        steadyFrames_ >= UPSCALE_STEADY_FRAMES_UNCLAMPED ? ResolveView::Steady
                        : viewHeld_                                      ? ResolveView::HeldCamera
                                                                         : ResolveView::Moving);
  }
  stamp(3);
  const VkImage picture = outputImage();
  if (readback && !probeOnly) {
    // The picture: the tonemap's (a compute shader) or the upscaler's.
    const VkPipelineStageFlags pictureStage =
        upscaler_ ? upscaler_->pictureStage()
                  : VkPipelineStageFlags{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT};
    const VkAccessFlags pictureAccess =
        upscaler_ ? upscaler_->pictureAccess() : VkAccessFlags{VK_ACCESS_SHADER_WRITE_BIT};
    imageLayoutBarrier(commands, picture, VK_IMAGE_LAYOUT_GENERAL,
                       VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, pictureStage, pictureAccess,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {shownWidth(), shownHeight(), 1};
    vkCmdCopyImageToBuffer(commands, picture, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           readback_.handle(), 1, &region);
    memoryBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
    // Back to GENERAL for the next frame's passes, after the copy has read it.
    imageLayoutBarrier(commands, picture, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, pictureStage,
                       pictureAccess);
  }
  // The counters, for the host: a few hundred bytes.
  memoryBarrier(commands, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_WRITE_BIT,
                VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  const VkBufferCopy counterCopy{0, 0, countersReadback_.size()};
  vkCmdCopyBuffer(commands, counters_.handle(), countersReadback_.handle(), 1, &counterCopy);
  memoryBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
  stamp(4);
}

VkImageView Renderer::outputView() const {
  return upscaler_ ? upscaler_->display().view() : outputImage_->view();
}

VkImage Renderer::outputImage() const {
  return upscaler_ ? upscaler_->display().image() : outputImage_->image();
}

uint32_t Renderer::denoiserIterations(const scene::FrameDesc& frame) const {
  return frame.referenceAccumulation ? 0u : std::min(options_.denoiserIterations, 5u);
}

std::vector<glm::vec4> Renderer::readDenoiser(DenoiserImage which) const {
  if (!denoiser_) throw RenderError("readDenoiser: this scene has no soft shadows");
  // The last frame rendered used the parity before the current one.
  return denoiser_->read(which, parity_ ^ 1u, lastIterations_);
}

std::vector<glm::vec4> Renderer::readRadiance() const {
  return readDeviceBuffer<glm::vec4>(context_, radiance_);
}

void Renderer::fillDenoiserHistory(const glm::vec4& history, const glm::vec4& moments) {
  if (!denoiser_) throw RenderError("fillDenoiserHistory: this scene has no soft shadows");
  denoiser_->fillHistory(parity_, history, moments);
}

void Renderer::writeDenoiserHistoryTexel(uint32_t x, uint32_t y, const glm::vec4& history,
                                         const glm::vec4& moments) {
  if (!denoiser_) throw RenderError("writeDenoiserHistoryTexel: this scene has no soft shadows");
  denoiser_->writeHistoryTexel(parity_, x, y, history, moments);
}

FrameStats Renderer::renderFrame(const scene::FrameDesc& frame, bool readback) {
  return submitFrame(frame, readback, false);
}

FrameStats Renderer::renderProbeFrame(const scene::FrameDesc& frame) {
  return submitFrame(frame, false, true);
}

void Renderer::runEachPicturePipelineOnce(
    const scene::FrameDesc& frame,
    const std::function<void(uint32_t done, uint32_t frames)>& afterEachFrame) {
  if (previousUniforms_)
    throw RenderError("runEachPicturePipelineOnce: only before the first full frame");
  // What a full frame changes and the first one would otherwise start from.
  const glm::uvec2 picture(pictureWidth_, pictureHeight_);
  const glm::uvec2 shownPicture = shownPicture_;
  const uint32_t jitterIndex = jitterIndex_;
  const uint32_t parity = parity_;
  const bool sceneChanged = sceneChanged_;
  const bool unchangedSinceReset = unchangedSinceReset_;

  constexpr uint32_t kFewPixels = 8;
  pictureWidth_ = std::min(kFewPixels, options_.width);
  pictureHeight_ = std::min(kFewPixels, options_.height);
  lastIterations_ = std::max(denoiserIterations(frame), 1u);
  moveRenderOrigin(glm::dvec3(frame.camera.position));
  writeLightRoutes();
  writeFrameUniforms(frame, false);  // a frame without history: nothing it reads matters
  // The passes of a moving view, of a camera held still and of a steady view, each of which
  // has pipelines of its own (the denoiser's temporal pass, the upscaler's resolve).
  struct View {
    bool held;
    uint32_t steadyFrames;
  };
  constexpr std::array kViews{View{false, 0}, View{true, 0},
                              View{true, UPSCALE_STEADY_FRAMES_UNCLAMPED}};
  // Each a frame of its own, submitted and waited for as frames are, ping-ponging likewise.
  for (uint32_t i = 0; i < kViews.size(); ++i) {
    viewHeld_ = kViews[i].held;
    stillView_ = kViews[i].held && options_.stillViewDenoiser;
    steadyFrames_ = kViews[i].steadyFrames;
    recordCommands(false, false);
    submitAndWaitForFrame();
    parity_ ^= 1u;
    if (afterEachFrame) afterEachFrame(i + 1, uint32_t(kViews.size()));
  }
  parity_ = parity;

  pictureWidth_ = picture.x;
  pictureHeight_ = picture.y;
  shownPicture_ = shownPicture;
  jitterIndex_ = jitterIndex;
  sceneChanged_ = sceneChanged;
  unchangedSinceReset_ = unchangedSinceReset;
  previousUniforms_.reset();
  historyOrigin_.reset();
  steadyFrames_ = 0;
  viewHeld_ = false;
  stillView_ = false;
}

FrameStats Renderer::submitFrame(const scene::FrameDesc& frame, bool readback, bool probeOnly) {
  if (!probeOnly) lastIterations_ = denoiserIterations(frame);
  moveRenderOrigin(glm::dvec3(frame.camera.position));
  writeInstanceMotion(!probeOnly);
  writeLightMotion(!probeOnly);
  writeLightRoutes();
  writeFrameUniforms(frame, probeOnly);

  recordCommands(readback, probeOnly);
  const auto start = std::chrono::steady_clock::now();
  submitAndWaitForFrame();
  const auto end = std::chrono::steady_clock::now();

  FrameStats stats;
  stats.milliseconds = std::chrono::duration<double, std::milli>(end - start).count();
  std::array<gpu::FrameCounters, COUNTER_SLOTS> slots{};
  countersReadback_.read(slots.data(), sizeof slots);
  gpu::FrameCounters counters{};
  for (const gpu::FrameCounters& slot : slots) {
    counters.surfaceRays += slot.surfaceRays;
    counters.secondaryRays += slot.secondaryRays;
  }
  if (timestamps_) {
    uint64_t ticks[kTimestampCount] = {};
    vkCheck(vkGetQueryPoolResults(context_.device(), timestamps_, 0, kTimestampCount, sizeof ticks,
                                  ticks, sizeof(uint64_t),
                                  VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
            "vkGetQueryPoolResults");
    const double msPerTick = context_.properties().limits.timestampPeriod * 1e-6;
    auto between = [&](int from, int to) { return double(ticks[to] - ticks[from]) * msPerTick; };
    stats.gpu = {between(0, 1), between(1, 2), between(2, 3), between(3, 4)};
  }
  gpu::ProbeResults probeResults{};
  countersReadback_.read(&probeResults, sizeof probeResults, sizeof slots);
  for (size_t i = 0; i < probeRequest_.focus.size(); ++i)
    probeCounts_.focusPixels[i] = probeResults.focusPixels[i];
  for (size_t i = 0; i < probeRequest_.exposure.size(); ++i)
    probeCounts_.exposureFixed[i] = probeResults.exposure[i];
  stats.surfaceRays = counters.surfaceRays;
  stats.secondaryRays = counters.secondaryRays;
  if (probeOnly) return stats;
  if (readback) {
    pixels_.resize(size_t(shownWidth()) * shownHeight() * 4);
    readback_.read(pixels_.data(), pixels_.size());
  }
  parity_ ^= 1u;
  return stats;
}

void Renderer::recordCommands(bool readback, bool probeOnly) {
  vkCheck(vkResetCommandBuffer(commands_, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo beginInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkCheck(vkBeginCommandBuffer(commands_, &beginInfo), "vkBeginCommandBuffer");
  recordFrame(commands_, readback, probeOnly);
  vkCheck(vkEndCommandBuffer(commands_), "vkEndCommandBuffer");
}

void Renderer::submitAndWaitForFrame() const {
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands_;
  vkCheck(vkQueueSubmit(context_.queue(), 1, &submit, frameDone_), "vkQueueSubmit");
  waitForFence(context_.device(), frameDone_, options_.waitSlice, options_.whileWaiting);
  vkCheck(vkResetFences(context_.device(), 1, &frameDone_), "vkResetFences");
}

}  // namespace render
