#pragma once
// The play window's picture scaled by the CPU, for CPU drivers: the renderer's image read back
// into host memory, doubled (or copied) into a host buffer, and copied into the window's image,
// centred, before the HUD and the overlay are drawn over it. On lavapipe, in a 1280x720 window,
// the present went from 4.2-5.0 ms a frame with the fragment pass that sampled the picture over
// every window pixel to 2.3-3.5, the wait for the X server included (docs/PERFORMANCE.md,
// session 38). GPUs keep the pass.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "render/buffer.hpp"

namespace render {

class Context;
class Renderer;

// Whether a window image of `format` (four 8-bit channels) holds each pixel blue first, where
// the renderer's pictures are red first.
constexpr bool isBlueFirst(VkFormat format) {
  return format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_B8G8R8A8_SRGB;
}

class HostScaledPicture {
 public:
  explicit HostScaledPicture(const Context& context);  // throws RenderError
  ~HostScaledPicture();
  HostScaledPicture(const HostScaledPicture&) = delete;
  HostScaledPicture& operator=(const HostScaledPicture&) = delete;

  // How many pixels a side the picture at twice (or once) its size may differ from the window's
  // and still be shown so, centred: cut at the window's edges, or with a black edge. The play
  // window's output size on a CPU driver is twice the render size, which is the window's times
  // the render scale, rounded: 1366x768 at 0.25 gives 684x384, doubled 1368x768.
  static constexpr uint32_t kSlackPixels = 2;

  // The factor (2, else 1) at which the renderer's picture fills a window of `window` pixels to
  // within kSlackPixels a side, where the window's images have 8-bit RGBA or BGRA pixels; 0 when
  // there is none (others take the pass).
  static uint32_t factorFor(const Renderer& renderer, VkExtent2D window, VkFormat format);

  // Reads the renderer's last picture (its passes finished: a submit waited for) and writes it,
  // at `factor` times its size with its channels in `format`'s order, into the upload buffer.
  // Only once no submitted recordUpload() of the last picture is pending. Throws RenderError.
  void readAndScale(const Renderer& renderer, uint32_t factor, VkFormat format);

  // Where the scaled picture lies in a window of `window` pixels: centred, its offset negative
  // where it is cut.
  VkRect2D placement(VkExtent2D window) const;

  // Copies the scaled picture (readAndScale) into `target` (a swapchain image of `window` pixels
  // whose acquire the submit waits for at the transfer stage), black where it does not reach,
  // leaving it in COLOR_ATTACHMENT_OPTIMAL, written.
  void recordUpload(VkCommandBuffer commands, VkImage target, VkExtent2D window) const;

 private:
  void release();

  const Context& context_;
  Buffer readBack_;      // the renderer's image as read back, RGBA8
  Buffer scaledPixels_;  // the picture scaled, in the window's channel order
  VkExtent2D scaledSize_{};
  // Each band's scratch space for doublePictureRows (allocated here: the bands' threads must not).
  std::vector<uint16_t> upperBandScratch_, lowerBandScratch_;
  VkCommandBuffer readCommands_ = VK_NULL_HANDLE;
  VkFence readDone_ = VK_NULL_HANDLE;
};

}  // namespace render
