#pragma once
// Shows the renderer's output in a GLFW window: a surface, a swapchain and one render pass a
// frame that draws the picture scaled, the HUD's rectangles and the overlay (ImGui).
//
// The renderer's display image is R8G8B8A8_UNORM already holding sRGB-encoded bytes, so the
// swapchain prefers a UNORM format: writing them to an _SRGB image would encode a second time.
// The picture keeps its aspect ratio; the rest of the window is black. On CPU drivers, where it
// fills the window at once or twice its size (to within two pixels a side), the CPU scales it
// (HostScaledPicture).
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "render/buffer.hpp"
#include "render/host_scaled_picture.hpp"
#include "render/image_io.hpp"
#include "render/window_picture.hpp"
#include "render/window_surface.hpp"

struct GLFWwindow;

namespace render {

class Context;
class Renderer;
class ShaderCompiler;

// Colours of the heads-up display, from the Okabe-Ito palette so they stay apart for the
// common colour-vision deficiencies.
enum class HudColour : uint32_t { White, Shade, SkyBlue, BluishGreen, Orange, Vermillion, Count };

// A solid rectangle over the picture, in fractions of the shown image (0,0 top left, 1,1
// bottom right); at least 2 window pixels thick, so thin frames stay visible.
struct HudRect {
  float x0, y0, x1, y1;
  HudColour colour;
};

// Draws over the picture and the HUD, inside the presenter's render pass (the menus and text
// of Dear ImGui).
using OverlayDraw = std::function<void(VkCommandBuffer)>;

// Where the picture lands in the window, in window pixels.
struct PictureRect {
  int32_t x = 0, y = 0, width = 0, height = 0;
};

class Presenter {
 public:
  // The context must have been made with ContextOptions::presentation and the instance
  // extensions glfwGetRequiredInstanceExtensions names. `compiler` compiles the shaders that
  // draw the picture and the HUD. `hostScaling`: on a CPU driver, let the CPU scale the picture
  // where it can (false: the render pass samples it, as on GPUs). Throws RenderError, or
  // ShaderCompileError when one of those shaders does not compile.
  Presenter(const Context& context, GLFWwindow* window, bool vsync, ShaderCompiler& compiler,
            bool hostScaling = true);
  ~Presenter();
  Presenter(const Presenter&) = delete;
  Presenter& operator=(const Presenter&) = delete;

  // Draws the renderer's last frame into the window and queues it for display. Returns false
  // when nothing was shown (a minimised window, or a swapchain that had to be recreated).
  bool present(const Renderer& renderer, std::span<const HudRect> hud = {},
               const OverlayDraw& overlay = {});
  // The same with no picture: the window black under the overlay (the screen shown while a
  // level loads).
  bool presentWithoutPicture(const OverlayDraw& overlay);
  // How long the last present() waited for the display rather than worked (milliseconds): the
  // wait for a swapchain image, and on a GPU the present call itself, where vsync holds a frame
  // back. On a CPU driver the present call copies the picture to the window: that is work.
  double lastDisplayWaitMilliseconds() const { return displayWaitMilliseconds_; }

  // The next present that shows something also copies the window's image (the picture, the
  // HUD and the overlay) for takeCapture(). Throws RenderError when the surface's images
  // cannot be copied from.
  void captureNextPresent();
  // The copied image (RGBA, sRGB-encoded like the picture), once; empty until one is taken.
  std::optional<Rgba8Image> takeCapture();

  // The single-subpass render pass over one swapchain image in which the overlay draws, after
  // the picture and the HUD; it leaves the image ready to present.
  VkRenderPass renderPass() const { return renderPass_; }
  uint32_t imageCount() const { return uint32_t(images_.size()); }
  uint32_t minImageCount() const { return minImageCount_; }
  // The largest rectangle of the picture's aspect ratio centred in the window.
  PictureRect pictureRect(uint32_t pictureWidth, uint32_t pictureHeight) const;

