#pragma once
// The play window's picture scaled by the CPU, for CPU drivers: the renderer's image read back
// into host memory, doubled (or copied) into a buffer the window's size, and copied into the
// window's image before the HUD and the overlay are drawn over it. On lavapipe, in a 1280x720
// window, the present went from 4.2-5.0 ms a frame with the fragment pass that sampled the
// picture over every window pixel to 2.0-3.1 (docs/PERFORMANCE.md, session 38). GPUs keep the
// pass.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "render/buffer.hpp"

namespace render {

class Context;
class Renderer;

class HostScaledPicture {
 public:
  explicit HostScaledPicture(const Context& context);  // throws RenderError
  ~HostScaledPicture();
  HostScaledPicture(const HostScaledPicture&) = delete;
  HostScaledPicture& operator=(const HostScaledPicture&) = delete;

  // Whether the renderer's picture fills a window of `window` pixels at exactly once or twice
  // its size (the play window's usual case on CPU drivers: 2x) and the window's images have
  // 8-bit RGBA or BGRA pixels; others take the pass.
  static bool fits(const Renderer& renderer, VkExtent2D window, VkFormat format);

  // Reads the renderer's last picture (its passes finished: a submit waited for) and writes it,
  // scaled to `window` with its channels in `format`'s order, into the upload buffer. Only once
  // no submitted recordUpload() of the last picture is pending. Throws RenderError.
  void readAndScale(const Renderer& renderer, VkExtent2D window, VkFormat format);

  // Copies the scaled picture (readAndScale) into all of `target` (a swapchain image whose acquire
  // the submit waits for at the transfer stage), leaving it in COLOR_ATTACHMENT_OPTIMAL, written.
  void recordUpload(VkCommandBuffer commands, VkImage target, VkExtent2D window) const;

 private:
  void release();

  const Context& context_;
  Buffer readBack_;      // the renderer's image as read back, RGBA8
  Buffer windowPixels_;  // the picture scaled to the window, in its channel order
  // Each band's scratch space for doublePictureRows (allocated here: the bands' threads must not).
  std::vector<uint16_t> upperBandScratch_, lowerBandScratch_;
  VkCommandBuffer readCommands_ = VK_NULL_HANDLE;
  VkFence readDone_ = VK_NULL_HANDLE;
};

}  // namespace render
