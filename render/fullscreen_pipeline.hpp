#pragma once
// Graphics pipelines that run a fragment shader once a pixel of a rectangle: fullscreen.vert's
// one triangle over the viewport, no vertex input, no culling, no blending. The upscaler's
// resolve on CPU drivers and the window's picture and HUD are drawn this way.
#include <cstdint>
#include <string>

#include <vulkan/vulkan.h>

#include "render/shader_compiler.hpp"

namespace render {

class Context;

// For subpass 0 of `renderPass`, writing its `colourAttachments` colour attachments. The
// viewport and scissor are dynamic: setDrawArea before each draw. Throws RenderError or
// ShaderCompileError.
VkPipeline createFullscreenPipeline(const Context& context, ShaderCompiler& compiler,
                                    VkPipelineLayout layout, VkRenderPass renderPass,
                                    uint32_t colourAttachments, const std::string& fragmentShader,
                                    const ShaderDefines& defines, const std::string& name);

// The viewport and the scissor of such a pipeline's next draws, both `area` of the framebuffer.
void setDrawArea(VkCommandBuffer commands, VkRect2D area);

}  // namespace render
