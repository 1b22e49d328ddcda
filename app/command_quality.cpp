// bench-quality: soft-shadow error against time, for raw sampling and the denoiser.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/csv_field.hpp"
#include "app/data_paths.hpp"
#include "app/quality_plot.hpp"
#include "app/session.hpp"
#include "game/level.hpp"
#include "game/level_loader.hpp"
#include "render/image_metrics.hpp"
#include "render/renderer.hpp"
#include "scene/color.hpp"

namespace app {
namespace fs = std::filesystem;

namespace {

// Samples for the ground truth; a stretch of the sequence far from the frames measured, so
// the reference is independent of them.
constexpr uint32_t kReferenceFirstFrame = 1u << 20;
constexpr uint32_t kWarmUpFrame = 1u << 21;  // a sequence index no measured frame uses

struct Images {
  std::vector<float> visibility;  // luminance of the visibility the final image used
  std::vector<float> display;     // luminance of the displayed sRGB values, in [0, 1]
};

struct Row {
  std::string configuration;
  uint32_t samples;
  uint32_t frames;
  double gpuMs;
  double visibilityRmse, visibilitySsim, imageRmse, imageSsim;
};

float luminance(const glm::vec3& rgb) {
  return glm::dot(rgb, glm::vec3(0.2126f, 0.7152f, 0.0722f));
}

Images capture(const render::Renderer& renderer) {
  Images images;
  for (const glm::vec4& texel : renderer.readDenoiser(render::DenoiserImage::Denoised))
    images.visibility.push_back(luminance(glm::vec3(texel)));
  const std::vector<uint8_t>& pixels = renderer.pixels();
  for (size_t i = 0; i < pixels.size(); i += 4) {
    images.display.push_back(
        luminance(glm::vec3(pixels[i], pixels[i + 1], pixels[i + 2]) / 255.0f));
  }
  return images;
}

scene::CameraDesc cameraAt(const game::Level& level, uint32_t frame, bool moving) {
  return moving ? strafed(level.camera, kStrafeStepMetres * float(frame)) : level.camera;
}

class QualityBench {
 public:
  QualityBench(const game::Level& level, const Options& options)
      : level_(level),
        options_(options),
        scene_(game::buildSceneDesc(level)),
        context_(contextOptions(options)),
        compiler_(makeCompiler(findDataRoot())) {}

  std::unique_ptr<render::Renderer> renderer() {
    render::RendererOptions rendererOptions =
        rendererOptionsFor(options_, options_.width, options_.height);
    rendererOptions.allFeatures = true;  // soft shadows even for a level that has none
    return std::make_unique<render::Renderer>(context_, compiler_, scene_, rendererOptions);
  }

  scene::FrameDesc frame(uint32_t index, const scene::CameraDesc& camera, bool reference) {
    scene::FrameDesc frame = frameFor(level_, options_, index);
    frame.camera = camera;
    frame.referenceAccumulation = reference;
    return frame;
  }

  Images reference(const scene::CameraDesc& camera, uint32_t samples) {
    auto r = renderer();
    for (uint32_t i = 0; i < samples; ++i)
      r->renderFrame(frame(kReferenceFirstFrame + i, camera, true), i + 1 == samples);
    return capture(*r);
  }

  // `frames` frames; raw: averaged with no denoiser. Returns the images and the GPU time: all
  // frames' for raw accumulation (that is its cost), the last frame's for the denoiser.
  std::pair<Images, double> run(uint32_t frames, bool raw, bool moving) {
    auto r = renderer();
    // A first frame pays for work lavapipe defers to the first dispatch (shader JIT), which its
    // timestamps include; render one, then start the measured run with a fresh history.
    r->renderFrame(frame(kWarmUpFrame, cameraAt(level_, 0, moving), raw), false);
    double gpuMs = 0.0;
    for (uint32_t i = 0; i < frames; ++i) {
      scene::FrameDesc desc = frame(i, cameraAt(level_, i, moving), raw);
      desc.resetHistory = i == 0;
      const render::FrameStats stats = r->renderFrame(desc, i + 1 == frames);
      const double frameMs = stats.gpu.traceMs + stats.gpu.denoiseMs + stats.gpu.tonemapMs;
      gpuMs = raw ? gpuMs + frameMs : frameMs;
    }
    return {capture(*r), gpuMs};
  }

