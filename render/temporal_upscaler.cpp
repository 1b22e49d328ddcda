#include "render/temporal_upscaler.hpp"

#include <stdexcept>
#include <string>

#include "render/context.hpp"
#include "render/denoiser.hpp"
#include "render/shader_compiler.hpp"
#include "shaders/shared_types.h"

namespace render {
namespace {

// The radical inverse of `index` in `base`: 1/2, 1/4, 3/4, ... for base 2.
float radicalInverse(uint32_t index, uint32_t base) {
  float result = 0.0f, digitWeight = 1.0f / float(base);
  for (; index > 0; index /= base, digitWeight /= float(base))
    result += float(index % base) * digitWeight;
  return result;
}

}  // namespace

glm::vec2 TemporalUpscaler::jitter(uint32_t index) {
  // Index 1 to 16: index 0 of the sequence is (0, 0), the pixel's corner.
  const uint32_t n = index % 16u + 1u;
  return glm::vec2(radicalInverse(n, 2), radicalInverse(n, 3)) - 0.5f;
}

TemporalUpscaler::TemporalUpscaler(const Context& context, uint32_t renderWidth,
                                   uint32_t renderHeight, uint32_t outputWidth,
                                   uint32_t outputHeight)
    : context_(context), outputWidth_(outputWidth), outputHeight_(outputHeight) {
  // The resolve weighs each sample by a bump one output pixel wide: with fewer output pixels
  // than samples, some pixels would get no sample's weight at all.
  if (outputWidth < renderWidth || outputHeight < renderHeight) {
    throw std::invalid_argument("temporal upscaling: the output size " +
                                std::to_string(outputWidth) + "x" + std::to_string(outputHeight) +
                                " is smaller than the render size " + std::to_string(renderWidth) +
                                "x" + std::to_string(renderHeight));
  }
  constexpr VkImageUsageFlags kCopyUsage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  motion_ = std::make_unique<StorageImage>(context, renderWidth, renderHeight,
                                           VK_FORMAT_R32G32B32A32_SFLOAT, 0, "upscale motion");
  display_ =
      std::make_unique<StorageImage>(context, outputWidth, outputHeight, VK_FORMAT_R8G8B8A8_UNORM,
                                     kCopyUsage, "upscaled display image");
  for (int parity = 0; parity < 2; ++parity) {
    const std::string suffix = parity ? " (odd frames)" : " (even frames)";
    history_[parity] =
        std::make_unique<StorageImage>(context, outputWidth, outputHeight,
                                       VK_FORMAT_R32G32B32A32_UINT, 0, "upscale history" + suffix);
  }
}

TemporalUpscaler::~TemporalUpscaler() {
  if (resolve_) vkDestroyPipeline(context_.device(), resolve_, nullptr);
}

std::vector<std::pair<uint32_t, VkImageView>> TemporalUpscaler::bindings(uint32_t parity) const {
  const uint32_t current = parity & 1u, previous = current ^ 1u;
  return {
      {BINDING_UPSCALE_MOTION, motion_->view()},
      {BINDING_UPSCALE_HISTORY, history_[previous]->view()},
      {BINDING_UPSCALE_HISTORY_NEXT, history_[current]->view()},
      {BINDING_DISPLAY_IMAGE, display_->view()},
  };
}

void TemporalUpscaler::createPipeline(ShaderCompiler& compiler, VkPipelineLayout layout) {
  resolve_ = createComputePipeline(
      context_, layout, compiler.compile("temporal_upscale.comp").spirv, "temporal upscale");
}

void TemporalUpscaler::record(VkCommandBuffer commands, VkPipelineLayout layout,
                              VkDescriptorSet set) const {
  vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0, nullptr);
  vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, resolve_);
  vkCmdDispatch(commands, (outputWidth_ + 7) / 8, (outputHeight_ + 7) / 8, 1);
}

}  // namespace render
