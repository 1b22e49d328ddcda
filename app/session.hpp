#pragma once
// What the commands share: a Vulkan context and shader compiler set up from the options,
// frame descriptions, and small statistics.
#include <filesystem>
#include <vector>

#include "app/options.hpp"
#include "game/level.hpp"
#include "render/context.hpp"
#include "render/renderer.hpp"
#include "render/shader_compiler.hpp"

namespace app {

render::ContextOptions contextOptions(const Options& options);
render::ShaderCompiler makeCompiler(const std::filesystem::path& dataRoot);
// The renderer's settings the command line gives (size, row groups, subgroup counters).
render::RendererOptions rendererOptionsFor(const Options& options, uint32_t width, uint32_t height);
scene::FrameDesc frameFor(const game::Level& level, const Options& options, uint32_t index);
double median(std::vector<double> values);
// Non-zero (3) when the validation layer reported anything, after printing how many.
int validationExitCode(const render::Context& context);

}  // namespace app
