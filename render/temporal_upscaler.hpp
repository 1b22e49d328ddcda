#pragma once
// Temporal upscaling (TAAU): the camera rays are jittered by a sub-pixel sequence, and a pass
// accumulates each frame's picture into a history kept at the output size, which becomes the
// presented image (shaders/temporal_upscale.frag, drawn into the picture and the history as
// colour attachments).
#include <array>
#include <memory>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "render/storage_image.hpp"

namespace render {

class Context;
class ShaderCompiler;

class TemporalUpscaler {
 public:
  TemporalUpscaler(const Context& context, uint32_t renderWidth, uint32_t renderHeight,
                   uint32_t outputWidth, uint32_t outputHeight);
  ~TemporalUpscaler();
  TemporalUpscaler(const TemporalUpscaler&) = delete;
  TemporalUpscaler& operator=(const TemporalUpscaler&) = delete;

  // The camera rays' offset from the pixel centres in frame `index` (pixels, in [-0.5, 0.5)):
  // the Halton (2, 3) sequence, repeating every 16 frames.
  static glm::vec2 jitter(uint32_t index);

  // Storage images by binding for frame parity 0 or 1 ("previous" bindings get the other's).
  std::vector<std::pair<uint32_t, VkImageView>> bindings(uint32_t parity) const;
  void createPipeline(ShaderCompiler& compiler, VkPipelineLayout layout);
  // The resolve into frame parity `parity`'s history, ordered after this frame's tonemap and
  // ray-gen and after the earlier frames' reads of what it overwrites; a readback of the
  // picture after it waits for the colour attachment output stage.
  void record(VkCommandBuffer commands, VkPipelineLayout layout, VkDescriptorSet set,
              uint32_t parity) const;

  // The upscaled picture (R8G8B8A8_UNORM holding sRGB-encoded bytes), kept in GENERAL.
  const StorageImage& display() const { return *display_; }
  uint32_t outputWidth() const { return outputWidth_; }
  uint32_t outputHeight() const { return outputHeight_; }

 private:
  static constexpr VkFormat kDisplayFormat = VK_FORMAT_R8G8B8A8_UNORM;
  static constexpr VkFormat kHistoryFormat = VK_FORMAT_R32G32B32A32_UINT;
  void createRenderPass();

  const Context& context_;
  uint32_t outputWidth_, outputHeight_;
  std::unique_ptr<StorageImage> motion_, display_;
  std::array<std::unique_ptr<StorageImage>, 2> history_;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  std::array<VkFramebuffer, 2> framebuffers_{};  // by the parity of the history written
  VkPipeline resolve_ = VK_NULL_HANDLE;
};

}  // namespace render
