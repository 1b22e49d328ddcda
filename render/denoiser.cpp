#include "render/denoiser.hpp"

#include <cstddef>
#include <initializer_list>
#include <utility>

#include <glm/gtc/packing.hpp>

#include "render/barriers.hpp"
#include "render/buffer.hpp"
#include "render/context.hpp"
#include "render/ray_tracing_pipeline.hpp"
#include "render/shader_compiler.hpp"
#include "render/vulkan_error.hpp"
#include "shaders/shared_types.h"

namespace render {
namespace {

constexpr VkImageUsageFlags kDebugUsage =
    VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;

void computeBarrier(VkCommandBuffer commands) {
  memoryBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}

// Transitions for the debugging copies, which run alone in their own submission.
void layoutBarrier(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                   VkAccessFlags srcAccess, VkAccessFlags dstAccess) {
  imageLayoutBarrier(commands, image, from, to, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, srcAccess,
                     VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, dstAccess);
}

VkClearColorValue colorOf(const glm::vec4& value) {
  VkClearColorValue color{};
  color.float32[0] = value.x;
  color.float32[1] = value.y;
  color.float32[2] = value.z;
  color.float32[3] = value.w;
  return color;
}

// Fills each image (kept in GENERAL, created with TRANSFER_DST usage) with its colour; waits.
void clearImages(const Context& context,
                 std::initializer_list<std::pair<VkImage, VkClearColorValue>> images) {
  context.submitAndWait([&](VkCommandBuffer commands) {
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    for (const auto& [image, color] : images) {
      layoutBarrier(commands, image, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
                    VK_ACCESS_TRANSFER_WRITE_BIT);
      vkCmdClearColorImage(commands, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &color, 1,
                           &range);
      layoutBarrier(commands, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                    VK_ACCESS_TRANSFER_WRITE_BIT,
                    VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    }
  });
}

// The start of the filter tile list (FilterTileList in frame_bindings.glsl).
struct FilterTileListHeader {
  VkDispatchIndirectCommand dispatch;
  uint32_t listedTiles;
};

}  // namespace

VkPipeline createComputePipeline(const Context& context, VkPipelineLayout layout,
                                 const std::vector<uint32_t>& spirv, const char* name) {
  VkShaderModule module = createShaderModule(context, spirv, name);
  VkComputePipelineCreateInfo createInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  createInfo.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  createInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  createInfo.stage.module = module;
  createInfo.stage.pName = "main";
  createInfo.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkResult result = vkCreateComputePipelines(context.device(), VK_NULL_HANDLE, 1, &createInfo,
                                             nullptr, &pipeline);
  vkDestroyShaderModule(context.device(), module, nullptr);
  vkCheck(result, "vkCreateComputePipelines");
  context.setName(pipeline, VK_OBJECT_TYPE_PIPELINE, name);
  return pipeline;
}

Denoiser::Denoiser(const Context& context, uint32_t width, uint32_t height)
    : context_(context),
      width_(width),
      height_(height),
      groupSize_(context.isCpuDevice() ? kCpuGroupSize : kGpuGroupSize),
      writesThroughBuffers_(context.isCpuDevice()) {
  auto make = [&](VkFormat format, const char* name) {
    return std::make_unique<StorageImage>(context, width, height, format, kDebugUsage, name);
  };
  // Storage buffers of a value per pixel, which ray-gen or the temporal pass writes
  // (shaders/pixel_index.glsl says why).
  auto makePixelBuffer = [&](VkDeviceSize bytesPerPixel, const std::string& name) {
    return pixelBuffer(context, width, height, bytesPerPixel, name);
  };
  // Full floats: unshadowed light of a bright lamp passes half float's 65504 (then Inf, and
  // Inf times a visibility of 0 is NaN).
  softLight_ = makePixelBuffer(sizeof(glm::vec4), "soft light");
  // On CPU drivers ray-gen writes the raw visibility and the surface, and the temporal pass the
  // next moments and history, to buffers copied into the images their readers read;
  // elsewhere the shaders store to the images.
  if (writesThroughBuffers_) {
    visibilityWritten_ = makePixelBuffer(sizeof(uint64_t), "raw visibility written");
    surfaceWritten_ = makePixelBuffer(sizeof(glm::uvec4), "surface written");
    momentsWritten_ = makePixelBuffer(sizeof(uint64_t), "moments written");
    historyWritten_ = makePixelBuffer(sizeof(glm::vec4), "history written");
  }
  visibilityRaw_ = make(kVisibilityFormat, "raw visibility");
  // On GPUs the passes are limited by memory traffic, so what tolerates fewer bits has them
  // (docs/PERFORMANCE.md, session 12). The motion (an offset of a few pixels in half floats and
  // a distance) takes 8 bytes, as does the surface (a normal in two 16-bit numbers and a
  // distance); the distances stay full floats, since half floats end at 65504 and a level may be
  // large. The surface's image also holds its instance, so that one read gives both: on lavapipe
  // each image read costs alike whatever its size (docs/PERFORMANCE.md, session 19).
  // The moments steer the filter: half floats. The history (the estimate, and its length in
  // alpha) keeps full floats: a running average in half floats moves in steps of 1/2048 near 1
  // (07's error after 32 frames 9 % worse), and a reference accumulation counts past half
  // float's 2048 exact integers.
  motion_ = makePixelBuffer(sizeof(glm::uvec2), "motion");
  filterA_ = make(VK_FORMAT_R16G16B16A16_SFLOAT, "filter ping");
  filterB_ = make(VK_FORMAT_R16G16B16A16_SFLOAT, "filter pong");
  for (int parity = 0; parity < 2; ++parity) {
    const std::string suffix = parity ? " (odd frames)" : " (even frames)";
    surface_[parity] = make(kSurfaceFormat, ("surface" + suffix).c_str());
    history_[parity] = make(VK_FORMAT_R32G32B32A32_SFLOAT, ("history" + suffix).c_str());
    moments_[parity] = make(VK_FORMAT_R16G16B16A16_SFLOAT, ("moments" + suffix).c_str());
  }
  filterTiles_ = std::make_unique<StorageImage>(
      context, (width + groupSize_ - 1) / groupSize_, (height + groupSize_ - 1) / groupSize_,
      VK_FORMAT_R32_UINT, VK_IMAGE_USAGE_TRANSFER_DST_BIT, "filter tiles");
  clearImages(context, {{filterTiles_->image(), VkClearColorValue{}}});
  const VkDeviceSize tileCount = VkDeviceSize(filterTiles_->width()) * filterTiles_->height();
  filterTileList_ =
      Buffer(context, sizeof(FilterTileListHeader) + sizeof(uint32_t) * tileCount,
             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                 VK_BUFFER_USAGE_TRANSFER_DST_BIT,
             MemoryUse::DeviceOnly, "filter tile list");
  // Start with an empty history: length 0 everywhere, whatever the memory held.
  for (int parity = 0; parity < 2; ++parity)
    fillHistory(uint32_t(parity), glm::vec4(1.0f), glm::vec4(0.0f));
}

Denoiser::~Denoiser() {
  VkDevice device = context_.device();
  for (VkPipeline temporal : temporal_)
    if (temporal) vkDestroyPipeline(device, temporal, nullptr);
  if (atrous_) vkDestroyPipeline(device, atrous_, nullptr);
}

std::vector<std::pair<uint32_t, VkImageView>> Denoiser::bindings(uint32_t parity) const {
  const uint32_t current = parity & 1u, previous = current ^ 1u;
  return {
      {BINDING_VISIBILITY_RAW, visibilityRaw_->view()},
      {BINDING_SURFACE, surface_[current]->view()},
      {BINDING_SURFACE_PREVIOUS, surface_[previous]->view()},
      {BINDING_HISTORY, history_[previous]->view()},
      {BINDING_HISTORY_NEXT, history_[current]->view()},
      {BINDING_MOMENTS, moments_[previous]->view()},
      {BINDING_MOMENTS_NEXT, moments_[current]->view()},
      {BINDING_FILTER_A, filterA_->view()},
      {BINDING_FILTER_B, filterB_->view()},
      {BINDING_FILTER_TILES, filterTiles_->view()},
  };
}

void Denoiser::createPipelines(ShaderCompiler& compiler, VkPipelineLayout layout,
                               NeighbourhoodReads reads, bool greyVisibility) {
  const bool tile = reads == NeighbourhoodReads::Tile ||
                    (reads == NeighbourhoodReads::Auto && !context_.isCpuDevice());
  const std::string group = std::to_string(groupSize_);
  for (const bool stillView : {false, true}) {
    temporal_[stillView] = createComputePipeline(
        context_, layout,
        compiler
            .compile("denoise_temporal.comp",
                     {{"NEIGHBOURHOOD_TILE", tile ? "1" : "0"},
                      {"DENOISER_GROUP_SIZE", group},
                      {"GREY_VISIBILITY", greyVisibility ? "1" : "0"},
                      {"STILL_VIEW", stillView ? "1" : "0"},
                      {"BUFFERED_IMAGE_WRITES", writesThroughBuffers_ ? "1" : "0"}})
            .spirv,
        stillView ? "denoise temporal, still view" : "denoise temporal");
  }
  atrous_ = createComputePipeline(
      context_, layout,
      compiler.compile("denoise_atrous.comp", {{"DENOISER_GROUP_SIZE", group}}).spirv,
      "denoise a-trous");
}

void Denoiser::record(VkCommandBuffer commands, VkPipelineLayout layout, VkDescriptorSet set,
                      uint32_t parity, uint32_t iterations, uint32_t width, uint32_t height,
                      bool stillView) {
  // The temporal pass lists the work-groups with something to filter, from an empty list.
  memoryBarrier(commands,
                VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0,
                VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
  const FilterTileListHeader empty{{0, 0, 1}, 0};
  vkCmdUpdateBuffer(commands, filterTileList_.handle(), 0, sizeof empty, &empty);
  memoryBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
  DenoiserPass pass{0, 0, 0, ++tileStamp_};
  vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0, nullptr);
  vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, temporal_[stillView]);
  vkCmdPushConstants(commands, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof pass, &pass);
  vkCmdDispatch(commands, (width + groupSize_ - 1) / groupSize_,
                (height + groupSize_ - 1) / groupSize_, 1);
  memoryBarrier(
      commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
      VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
      VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
  if (writesThroughBuffers_) {
    // The next moments and history into their images, which the a-trous iterations read (and
    // the first may overwrite) and the next frame reprojects.
    const uint32_t current = parity & 1u;
    recordCopies(
        commands,
        {{&momentsWritten_, moments_[current]->image()},
         {&historyWritten_, history_[current]->image()}},
        VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
        VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, width,
        height);
  }
  vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, atrous_);
  for (uint32_t i = 0; i < iterations; ++i) {
    if (i > 0) computeBarrier(commands);
    pass.stepSize = int32_t(1u << i);
    pass.readFromA = i % 2 == 0 ? 1 : 0;
    pass.writeHistory = i == 0 ? 1 : 0;
    vkCmdPushConstants(commands, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof pass, &pass);
    vkCmdDispatchIndirect(commands, filterTileList_.handle(), 0);
  }
}

std::vector<std::pair<uint32_t, const Buffer*>> Denoiser::bufferBindings() const {
  std::vector<std::pair<uint32_t, const Buffer*>> buffers = {
      {BINDING_SOFT_LIGHT, &softLight_},
      {BINDING_MOTION, &motion_},
      {BINDING_FILTER_TILE_LIST, &filterTileList_},
  };
  if (writesThroughBuffers_) {
    buffers.push_back({BINDING_VISIBILITY_WRITTEN, &visibilityWritten_});
    buffers.push_back({BINDING_SURFACE_WRITTEN, &surfaceWritten_});
    buffers.push_back({BINDING_MOMENTS_WRITTEN, &momentsWritten_});
    buffers.push_back({BINDING_HISTORY_WRITTEN, &historyWritten_});
  }
  return buffers;
}

void Denoiser::recordCopies(VkCommandBuffer commands,
                            std::initializer_list<std::pair<const Buffer*, VkImage>> copies,
                            VkPipelineStageFlags writers, VkPipelineStageFlags readers,
                            uint32_t width, uint32_t height) const {
  memoryBarrier(commands, writers, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                VK_ACCESS_TRANSFER_READ_BIT);
  VkBufferImageCopy region{};
  region.bufferRowLength = width_;  // the buffers' rows are the render size's
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {width, height, 1};
  for (const auto& [written, image] : copies) {
    // After the earlier reads of the image (the frames before are ordered by the renderer's
    // barrier at the frame's start); back to GENERAL, where the shaders read it.
    imageLayoutBarrier(commands, image, VK_IMAGE_LAYOUT_GENERAL,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, readers, 0,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdCopyBufferToImage(commands, written->handle(), image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           1, &region);
    imageLayoutBarrier(commands, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                       VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_ACCESS_TRANSFER_WRITE_BIT, readers,
                       VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
  }
}

void Denoiser::recordInputCopies(VkCommandBuffer commands, uint32_t parity, uint32_t width,
                                 uint32_t height) const {
  if (!writesThroughBuffers_) return;  // ray-gen stored to the images
  recordCopies(commands,
               {{&visibilityWritten_, visibilityRaw_->image()},
                {&surfaceWritten_, surface_[parity & 1u]->image()}},
               VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
               VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
               width, height);
}

const StorageImage& Denoiser::imageFor(DenoiserImage which, uint32_t parity,
                                       uint32_t iterations) const {
  switch (which) {
    case DenoiserImage::Denoised:
      return iterations % 2 == 0 ? *filterA_ : *filterB_;
    case DenoiserImage::Moments:
      return *moments_[parity & 1u];
    case DenoiserImage::History:
      return *history_[parity & 1u];
    case DenoiserImage::RawVisibility:
      return *visibilityRaw_;
    case DenoiserImage::SoftLight:  // a buffer, which read() reads
      break;
  }
  return *filterA_;
}

std::vector<glm::vec4> Denoiser::read(DenoiserImage which, uint32_t parity,
                                      uint32_t iterations) const {
  if (which == DenoiserImage::SoftLight) return readDeviceBuffer<glm::vec4>(context_, softLight_);
  const bool halfFloats = which != DenoiserImage::History;
  std::vector<glm::vec4> texels =
      readTexels(context_, imageFor(which, parity, iterations), halfFloats);
  if (which == DenoiserImage::Moments) {
    // The history length as the history holds it, in full floats.
    const std::vector<glm::vec4> history = readTexels(context_, *history_[parity & 1u], false);
    for (size_t i = 0; i < texels.size(); ++i) texels[i].z = history[i].a;
  }
  return texels;
}

void Denoiser::fillHistory(uint32_t nextParity, const glm::vec4& history,
                           const glm::vec4& moments) const {
  const uint32_t previous = (nextParity & 1u) ^ 1u;
  // The history holds its length in alpha.
  const glm::vec4 historyTexel(glm::vec3(history), moments.z);
  clearImages(context_, {{history_[previous]->image(), colorOf(historyTexel)},
                         {moments_[previous]->image(), colorOf(moments)}});
}

void Denoiser::writeHistoryTexel(uint32_t nextParity, uint32_t x, uint32_t y,
                                 const glm::vec4& history, const glm::vec4& moments) const {
  if (x >= width_ || y >= height_) throw RenderError("writeHistoryTexel: pixel outside the image");
  const uint32_t previous = (nextParity & 1u) ^ 1u;
  // In the images' formats: the history full floats with its length in alpha, then the moments
  // half floats.
  struct {
    glm::vec4 history;
    uint64_t moments;
  } texels{glm::vec4(glm::vec3(history), moments.z), glm::packHalf4x16(moments)};
  Buffer staging(context_, sizeof texels, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload,
                 "history texel");
  staging.write(&texels, sizeof texels);
  context_.submitAndWait([&](VkCommandBuffer commands) {
    const VkImage images[2] = {history_[previous]->image(), moments_[previous]->image()};
    for (int i = 0; i < 2; ++i) {
      layoutBarrier(
          commands, images[i], VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
          VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
      VkBufferImageCopy region{};
      region.bufferOffset = i == 0 ? 0 : offsetof(decltype(texels), moments);
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      region.imageOffset = {int32_t(x), int32_t(y), 0};
      region.imageExtent = {1, 1, 1};
      vkCmdCopyBufferToImage(commands, staging.handle(), images[i],
                             VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
      layoutBarrier(commands, images[i], VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_GENERAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                    VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    }
  });
}

}  // namespace render