  const render::Context& context() const { return context_; }

 private:
  const game::Level& level_;
  const Options& options_;
  scene::SceneDesc scene_;
  render::Context context_;
  render::ShaderCompiler compiler_;
};

Row measureRow(const std::string& name, uint32_t samples, uint32_t frames, double gpuMs,
               const Images& images, const Images& reference, uint32_t width, uint32_t height) {
  return {name,
          samples,
          frames,
          gpuMs,
          render::rootMeanSquareError(reference.visibility, images.visibility),
          render::structuralSimilarity(reference.visibility, images.visibility, width, height),
          render::rootMeanSquareError(reference.display, images.display),
          render::structuralSimilarity(reference.display, images.display, width, height)};
}

// A log-log plot of visibility RMSE against GPU milliseconds, one polyline per series.
void writePlot(const fs::path& file, const std::vector<Row>& rows, const std::string& title) {
  double minMs = 1e30, maxMs = 0, minError = 1e30, maxError = 0;
  for (const Row& row : rows) {
    minMs = std::min(minMs, row.gpuMs), maxMs = std::max(maxMs, row.gpuMs);
    minError = std::min(minError, row.visibilityRmse);
    maxError = std::max(maxError, row.visibilityRmse);
  }
  const double x0 = std::log10(std::max(minMs, 1e-4)) - 0.1, x1 = std::log10(maxMs) + 0.1;
  const double y0 = std::log10(std::max(minError, 1e-5)) - 0.1, y1 = std::log10(maxError) + 0.1;
  const PlotArea area;
  const double left = area.left, top = area.top, plotWidth = area.width, plotHeight = area.height;
  auto px = [&](double ms) { return left + (std::log10(ms) - x0) / (x1 - x0) * plotWidth; };
  auto py = [&](double error) { return top + (y1 - std::log10(error)) / (y1 - y0) * plotHeight; };
  std::ofstream svg(file);
  writePlotFrame(svg, area, title, "GPU time per result (ms, log)", "visibility RMSE (log)");
  for (int decade = int(std::ceil(x0)); decade <= int(std::floor(x1)); ++decade)
    svg << "<text x='" << px(std::pow(10.0, decade)) - 10 << "' y='" << top + plotHeight + 16
        << "'>1e" << decade << "</text>\n";
  for (int decade = int(std::ceil(y0)); decade <= int(std::floor(y1)); ++decade)
    svg << "<text x='" << left - 40 << "' y='" << py(std::pow(10.0, decade)) + 4 << "'>1e" << decade
        << "</text>\n";
  const std::vector<std::pair<std::string, std::string>> series = {
      {"raw", "#d62728"}, {"denoised static", "#1f77b4"}, {"denoised moving", "#2ca02c"}};
  int legend = 0;
  for (const auto& [prefix, colour] : series) {
    std::string points;
    for (const Row& row : rows) {
      if (row.configuration.rfind(prefix, 0) != 0) continue;
      points += std::to_string(px(row.gpuMs)) + "," + std::to_string(py(row.visibilityRmse)) + " ";
      svg << "<circle cx='" << px(row.gpuMs) << "' cy='" << py(row.visibilityRmse)
          << "' r='4' fill='" << colour << "'/>\n";
    }
    svg << "<polyline points='" << points << "' fill='none' stroke='" << colour << "'/>\n"
        << "<text x='" << left + plotWidth - 130 << "' y='" << top + 20 + 16 * legend++
        << "' fill='" << colour << "'>" << prefix << "</text>\n";
  }
  svg << "</svg>\n";
}

}  // namespace

int commandBenchQuality(const Options& options) {
  if (options.positional.size() != 1) throw UsageError("bench-quality: expected one level file");
  const fs::path levelFile = options.positional[0];
  const game::Level level = game::loadLevel(levelFile, levelLoadOptions());
  QualityBench bench(level, options);
  const uint32_t width = options.width, height = options.height;
  const uint32_t referenceSamples = options.samplesPerPixel;
  std::printf("%s at %ux%u on %s; reference: %u samples per pixel\n", level.name.c_str(), width,
              height, bench.context().deviceInfo().name.c_str(), referenceSamples);

  std::vector<Row> rows;
  const Images staticReference = bench.reference(cameraAt(level, 0, false), referenceSamples);
  for (uint32_t samples : {1u, 2u, 4u, 8u, 16u, 64u}) {
    const auto [images, ms] = bench.run(samples, true, false);
    rows.push_back(measureRow("raw " + std::to_string(samples) + " spp", samples, samples, ms,
                              images, staticReference, width, height));
  }
  for (uint32_t frames : {1u, 8u, 32u}) {
    const auto [images, ms] = bench.run(frames, false, false);
    rows.push_back(measureRow("denoised static after " + std::to_string(frames), 1, frames, ms,
                              images, staticReference, width, height));
  }
  for (uint32_t frames : {1u, 8u, 32u}) {
    const Images movingReference =
        bench.reference(cameraAt(level, frames - 1, true), referenceSamples);
    const auto [images, ms] = bench.run(frames, false, true);
    rows.push_back(measureRow("denoised moving after " + std::to_string(frames), 1, frames, ms,
                              images, movingReference, width, height));
  }

  const fs::path outDirectory = options.out.value_or(fs::path("out"));
  fs::create_directories(outDirectory);
  const fs::path csv = outDirectory / ("quality_" + levelFile.stem().string() + ".csv");
  const fs::path svg = outDirectory / ("quality_" + levelFile.stem().string() + ".svg");
  std::ofstream table(csv);
  table << "configuration,samples_per_frame,frames,gpu_ms,visibility_rmse,visibility_ssim,"
           "image_rmse,image_ssim\n";
  std::printf("%-28s %8s %10s %10s %10s %10s\n", "configuration", "GPU ms", "vis RMSE", "vis SSIM",
              "img RMSE", "img SSIM");
  for (const Row& row : rows) {
    table << csvField(row.configuration) << "," << row.samples << "," << row.frames << ","
          << row.gpuMs << "," << row.visibilityRmse << "," << row.visibilitySsim << ","
          << row.imageRmse << "," << row.imageSsim << "\n";
    std::printf("%-28s %8.3f %10.5f %10.4f %10.5f %10.4f\n", row.configuration.c_str(), row.gpuMs,
                row.visibilityRmse, row.visibilitySsim, row.imageRmse, row.imageSsim);
  }
  writePlot(svg, rows, level.name + ": soft-shadow error against GPU time");

  auto find = [&](const std::string& name) {
    return *std::find_if(rows.begin(), rows.end(),
                         [&](const Row& row) { return row.configuration == name; });
  };
  const Row raw1 = find("raw 1 spp"), raw64 = find("raw 64 spp");
  const Row static1 = find("denoised static after 1"), static32 = find("denoised static after 32");
  std::printf(
      "target: 1 spp + denoiser after 32 frames beats raw 64 spp at <= 1/8 of its time: "
      "RMSE %.5f vs %.5f, time %.3f vs %.3f ms -> %s\n",
      static32.visibilityRmse, raw64.visibilityRmse, static32.gpuMs, raw64.gpuMs,
      static32.visibilityRmse < raw64.visibilityRmse && static32.gpuMs <= raw64.gpuMs / 8
          ? "met"
          : "not met");
  std::printf("target: first frame denoised RMSE <= 0.5 x raw 1 spp: %.5f vs %.5f -> %s\n",
              static1.visibilityRmse, raw1.visibilityRmse,
              static1.visibilityRmse <= 0.5 * raw1.visibilityRmse ? "met" : "not met");
  std::printf("wrote %s and %s\n", fs::absolute(csv).c_str(), fs::absolute(svg).c_str());
  return validationExitCode(bench.context());
}

}  // namespace app
