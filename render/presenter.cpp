#include "render/presenter.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "render/barriers.hpp"
#include "render/context.hpp"
#include "render/renderer.hpp"
#include "render/storage_image.hpp"
#include "render/vulkan_error.hpp"

namespace render {
namespace {

constexpr VkFormat kDisplayFormat = VK_FORMAT_R8G8B8A8_UNORM;  // the renderer's output image

bool isSrgb(VkFormat format) {
  switch (format) {
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_A8B8G8R8_SRGB_PACK32:
      return true;
    default:
      return false;
  }
}

// A UNORM 8-bit format first (the bytes are already sRGB-encoded), then any non-sRGB format,
// then whatever the surface offers.
VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice physicalDevice, VkSurfaceKHR surface) {
  uint32_t count = 0;
  vkCheck(vkGetPhysicalDeviceSurfaceFormatsKHR(physicalDevice, surface, &count, nullptr),
          "vkGetPhysicalDeviceSurfaceFormatsKHR");
  std::vector<VkSurfaceFormatKHR> formats(count);
  vkCheck(vkGetPhysicalDeviceSurfaceFormatsKHR(physicalDevice, surface, &count, formats.data()),
          "vkGetPhysicalDeviceSurfaceFormatsKHR");
  if (formats.empty()) throw RenderError("the window surface offers no formats");
  for (VkFormat preferred : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM}) {
    for (const VkSurfaceFormatKHR& format : formats) {
      if (format.format == preferred && format.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
        return format;
    }
  }
  for (const VkSurfaceFormatKHR& format : formats)
    if (!isSrgb(format.format)) return format;
  return formats.front();
}

VkPresentModeKHR choosePresentMode(VkPhysicalDevice physicalDevice, VkSurfaceKHR surface,
                                   bool vsync) {
  if (vsync) return VK_PRESENT_MODE_FIFO_KHR;  // always supported
  uint32_t count = 0;
  vkCheck(vkGetPhysicalDeviceSurfacePresentModesKHR(physicalDevice, surface, &count, nullptr),
          "vkGetPhysicalDeviceSurfacePresentModesKHR");
  std::vector<VkPresentModeKHR> modes(count);
  vkCheck(vkGetPhysicalDeviceSurfacePresentModesKHR(physicalDevice, surface, &count, modes.data()),
          "vkGetPhysicalDeviceSurfacePresentModesKHR");
  for (VkPresentModeKHR preferred : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
    if (std::find(modes.begin(), modes.end(), preferred) != modes.end()) return preferred;
  return VK_PRESENT_MODE_FIFO_KHR;
}

VkSemaphore createSemaphore(VkDevice device) {
  VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VkSemaphore semaphore = VK_NULL_HANDLE;
  vkCheck(vkCreateSemaphore(device, &info, nullptr, &semaphore), "vkCreateSemaphore");
  return semaphore;
}

// The largest rectangle of the source's aspect ratio centred in the target.
VkRect2D fitRectangle(uint32_t sourceWidth, uint32_t sourceHeight, VkExtent2D target) {
  const double scale =
      std::min(double(target.width) / sourceWidth, double(target.height) / sourceHeight);
  const uint32_t width = std::max(1u, uint32_t(sourceWidth * scale + 0.5));
  const uint32_t height = std::max(1u, uint32_t(sourceHeight * scale + 0.5));
  const int32_t x = (int32_t(target.width) - int32_t(width)) / 2;
  const int32_t y = (int32_t(target.height) - int32_t(height)) / 2;
  return {{x, y}, {width, height}};
}

// The HUD's colours as the window's image gets them: sRGB-encoded like the picture.
std::array<float, 4> hudColour(HudColour colour) {
  constexpr std::array<std::array<uint8_t, 3>, size_t(HudColour::Count)> kBytes = {{
      {255, 255, 255},  // white
      {40, 40, 40},     // shade: bar backgrounds
      {86, 180, 233},   // sky blue: progress
      {0, 158, 115},    // bluish green: met, won
      {230, 159, 0},    // orange: exposure
      {213, 94, 0},     // vermillion: lost
  }};
  const std::array<uint8_t, 3>& bytes = kBytes.at(size_t(colour));
  return {bytes[0] / 255.0f, bytes[1] / 255.0f, bytes[2] / 255.0f, 1.0f};
}

}  // namespace

const char* Presenter::formatName(VkFormat format) {
  switch (format) {
    case VK_FORMAT_B8G8R8A8_UNORM:
      return "B8G8R8A8_UNORM";
    case VK_FORMAT_R8G8B8A8_UNORM:
      return "R8G8B8A8_UNORM";
    case VK_FORMAT_B8G8R8A8_SRGB:
      return "B8G8R8A8_SRGB";
    case VK_FORMAT_R8G8B8A8_SRGB:
      return "R8G8B8A8_SRGB";
    case VK_FORMAT_A2R10G10B10_UNORM_PACK32:
      return "A2R10G10B10_UNORM";
    case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
      return "A2B10G10R10_UNORM";
    case VK_FORMAT_R16G16B16A16_SFLOAT:
      return "R16G16B16A16_SFLOAT";
    default:
      return "other format";
  }
}

const char* Presenter::presentModeName(VkPresentModeKHR mode) {
  switch (mode) {
    case VK_PRESENT_MODE_FIFO_KHR:
      return "FIFO";
    case VK_PRESENT_MODE_FIFO_RELAXED_KHR:
      return "FIFO_RELAXED";
    case VK_PRESENT_MODE_MAILBOX_KHR:
      return "MAILBOX";
    case VK_PRESENT_MODE_IMMEDIATE_KHR:
      return "IMMEDIATE";
    default:
      return "other mode";
  }
}

Presenter::Presenter(const Context& context, GLFWwindow* window, bool vsync,
                     ShaderCompiler& compiler, bool hostScaling)
    : context_(context), window_(window), vsync_(vsync) {
  surface_.emplace(context, window);
  try {
    VkBool32 canPresent = VK_FALSE;
    vkCheck(vkGetPhysicalDeviceSurfaceSupportKHR(context.physicalDevice(), context.queueFamily(),
                                                 surface_->handle(), &canPresent),
            "vkGetPhysicalDeviceSurfaceSupportKHR");
    if (!canPresent) {
      throw RenderError(context.deviceInfo().name +
                        "'s ray tracing queue cannot present to this window");
    }
    // Linear filtering where the display format allows it: smoother at non-integer scales.
    VkFormatProperties displayProperties{};
    vkGetPhysicalDeviceFormatProperties(context.physicalDevice(), kDisplayFormat,
                                        &displayProperties);
    const VkFilter filter =
        displayProperties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT
            ? VK_FILTER_LINEAR
            : VK_FILTER_NEAREST;

    imageAcquired_ = createSemaphore(context.device());
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;  // nothing to wait for before the first frame
    vkCheck(vkCreateFence(context.device(), &fenceInfo, nullptr, &frameFinished_), "vkCreateFence");
    commands_ = context.allocateCommandBuffer();
    if (hostScaling && context.isCpuDevice()) hostPicture_.emplace(context);
    createSwapchain();
    windowPicture_.emplace(context, compiler, renderPass_, filter);
  } catch (...) {
    release();
    throw;
  }
}

Presenter::~Presenter() {
  release();
}

void Presenter::release() {
  const VkDevice device = context_.device();
  if (frameFinished_) vkWaitForFences(device, 1, &frameFinished_, VK_TRUE, UINT64_MAX);
  // Presentation has no fence of its own; the queue going idle covers the last present.
  vkQueueWaitIdle(context_.queue());
  windowPicture_.reset();
  hostPicture_.reset();
  destroySwapchainResources();
  if (swapchain_) vkDestroySwapchainKHR(device, swapchain_, nullptr);
  swapchain_ = VK_NULL_HANDLE;
  for (VkRenderPass* pass : {&renderPass_, &overPass_}) {
    if (*pass) vkDestroyRenderPass(device, *pass, nullptr);
    *pass = VK_NULL_HANDLE;
  }
  captureBuffer_ = Buffer();
  if (commands_) vkFreeCommandBuffers(device, context_.commandPool(), 1, &commands_);
  commands_ = VK_NULL_HANDLE;
  if (frameFinished_) vkDestroyFence(device, frameFinished_, nullptr);
  frameFinished_ = VK_NULL_HANDLE;
  if (imageAcquired_) vkDestroySemaphore(device, imageAcquired_, nullptr);
  imageAcquired_ = VK_NULL_HANDLE;
  surface_.reset();  // after its swapchain
}

void Presenter::setVsync(bool vsync) {
  if (vsync == vsync_) return;
  vsync_ = vsync;
  swapchainStale_ = true;
}

void Presenter::destroySwapchainResources() {
  const VkDevice device = context_.device();
  for (VkFramebuffer framebuffer : framebuffers_)
    vkDestroyFramebuffer(device, framebuffer, nullptr);
  framebuffers_.clear();
  for (VkImageView view : views_) vkDestroyImageView(device, view, nullptr);
  views_.clear();
  for (VkSemaphore semaphore : frameDrawn_) vkDestroySemaphore(device, semaphore, nullptr);
  frameDrawn_.clear();
  images_.clear();
}

void Presenter::createRenderPasses() {
  VkAttachmentDescription attachment{};
  attachment.format = format_;
  attachment.samples = VK_SAMPLE_COUNT_1_BIT;
  // renderPass_: every pixel is drawn, the picture and black beside it where it does not fill
  // the window.
  attachment.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachment.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  attachment.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  VkAttachmentReference colour{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colour;
  // After the acquire, whose semaphore the submit waits for at the colour output stage (the
  // layout transition too; for overPass_ at the transfer stage, before recordUpload's copy and
  // barriers); before presentation (which the semaphore orders).
  std::array<VkSubpassDependency, 2> dependencies{};
  dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[0].dstSubpass = 0;
  dependencies[0].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[0].srcAccessMask = 0;
  dependencies[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[0].dstAccessMask =
      VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[1].srcSubpass = 0;
  dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  // (The transfer stage too: a capture's copy, recorded next, waits for the final layout.)
  dependencies[1].dstStageMask =
      VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT;
  dependencies[1].dstAccessMask = 0;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &attachment;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = uint32_t(dependencies.size());
  info.pDependencies = dependencies.data();
  vkCheck(vkCreateRenderPass(context_.device(), &info, nullptr, &renderPass_),
          "vkCreateRenderPass");
  // overPass_: the picture is in the image already, copied in and left ready to draw over.
  attachment.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  attachment.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  vkCheck(vkCreateRenderPass(context_.device(), &info, nullptr, &overPass_), "vkCreateRenderPass");
}

void Presenter::createSwapchain() {
  const VkPhysicalDevice physicalDevice = context_.physicalDevice();
  VkSurfaceCapabilitiesKHR capabilities{};
  vkCheck(
      vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physicalDevice, surface_->handle(), &capabilities),
      "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
  if (!(capabilities.supportedUsageFlags & VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT))
    throw RenderError("the window surface's images cannot be drawn to");
  canCapture_ = (capabilities.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
  canUpload_ = (capabilities.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT) != 0;
  const VkSurfaceFormatKHR surfaceFormat = chooseFormat(physicalDevice, surface_->handle());
  presentMode_ = choosePresentMode(physicalDevice, surface_->handle(), vsync_);

  VkExtent2D extent = capabilities.currentExtent;
  if (extent.width == UINT32_MAX) {  // the surface takes its size from the swapchain
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    extent.width = std::clamp(uint32_t(std::max(width, 1)), capabilities.minImageExtent.width,
                              capabilities.maxImageExtent.width);
    extent.height = std::clamp(uint32_t(std::max(height, 1)), capabilities.minImageExtent.height,
                               capabilities.maxImageExtent.height);
  }
  uint32_t imageCount = capabilities.minImageCount + 1;
  if (capabilities.maxImageCount != 0)
    imageCount = std::min(imageCount, capabilities.maxImageCount);
  VkCompositeAlphaFlagBitsKHR compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  if (!(capabilities.supportedCompositeAlpha & compositeAlpha)) {
    for (VkCompositeAlphaFlagBitsKHR candidate :
         {VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR, VK_COMPOSITE_ALPHA_PRE_MULTIPLIED_BIT_KHR,
          VK_COMPOSITE_ALPHA_POST_MULTIPLIED_BIT_KHR}) {
      if (capabilities.supportedCompositeAlpha & candidate) {
        compositeAlpha = candidate;
        break;
      }
    }
  }

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_->handle();
  info.minImageCount = imageCount;
  info.imageFormat = surfaceFormat.format;
  info.imageColorSpace = surfaceFormat.colorSpace;
  info.imageExtent = extent;
  info.imageArrayLayers = 1;
  // Drawn to by the render pass; copied from for captures, and to for a picture the CPU scaled.
  info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  if (canCapture_) info.imageUsage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  if (hostPicture_ && canUpload_) info.imageUsage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = capabilities.currentTransform;
  info.compositeAlpha = compositeAlpha;
  info.presentMode = presentMode_;
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_;
  VkSwapchainKHR swapchain = VK_NULL_HANDLE;
  vkCheck(vkCreateSwapchainKHR(context_.device(), &info, nullptr, &swapchain),
          "vkCreateSwapchainKHR");
  destroySwapchainResources();
  if (swapchain_) vkDestroySwapchainKHR(context_.device(), swapchain_, nullptr);
  swapchain_ = swapchain;
  if (renderPass_ && surfaceFormat.format != format_) {
    // The pipelines (the picture's, the HUD's, the overlay's) were made for the old format's pass.
    throw RenderError("the window surface changed its format; restart the game");
  }
  format_ = surfaceFormat.format;
  extent_ = extent;
  minImageCount_ = std::max(2u, capabilities.minImageCount);

  uint32_t count = 0;
  vkCheck(vkGetSwapchainImagesKHR(context_.device(), swapchain_, &count, nullptr),
          "vkGetSwapchainImagesKHR");
  images_.resize(count);
  vkCheck(vkGetSwapchainImagesKHR(context_.device(), swapchain_, &count, images_.data()),
          "vkGetSwapchainImagesKHR");
  for (uint32_t i = 0; i < count; ++i) frameDrawn_.push_back(createSemaphore(context_.device()));
  if (!renderPass_) createRenderPasses();
  for (VkImage image : images_) {
    views_.push_back(createImageView(context_, image, format_, "swapchain image"));
    VkFramebufferCreateInfo framebufferInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    framebufferInfo.renderPass = renderPass_;
    framebufferInfo.attachmentCount = 1;
    framebufferInfo.pAttachments = &views_.back();
    framebufferInfo.width = extent_.width;
    framebufferInfo.height = extent_.height;
    framebufferInfo.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    vkCheck(vkCreateFramebuffer(context_.device(), &framebufferInfo, nullptr, &framebuffer),
            "vkCreateFramebuffer");
    framebuffers_.push_back(framebuffer);
  }
  swapchainStale_ = false;
}

void Presenter::recreateSwapchain() {
  vkCheck(vkWaitForFences(context_.device(), 1, &frameFinished_, VK_TRUE, UINT64_MAX),
          "vkWaitForFences");
  // The old images' semaphores may still be waited on by a queued present.
  vkCheck(vkQueueWaitIdle(context_.queue()), "vkQueueWaitIdle");
  createSwapchain();
}

PictureRect Presenter::pictureRect(uint32_t pictureWidth, uint32_t pictureHeight) const {
  const VkRect2D area = fitRectangle(pictureWidth, pictureHeight, extent_);
  return {area.offset.x, area.offset.y, int32_t(area.extent.width), int32_t(area.extent.height)};
}

void Presenter::captureNextPresent() {
  if (!canCapture_) throw RenderError("the window surface's images cannot be copied from");
  captureRequested_ = true;
}

void Presenter::collectCapture() {
  if (captureInFlight_) {
    vkCheck(vkWaitForFences(context_.device(), 1, &frameFinished_, VK_TRUE, UINT64_MAX),
            "vkWaitForFences");
    Rgba8Image image;
    image.width = extent_.width;
    image.height = extent_.height;
    image.pixels.resize(size_t(image.width) * image.height * 4);
    captureBuffer_.read(image.pixels.data(), image.pixels.size());
    const bool bgra = isBlueFirst(format_);
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
      if (bgra) std::swap(image.pixels[i], image.pixels[i + 2]);
      image.pixels[i + 3] = 255;  // the window is opaque
    }
    capture_ = std::move(image);
    captureInFlight_ = false;
  }
}

std::optional<Rgba8Image> Presenter::takeCapture() {
  collectCapture();
  std::optional<Rgba8Image> taken = std::move(capture_);
  capture_.reset();
  return taken;
}

bool Presenter::present(const Renderer& renderer, std::span<const HudRect> hud,
                        const OverlayDraw& overlay) {
  return presentFrame(&renderer, hud, overlay);
}

bool Presenter::presentWithoutPicture(const OverlayDraw& overlay) {
  return presentFrame(nullptr, {}, overlay);
}

bool Presenter::presentFrame(const Renderer* renderer, std::span<const HudRect> hud,
                             const OverlayDraw& overlay) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  if (width <= 0 || height <= 0) return false;  // minimised: nothing to show
  if (swapchainStale_ || uint32_t(width) != extent_.width || uint32_t(height) != extent_.height)
    recreateSwapchain();

  const VkDevice device = context_.device();
  collectCapture();  // keeps it for takeCapture; the buffer is free for the next one
  vkCheck(vkWaitForFences(device, 1, &frameFinished_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  // The last frame's upload has finished with the buffer: scale this one into it.
  const uint32_t hostFactor =
      renderer && scalesOnHost() ? HostScaledPicture::factorFor(*renderer, extent_, format_) : 0;
  const bool onHost = hostFactor != 0;
  if (onHost) hostPicture_->readAndScale(*renderer, hostFactor, format_);
  using Clock = std::chrono::steady_clock;
  auto millisecondsSince = [](Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  };
  uint32_t imageIndex = 0;
  const Clock::time_point acquireStarted = Clock::now();
  const VkResult acquired = vkAcquireNextImageKHR(device, swapchain_, UINT64_MAX, imageAcquired_,
                                                  VK_NULL_HANDLE, &imageIndex);
  displayWaitMilliseconds_ = millisecondsSince(acquireStarted);
  if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
    swapchainStale_ = true;  // the semaphore was not signalled; try again next frame
    return false;
  }
  if (acquired != VK_SUBOPTIMAL_KHR) vkCheck(acquired, "vkAcquireNextImageKHR");
  // Reset only once a submit that signals it is certain to follow.
  vkCheck(vkResetFences(device, 1, &frameFinished_), "vkResetFences");

  vkCheck(vkResetCommandBuffer(commands_, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo beginInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkCheck(vkBeginCommandBuffer(commands_, &beginInfo), "vkBeginCommandBuffer");
  recordFrame(commands_, renderer, imageIndex, onHost, hud, overlay);
  vkCheck(vkEndCommandBuffer(commands_), "vkEndCommandBuffer");

  // The render pass (or the scaled picture's copy) writes the image at the colour output
  // (transfer) stage: wait for the acquire there.
  const VkPipelineStageFlags waitStage =
      onHost ? VK_PIPELINE_STAGE_TRANSFER_BIT : VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &imageAcquired_;
  submit.pWaitDstStageMask = &waitStage;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands_;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &frameDrawn_[imageIndex];
  vkCheck(vkQueueSubmit(context_.queue(), 1, &submit, frameFinished_), "vkQueueSubmit");

  VkPresentInfoKHR presentInfo{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  presentInfo.waitSemaphoreCount = 1;
  presentInfo.pWaitSemaphores = &frameDrawn_[imageIndex];
  presentInfo.swapchainCount = 1;
  presentInfo.pSwapchains = &swapchain_;
  presentInfo.pImageIndices = &imageIndex;
  const Clock::time_point presentStarted = Clock::now();
  const VkResult presented = vkQueuePresentKHR(context_.queue(), &presentInfo);
  if (!context_.isCpuDevice()) displayWaitMilliseconds_ += millisecondsSince(presentStarted);
  if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR ||
      acquired == VK_SUBOPTIMAL_KHR) {
    swapchainStale_ = true;
  } else {
    vkCheck(presented, "vkQueuePresentKHR");
  }
  if (onHost) {
    ++hostScaledPresents_;
    // Let the X server take the image now rather than beside the next frame's passes (on a CPU
    // driver they share the cores).
    surface_->waitForServer();
  }
  return true;
}

void Presenter::recordCapture(VkCommandBuffer commands, VkImage target) {
  const VkDeviceSize bytes = VkDeviceSize(extent_.width) * extent_.height * 4;
  if (captureBuffer_.size() != bytes)
    captureBuffer_ = Buffer(context_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback,
                            "window capture");
  // After the render pass, which leaves the image ready to present (its last dependency
  // reaches the transfer stage, where this barrier starts).
  imageLayoutBarrier(commands, target, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_READ_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {extent_.width, extent_.height, 1};
  vkCmdCopyImageToBuffer(commands, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         captureBuffer_.handle(), 1, &region);
  memoryBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
  imageLayoutBarrier(commands, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                     VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
  captureRequested_ = false;
  captureInFlight_ = true;
}

void Presenter::recordFrame(VkCommandBuffer commands, const Renderer* renderer, uint32_t imageIndex,
                            bool onHost, std::span<const HudRect> hud, const OverlayDraw& overlay) {
  const VkImage source = renderer ? renderer->outputImage() : VK_NULL_HANDLE;
  const VkImage target = images_[imageIndex];
  const VkRect2D window{{0, 0}, extent_};
  // Where the picture lies, for the HUD too.
  const VkRect2D area =
      onHost     ? hostPicture_->placement(extent_)
      : renderer ? fitRectangle(renderer->outputWidth(), renderer->outputHeight(), extent_)
                 : window;
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.framebuffer = framebuffers_[imageIndex];
  begin.renderArea.extent = extent_;
  if (!renderer) {
    begin.renderPass = renderPass_;
    vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
    VkClearAttachment black{VK_IMAGE_ASPECT_COLOR_BIT, 0, {{{0.0f, 0.0f, 0.0f, 1.0f}}}};
    const VkClearRect everything{window, 0, 1};
    vkCmdClearAttachments(commands, 1, &black, 1, &everything);
  } else if (onHost) {
    // The upload fills the window, black where the picture does not reach.
    hostPicture_->recordUpload(commands, target, extent_);
    begin.renderPass = overPass_;
    vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
  } else {
    // The renderer's passes (and a readback copy with its layout changes) wrote the picture in
    // earlier submits; make all of it visible to the draw's reads. It stays in GENERAL.
    imageLayoutBarrier(commands, source, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                       VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT,
                       VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
    // The last frame's draw has finished (present() waited for its fence): the set is free.
    windowPicture_->setPicture(renderer->outputView());
    begin.renderPass = renderPass_;
    vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
    // Black bars where the window's aspect ratio differs from the picture's.
    if (area.offset.x != 0 || area.offset.y != 0 || area.extent.width != extent_.width ||
        area.extent.height != extent_.height)
      windowPicture_->fill(commands, window, {0.0f, 0.0f, 0.0f, 1.0f});
    windowPicture_->drawPicture(commands, area, renderer->shownWidth(), renderer->shownHeight(),
                                renderer->outputWidth(), renderer->outputHeight());
  }

  // The HUD over the picture, in order: a bar's fill lies over its background.
  const float width = float(area.extent.width), height = float(area.extent.height);
  for (const HudRect& rect : hud) {
    auto toX = [&](float fraction) {
      return std::clamp(area.offset.x + int32_t(std::lround(fraction * width)), 0,
                        int32_t(extent_.width));
    };
    auto toY = [&](float fraction) {
      return std::clamp(area.offset.y + int32_t(std::lround(fraction * height)), 0,
                        int32_t(extent_.height));
    };
    const int32_t x0 = toX(rect.x0), y0 = toY(rect.y0);
    const int32_t x1 = std::min(std::max(toX(rect.x1), x0 + 2), int32_t(extent_.width));
    const int32_t y1 = std::min(std::max(toY(rect.y1), y0 + 2), int32_t(extent_.height));
    if (x1 <= x0 || y1 <= y0) continue;
    windowPicture_->fill(commands, {{x0, y0}, {uint32_t(x1 - x0), uint32_t(y1 - y0)}},
                         hudColour(rect.colour));
  }
  if (overlay) overlay(commands);
  vkCmdEndRenderPass(commands);

  if (captureRequested_) recordCapture(commands, target);
  // The next frame's passes write the picture again only after this draw has read it.
  if (renderer && !onHost) {
    imageLayoutBarrier(commands, source, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                       VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                       VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
  }
}

}  // namespace render
