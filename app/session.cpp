#include "app/session.hpp"

#include <algorithm>
#include <iostream>
#include <string>

namespace app {
namespace fs = std::filesystem;

render::ContextOptions contextOptions(const Options& options) {
  render::ContextOptions context;
  context.validate = options.validate;
  context.deviceSelector = options.device;
  return context;
}

render::ShaderCompiler makeCompiler(const fs::path& dataRoot) {
  return render::ShaderCompiler(dataRoot / "shaders",
                                render::ShaderCompiler::defaultCacheDirectory());
}

render::RendererOptions rendererOptionsFor(const Options& options, uint32_t width,
                                           uint32_t height) {
  render::RendererOptions rendererOptions;
  rendererOptions.width = width;
  rendererOptions.height = height;
  rendererOptions.rowGroups = options.rowGroups;
  rendererOptions.subgroupCounters = options.subgroupCounters;
  rendererOptions.lightRoutes = options.lightRoutes;
  if (options.upscaleSize) {
    if (options.upscaleSize->first < width || options.upscaleSize->second < height) {
      throw UsageError("--upscale: expected an output size at least the render size (" +
                       std::to_string(width) + "x" + std::to_string(height) + "), got " +
                       std::to_string(options.upscaleSize->first) + "x" +
                       std::to_string(options.upscaleSize->second));
    }
    rendererOptions.outputWidth = options.upscaleSize->first;
    rendererOptions.outputHeight = options.upscaleSize->second;
  }
  return rendererOptions;
}

scene::FrameDesc frameFor(const game::Level& level, const Options& options, uint32_t index) {
  scene::FrameDesc frame;
  frame.camera = level.camera;
  frame.exposure = options.exposure;
  frame.tonemap = options.tonemap;
  frame.frameIndex = index;
  return frame;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

int validationExitCode(const render::Context& context) {
  if (context.validationEnabled() && context.validationMessageCount() > 0) {
    std::cerr << "sightline: " << context.validationMessageCount()
              << " validation message(s) (see above)\n";
    return 3;
  }
  return 0;
}

}  // namespace app
