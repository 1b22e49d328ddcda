#pragma once
// One validated Vulkan context for all GPU tests; any validation message fails the test.
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "game/level.hpp"
#include "game/level_loader.hpp"
#include "render/context.hpp"
#include "render/image_io.hpp"
#include "render/renderer.hpp"
#include "render/shader_compiler.hpp"

namespace test {

inline std::filesystem::path sourceDir() {
  return SIGHTLINE_SOURCE_DIR;
}

class VulkanTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    render::ContextOptions options;
    options.validate = true;
    context_ = std::make_unique<render::Context>(options);
    compiler_ = std::make_unique<render::ShaderCompiler>(
        sourceDir() / "shaders", render::ShaderCompiler::defaultCacheDirectory());
  }
  static void TearDownTestSuite() {
    compiler_.reset();
    context_.reset();
  }
  void TearDown() override {
    const auto messages = context_->validationMessages();
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s), first: "
                                  << (messages.empty() ? "" : messages.front());
    context_->clearValidationMessages();
  }

  static render::Context& context() { return *context_; }
  static render::ShaderCompiler& compiler() { return *compiler_; }

  // Renders a level (JSON text) at the given size and returns the sRGB bytes.
  static render::Rgba8Image renderLevelText(const std::string& json, uint32_t width,
                                            uint32_t height, scene::Tonemap tonemap,
                                            float exposure = 1.0f) {
    const game::Level level = game::parseLevel(json, sourceDir() / "tests" / "inline_level.json");
    return renderLevel(level, width, height, tonemap, exposure);
  }

  static render::Rgba8Image renderLevel(const game::Level& level, uint32_t width, uint32_t height,
                                        scene::Tonemap tonemap, float exposure = 1.0f,
                                        uint32_t rowGroups = 8) {
    render::RendererOptions options;
    options.width = width;
    options.height = height;
    options.rowGroups = rowGroups;
    render::Renderer renderer(*context_, *compiler_, game::buildSceneDesc(level), options);
    scene::FrameDesc frame;
    frame.camera = level.camera;
    frame.tonemap = tonemap;
    frame.exposure = exposure;
    renderer.renderFrame(frame);
    return {width, height, renderer.pixels()};
  }

  static inline std::unique_ptr<render::Context> context_;
  static inline std::unique_ptr<render::ShaderCompiler> compiler_;
};

inline int channel(const render::Rgba8Image& image, uint32_t x, uint32_t y, int c) {
  return image.pixels[(size_t(y) * image.width + x) * 4 + c];
}

}  // namespace test
