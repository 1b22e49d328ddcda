#pragma once
// Temporal upscaling (TAAU): the camera rays are jittered by a sub-pixel sequence, and a pass
// accumulates each frame's picture into a history kept at the output size, which becomes the
// presented image (shaders/temporal_upscale.glsl).
#include <array>
#include <memory>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "render/buffer.hpp"
#include "render/shader_compiler.hpp"
#include "render/storage_image.hpp"

namespace render {

class Context;

// How the resolve writes the picture and the history: as a fragment shader's colour attachments
// or as a compute shader's image stores. The results are the same; Auto takes the attachments
// on CPU drivers (lavapipe writes them in whole vectors, image stores a lane at a time) and the
// image stores on GPUs (the H100's few raster units made the fragment pass 26 times slower).
enum class ResolveWrites { Auto, Attachments, ImageStores };

// Which of the resolve's pipelines a frame takes: each reads only what its kind of view needs
// (shaders/temporal_upscale.glsl).
enum class ResolveView {
  Moving,      // the camera or the picture size changed, or the history starts afresh: every
               // pixel's history reprojected by its samples' motion
  HeldCamera,  // the camera and picture size held, the scene not steady (something moves, or
               // has not held long enough): a pixel around which nothing moved reads no motion
               // (HELD_POINT_RESOLVE)
  Steady,      // the scene held UPSCALE_STEADY_FRAMES_UNCLAMPED full frames: each pixel's
               // history where it is, unclamped (STEADY_VIEW)
};
inline constexpr std::size_t kResolveViews = 3;

class TemporalUpscaler {
 public:
  TemporalUpscaler(const Context& context, uint32_t renderWidth, uint32_t renderHeight,
                   uint32_t outputWidth, uint32_t outputHeight, ResolveWrites writes);
  ~TemporalUpscaler();
  TemporalUpscaler(const TemporalUpscaler&) = delete;
  TemporalUpscaler& operator=(const TemporalUpscaler&) = delete;

  // The camera rays' offset from the pixel centres in frame `index` (pixels, in [-0.5, 0.5)):
  // the Halton (2, 3) sequence, repeating every 16 frames.
  static glm::vec2 jitter(uint32_t index);

  // Storage images by binding for frame parity 0 or 1 ("previous" bindings get the other's).
  std::vector<std::pair<uint32_t, VkImageView>> bindings(uint32_t parity) const;
  // Storage buffers by binding: ray-gen's motion, a vec4 a render pixel.
  std::vector<std::pair<uint32_t, const Buffer*>> bufferBindings() const;
  // `mirrors`: the scene has mirrors, whose reflections ray-gen gives a motion of their own.
  // `heldPoints`: under a camera held still, a pixel around which nothing moved reads no motion
  // (RendererOptions::heldPointResolve), in a pipeline of its own.
  void createPipeline(ShaderCompiler& compiler, VkPipelineLayout layout, bool mirrors,
                      bool heldPoints);
  // The resolve into frame parity `parity`'s history, ordered after this frame's tonemap and
  // ray-gen and after the earlier frames' reads of what it overwrites, with the pipeline
  // compiled for `view`.
  void record(VkCommandBuffer commands, VkPipelineLayout layout, VkDescriptorSet set,
              uint32_t parity, ResolveView view) const;
  // The stage and access that write the picture, for what reads it next.
  VkPipelineStageFlags pictureStage() const;
  VkAccessFlags pictureAccess() const;

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
  bool attachments_;  // the fragment shader's colour attachments, else image stores
  Buffer motion_;
  std::unique_ptr<StorageImage> display_;
  std::array<std::unique_ptr<StorageImage>, 2> history_;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  std::array<VkFramebuffer, 2> framebuffers_{};       // by the parity of the history written
  std::array<VkPipeline, kResolveViews> resolves_{};  // by ResolveView
};

}  // namespace render