  // FIFO when on; MAILBOX, else IMMEDIATE, when off and the surface has one. Recreates the
  // swapchain on the next present.
  void setVsync(bool vsync);
  bool vsync() const { return vsync_; }

  // Whether the surface talks to the X server over a connection of its own (WindowSurface).
  bool hasOwnXConnection() const { return surface_ && surface_->hasOwnConnection(); }
  VkExtent2D extent() const { return extent_; }
  VkFormat format() const { return format_; }
  VkPresentModeKHR presentMode() const { return presentMode_; }
  // Whether the CPU may scale the picture into the window (a CPU driver, and the window's images
  // can be copied to); it does where HostScaledPicture::factorFor finds a factor.
  bool scalesOnHost() const { return hostPicture_.has_value() && canUpload_; }
  // How many presents so far showed a picture the CPU scaled.
  uint64_t hostScaledPresents() const { return hostScaledPresents_; }

  static const char* formatName(VkFormat format);
  static const char* presentModeName(VkPresentModeKHR mode);

 private:
  void release();  // every Vulkan object, after the queue has finished with them
  void createSwapchain();
  void destroySwapchainResources();
  // Waits for the last frame's draw, then rebuilds the swapchain for the window's current size.
  void recreateSwapchain();
  // present and presentWithoutPicture (renderer null).
  bool presentFrame(const Renderer* renderer, std::span<const HudRect> hud,
                    const OverlayDraw& overlay);
  // `onHost`: the picture comes from hostPicture_ (read and scaled), not from the picture pass.
  // Without a renderer, black under the HUD and the overlay.
  void recordFrame(VkCommandBuffer commands, const Renderer* renderer, uint32_t imageIndex,
                   bool onHost, std::span<const HudRect> hud, const OverlayDraw& overlay);
  void recordCapture(VkCommandBuffer commands, VkImage target);
  void collectCapture();  // once the capturing frame has finished: its pixels into capture_
  void createRenderPasses();

  const Context& context_;
  GLFWwindow* window_;
  bool vsync_;
  double displayWaitMilliseconds_ = 0.0;  // lastDisplayWaitMilliseconds
  bool swapchainStale_ = false;           // resized, out of date, or vsync changed
  std::optional<WindowSurface> surface_;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkPresentModeKHR presentMode_ = VK_PRESENT_MODE_FIFO_KHR;
  VkExtent2D extent_{};
  std::vector<VkImage> images_;
  uint32_t minImageCount_ = 2;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  // Compatible with renderPass_ (the same framebuffers and pipelines), but keeps the image's
  // pixels: the HUD and the overlay over a picture the CPU scaled and copied in.
  VkRenderPass overPass_ = VK_NULL_HANDLE;
  std::vector<VkImageView> views_;                // one per image
  std::vector<VkFramebuffer> framebuffers_;       // one per image
  std::optional<WindowPicture> windowPicture_;    // its pipelines draw in renderPass_
  std::optional<HostScaledPicture> hostPicture_;  // on CPU drivers, unless asked not to
  bool canUpload_ = false;                        // the images allow TRANSFER_DST
  bool canCapture_ = false;                       // the images allow TRANSFER_SRC
  uint64_t hostScaledPresents_ = 0;
  bool captureRequested_ = false;
  Buffer captureBuffer_;  // holds the copy until the frame's fence
  bool captureInFlight_ = false;
  std::optional<Rgba8Image> capture_;
  // One per swapchain image: a present may still wait on its semaphore while the next frame
  // is recorded, and an image is only acquired again after its presentation is done.
  std::vector<VkSemaphore> frameDrawn_;
  VkSemaphore imageAcquired_ = VK_NULL_HANDLE;  // reusable once frameFinished_ has signalled
  VkFence frameFinished_ = VK_NULL_HANDLE;
  VkCommandBuffer commands_ = VK_NULL_HANDLE;
};

}  // namespace render
