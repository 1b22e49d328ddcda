#pragma once
// Soft-shadow denoiser: the images ray-gen fills for it, its history, and its compute passes
// (temporal reprojection with moments, then edge-avoiding a-trous iterations).
#include <array>
#include <initializer_list>
#include <memory>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "render/buffer.hpp"
#include "render/storage_image.hpp"

namespace render {

class Context;
class ShaderCompiler;

enum class DenoiserImage {
  RawVisibility,  // this frame's one-sample visibility (rgb)
  Denoised,       // after the last filter iteration (rgb), variance (a)
  Moments,        // this frame's luminance moments (x, y) and history length (z)
  SoftLight,      // this frame's unshadowed light of the soft lights (rgb), before visibility
  History,        // the history the next frame continues: visibility (rgb) and length (a)
};

// How the temporal pass reads each pixel's 5x5 neighbourhood (RendererOptions).
enum class NeighbourhoodReads { Auto, Tile, PerPixel };

// Which channels of visibility the temporal pass's neighbourhood statistics keep
// (RendererOptions): Auto keeps one where the visibility has no colour, Rgb all three always.
enum class VisibilityChannels { Auto, Rgb };

class Denoiser {
 public:
  // Its passes run in square work-groups, and the a-trous iterations only on those with
  // something to filter. On the H100 at 3840x2160 (02 / 06 / 07) 8x8 took 0.54 / 0.41 / 0.39 ms
  // where 16x16 took 0.57 / 0.43 / 0.40 (before the iterations skipped work-groups, 16 was the
  // fastest, 32 the slowest); on lavapipe 8 was no faster (docs/PERFORMANCE.md, session 13).
  static constexpr uint32_t kGpuGroupSize = 8;
  static constexpr uint32_t kCpuGroupSize = 16;

  Denoiser(const Context& context, uint32_t width, uint32_t height);
  ~Denoiser();
  Denoiser(const Denoiser&) = delete;
  Denoiser& operator=(const Denoiser&) = delete;

  // Storage images by binding for frame parity 0 or 1: "previous" bindings get the other
  // parity's images, so nothing is copied between frames.
  std::vector<std::pair<uint32_t, VkImageView>> bindings(uint32_t parity) const;
  // Storage buffers by binding (the same for both parities).
  std::vector<std::pair<uint32_t, const Buffer*>> bufferBindings() const;
  // Whether ray-gen (the raw visibility and the surface) and the temporal pass (the next moments
  // and history) write to buffers that are copied into the images their readers read (CPU
  // drivers; shaders/frame_bindings.glsl says why), rather than to the images
  // (BUFFERED_IMAGE_WRITES).
  bool writesThroughBuffers() const { return writesThroughBuffers_; }
  // Copies what ray-gen wrote of the raw visibility and the surface (top-left width x height, the
  // picture) into the images the passes read, those of frame parity `parity`; after ray-gen,
  // before the passes (nothing where not writesThroughBuffers()).
  void recordInputCopies(VkCommandBuffer commands, uint32_t parity, uint32_t width,
                         uint32_t height) const;

  // `reads`: Auto picks the shared-memory tile on GPUs and per-pixel reads on CPU drivers.
  // `greyVisibility`: the soft lights' visibility has no colour (no glass on a shadow ray's way).
  void createPipelines(ShaderCompiler& compiler, VkPipelineLayout layout, NeighbourhoodReads reads,
                       bool greyVisibility);

  // Temporal pass then `iterations` a-trous passes over the top-left width x height of the
  // images (the picture's size); the caller has ordered ray-gen's writes before and orders the
  // tonemap's reads after. Each call stamps a new frame.
  // `stillView`: the camera, the picture's size and every instance are as in the last full frame
  // (and this is neither a reset nor a reference accumulation); the temporal pass compiled for
  // that reads each pixel's own history.
  // `parity`: the frame parity of `set`.
  void record(VkCommandBuffer commands, VkPipelineLayout layout, VkDescriptorSet set,
              uint32_t parity, uint32_t iterations, uint32_t width, uint32_t height,
              bool stillView);

  // Test and debugging hooks (they submit and wait).
  std::vector<glm::vec4> read(DenoiserImage which, uint32_t parity, uint32_t iterations) const;
  // Overwrites the history the next frame (of parity `nextParity`) will read.
  void fillHistory(uint32_t nextParity, const glm::vec4& history, const glm::vec4& moments) const;
  // The same for one pixel of that history (rgba32f history and moments).
  void writeHistoryTexel(uint32_t nextParity, uint32_t x, uint32_t y, const glm::vec4& history,
                         const glm::vec4& moments) const;

 private:
  // Copies each buffer of `copies` (rows of width_ pixels) into its image's top-left width x
  // height, after `writers` and before `readers` (the images stay in GENERAL).
  void recordCopies(VkCommandBuffer commands,
                    std::initializer_list<std::pair<const Buffer*, VkImage>> copies,
                    VkPipelineStageFlags writers, VkPipelineStageFlags readers, uint32_t width,
                    uint32_t height) const;
  // The image that holds `which` (not SoftLight, a buffer that read() reads).
  const StorageImage& imageFor(DenoiserImage which, uint32_t parity, uint32_t iterations) const;

  const Context& context_;
  uint32_t width_, height_;
  uint32_t groupSize_;         // kGpuGroupSize or kCpuGroupSize
  bool writesThroughBuffers_;  // writesThroughBuffers()
  static constexpr VkFormat kVisibilityFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
  static constexpr VkFormat kSurfaceFormat = VK_FORMAT_R32G32B32A32_UINT;
  // Ray-gen's, a value per pixel (shaders/frame_bindings.glsl); where writesThroughBuffers(), the
  // raw visibility, the surface, the next moments and history in their images' formats.
  Buffer softLight_, motion_;
  Buffer visibilityWritten_, surfaceWritten_, momentsWritten_, historyWritten_;
  std::unique_ptr<StorageImage> visibilityRaw_, filterA_, filterB_;
  // One texel per work-group: the stamp of the last frame that left it something to filter;
  // and this frame's list of those work-groups, the a-trous iterations' indirect dispatch.
  std::unique_ptr<StorageImage> filterTiles_;
  Buffer filterTileList_;
  uint32_t tileStamp_ = 0;  // the images start at 0; the first frame stamps 1
  std::array<std::unique_ptr<StorageImage>, 2> surface_, history_, moments_;
  std::array<VkPipeline, 2> temporal_{};  // [0] any view, [1] a still view (STILL_VIEW)
  VkPipeline atrous_ = VK_NULL_HANDLE;
};

// Push constants of the denoiser's passes (matches denoise_common.glsl).
struct DenoiserPass {
  int32_t stepSize;
  int32_t readFromA;
  int32_t writeHistory;
  uint32_t tileStamp;
};

VkPipeline createComputePipeline(const Context& context, VkPipelineLayout layout,
                                 const std::vector<uint32_t>& spirv, const char* name);

}  // namespace render
