#include "render/temporal_upscaler.hpp"

#include <array>
#include <stdexcept>
#include <string>

#include "render/barriers.hpp"
#include "render/context.hpp"
#include "render/denoiser.hpp"
#include "render/fullscreen_pipeline.hpp"
#include "render/ray_tracing_pipeline.hpp"
#include "render/shader_compiler.hpp"
#include "render/vulkan_error.hpp"
#include "shaders/shared_types.h"

namespace render {
namespace {

// The fragment resolve's colour attachments: the picture and the history
// (UPSCALE_ATTACHMENT_DISPLAY and UPSCALE_ATTACHMENT_HISTORY).
constexpr uint32_t kResolveAttachments = 2;

// The radical inverse of `index` in `base`: 1/2, 1/4, 3/4, ... for base 2.
float radicalInverse(uint32_t index, uint32_t base) {
  float result = 0.0f, digitWeight = 1.0f / float(base);
  for (; index > 0; index /= base, digitWeight /= float(base))
    result += float(index % base) * digitWeight;
  return result;
}

// The resolve for `view`: a moving one, a camera held still (HELD_POINT_RESOLVE: a pixel around
// which nothing moved takes the history under it), or a steady one (STEADY_VIEW: each pixel's
// history where it is, unclamped), of a scene with mirrors or without (HAS_MIRRORS: a
// reflection's motion inside a mirror, the mirror's along its outline);
// shaders/temporal_upscale.glsl.
ShaderDefines resolveDefines(ResolveView view, bool mirrors) {
  return {{"STEADY_VIEW", view == ResolveView::Steady ? "1" : "0"},
          {"HAS_MIRRORS", mirrors ? "1" : "0"},
          {"HELD_POINT_RESOLVE", view == ResolveView::HeldCamera ? "1" : "0"}};
}
// Each resolve pipeline's name, by ResolveView.
constexpr std::array<const char*, kResolveViews> kResolveNames = {
    "temporal upscale", "temporal upscale, camera held", "temporal upscale, steady view"};

}  // namespace

glm::vec2 TemporalUpscaler::jitter(uint32_t index) {
  // Index 1 to 16: index 0 of the sequence is (0, 0), the pixel's corner.
  const uint32_t n = index % 16u + 1u;
  return glm::vec2(radicalInverse(n, 2), radicalInverse(n, 3)) - 0.5f;
}

TemporalUpscaler::TemporalUpscaler(const Context& context, uint32_t renderWidth,
                                   uint32_t renderHeight, uint32_t outputWidth,
                                   uint32_t outputHeight, ResolveWrites writes)
    : context_(context),
      outputWidth_(outputWidth),
      outputHeight_(outputHeight),
      attachments_(writes == ResolveWrites::Attachments ||
                   (writes == ResolveWrites::Auto && context.isCpuDevice())) {
  // The resolve weighs each sample by a bump one output pixel wide: with fewer output pixels
  // than samples, some pixels would get no sample's weight at all.
  if (outputWidth < renderWidth || outputHeight < renderHeight) {
    throw std::invalid_argument("temporal upscaling: the output size " +
                                std::to_string(outputWidth) + "x" + std::to_string(outputHeight) +
                                " is smaller than the render size " + std::to_string(renderWidth) +
                                "x" + std::to_string(renderHeight));
  }
  motion_ = pixelBuffer(context, renderWidth, renderHeight, sizeof(glm::vec4), "upscale motion");
  const VkImageUsageFlags written = attachments_ ? VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT : 0;
  display_ = std::make_unique<StorageImage>(
      context, outputWidth, outputHeight, kDisplayFormat,
      VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | written,
      "upscaled display image");
  for (int parity = 0; parity < 2; ++parity) {
    const std::string suffix = parity ? " (odd frames)" : " (even frames)";
    history_[parity] = std::make_unique<StorageImage>(
        context, outputWidth, outputHeight, kHistoryFormat, written, "upscale history" + suffix);
  }
  if (attachments_) createRenderPass();
}

TemporalUpscaler::~TemporalUpscaler() {
  const VkDevice device = context_.device();
  for (VkPipeline resolve : resolves_)
    if (resolve) vkDestroyPipeline(device, resolve, nullptr);
  for (VkFramebuffer framebuffer : framebuffers_)
    if (framebuffer) vkDestroyFramebuffer(device, framebuffer, nullptr);
  if (renderPass_) vkDestroyRenderPass(device, renderPass_, nullptr);
}

void TemporalUpscaler::createRenderPass() {
  // Both attachments stay in GENERAL (the shaders read the history as a storage image, the
  // picture is copied from and sampled by the window) and are written whole, so nothing is loaded;
  // the barriers in record() order the pass against everything else.
  std::array<VkAttachmentDescription, kResolveAttachments> attachments{};
  attachments[UPSCALE_ATTACHMENT_DISPLAY].format = kDisplayFormat;
  attachments[UPSCALE_ATTACHMENT_HISTORY].format = kHistoryFormat;
  for (VkAttachmentDescription& attachment : attachments) {
    attachment.samples = VK_SAMPLE_COUNT_1_BIT;
    attachment.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachment.initialLayout = VK_IMAGE_LAYOUT_GENERAL;
    attachment.finalLayout = VK_IMAGE_LAYOUT_GENERAL;
  }
  std::array<VkAttachmentReference, kResolveAttachments> references{};
  references[UPSCALE_ATTACHMENT_DISPLAY] = {UPSCALE_ATTACHMENT_DISPLAY, VK_IMAGE_LAYOUT_GENERAL};
  references[UPSCALE_ATTACHMENT_HISTORY] = {UPSCALE_ATTACHMENT_HISTORY, VK_IMAGE_LAYOUT_GENERAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = uint32_t(references.size());
  subpass.pColorAttachments = references.data();
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = uint32_t(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  vkCheck(vkCreateRenderPass(context_.device(), &info, nullptr, &renderPass_),
          "vkCreateRenderPass");
  context_.setName(renderPass_, VK_OBJECT_TYPE_RENDER_PASS, "temporal upscale");
  for (uint32_t parity = 0; parity < 2; ++parity) {
    std::array<VkImageView, kResolveAttachments> views{};
    views[UPSCALE_ATTACHMENT_DISPLAY] = display_->view();
    views[UPSCALE_ATTACHMENT_HISTORY] = history_[parity]->view();
    VkFramebufferCreateInfo framebufferInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    framebufferInfo.renderPass = renderPass_;
    framebufferInfo.attachmentCount = uint32_t(views.size());
    framebufferInfo.pAttachments = views.data();
    framebufferInfo.width = outputWidth_;
    framebufferInfo.height = outputHeight_;
    framebufferInfo.layers = 1;
    vkCheck(
        vkCreateFramebuffer(context_.device(), &framebufferInfo, nullptr, &framebuffers_[parity]),
        "vkCreateFramebuffer");
  }
}

std::vector<std::pair<uint32_t, VkImageView>> TemporalUpscaler::bindings(uint32_t parity) const {
  const uint32_t current = parity & 1u, previous = current ^ 1u;
  std::vector<std::pair<uint32_t, VkImageView>> images = {
      {BINDING_UPSCALE_HISTORY, history_[previous]->view()},
  };
  if (!attachments_) {
    images.push_back({BINDING_UPSCALE_HISTORY_NEXT, history_[current]->view()});
    images.push_back({BINDING_DISPLAY_IMAGE, display_->view()});
  }
  return images;
}

std::vector<std::pair<uint32_t, const Buffer*>> TemporalUpscaler::bufferBindings() const {
  return {{BINDING_UPSCALE_MOTION, &motion_}};
}

void TemporalUpscaler::createPipeline(ShaderCompiler& compiler, VkPipelineLayout layout,
                                      bool mirrors, bool heldPoints) {
  for (const ResolveView view :
       {ResolveView::Moving, ResolveView::HeldCamera, ResolveView::Steady}) {
    VkPipeline& resolve = resolves_[size_t(view)];
    // Without held points a held camera takes the moving view's pipeline (record()).
    if (view == ResolveView::HeldCamera && !heldPoints) continue;
    const ShaderDefines defines = resolveDefines(view, mirrors);
    resolve = attachments_
                  ? createFullscreenPipeline(context_, compiler, layout, renderPass_,
                                             kResolveAttachments, "temporal_upscale.frag", defines,
                                             kResolveNames[size_t(view)])
                  : createComputePipeline(context_, layout,
                                          compiler.compile("temporal_upscale.comp", defines).spirv,
                                          kResolveNames[size_t(view)]);
  }
}

VkPipelineStageFlags TemporalUpscaler::pictureStage() const {
  return attachments_ ? VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT
                      : VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
}

VkAccessFlags TemporalUpscaler::pictureAccess() const {
  return attachments_ ? VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT : VK_ACCESS_SHADER_WRITE_BIT;
}

void TemporalUpscaler::record(VkCommandBuffer commands, VkPipelineLayout layout,
                              VkDescriptorSet set, uint32_t parity, ResolveView view) const {
  const VkPipeline held = resolves_[size_t(ResolveView::HeldCamera)];
  const VkPipeline resolve = view == ResolveView::HeldCamera && !held
                                 ? resolves_[size_t(ResolveView::Moving)]
                                 : resolves_[size_t(view)];
  if (!attachments_) {
    // The tonemap's picture before the resolve reads it; the earlier frames' accesses of its
    // images are ordered by the renderer's barrier at the frame's start.
    memoryBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                  VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0,
                            nullptr);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, resolve);
    vkCmdDispatch(commands, (outputWidth_ + 7) / 8, (outputHeight_ + 7) / 8, 1);
    return;
  }
  // This frame's picture (the tonemap) and motion (ray-gen) before the fragment shader reads
  // them; the earlier frames' reads of the picture (copies) and of the history this pass
  // overwrites, and their writes of the history it reads, before the attachments' writes.
  memoryBarrier(
      commands,
      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR |
          VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
          VK_PIPELINE_STAGE_TRANSFER_BIT,
      VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
      VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = renderPass_;
  begin.framebuffer = framebuffers_[parity & 1u];
  begin.renderArea = {{0, 0}, {outputWidth_, outputHeight_}};
  vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set, 0,
                          nullptr);
  vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, resolve);
  setDrawArea(commands, begin.renderArea);
  vkCmdDraw(commands, 3, 1, 0, 0);
  vkCmdEndRenderPass(commands);
}

}  // namespace render
