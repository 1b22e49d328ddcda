// bench-upscale: the presented picture's error against a supersampled reference at the output
// size, for today's bilinear upscale, a native render at twice the size, and temporal upscaling.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/csv_field.hpp"
#include "app/data_paths.hpp"
#include "app/quality_plot.hpp"
#include "app/session.hpp"
#include "game/level.hpp"
#include "game/level_loader.hpp"
#include "game/player_controller.hpp"
#include "render/image_io.hpp"
#include "render/image_metrics.hpp"
#include "render/renderer.hpp"
#include "render/temporal_upscaler.hpp"
#include "scene/color.hpp"

namespace app {
namespace fs = std::filesystem;

namespace {

// Sequence indices no measured frame uses, so the reference's samples are its own.
constexpr uint32_t kReferenceFirstFrame = 1u << 20;
// Frames a plain (not upscaled) picture renders before it is measured: the soft-shadow
// denoiser's history has settled by then.
constexpr uint32_t kSettleFrames = 32;
// The strafing camera: walking speed at 30 frames a second.
constexpr float kWalkPerFrame = game::PlayerSettings{}.walkSpeed / 30.0f;
constexpr uint32_t kLongestWalkFrames = 31;  // the moving run's last frame
// The moving run's last view, held still for as many frames.
constexpr const char* kStillAtWalkEnd = "TAAU still at the walk's end after 32";

struct Picture {
  uint32_t width = 0, height = 0;
  std::vector<float> rgb;  // sRGB-encoded values in [0, 1], 3 per pixel, rows top to bottom
};

struct Row {
  std::string configuration;
  uint32_t frames;
  double gpuMs;  // the frame's tonemap and upscale passes (the upscaler's cost over a plain frame)
  double rmse, ssim;
};

Picture pictureOf(const render::Renderer& renderer) {
  Picture picture{renderer.outputWidth(), renderer.outputHeight(), {}};
  const std::vector<uint8_t>& pixels = renderer.pixels();
  picture.rgb.reserve(pixels.size() / 4 * 3);
  for (size_t i = 0; i < pixels.size(); i += 4)
    for (size_t c = 0; c < 3; ++c) picture.rgb.push_back(float(pixels[i + c]) / 255.0f);
  return picture;
}

// What the window's linear filter makes of `source` at width x height: texel
// centres at (i + 0.5), edges clamped, on the encoded values (the swapchain is UNORM).
Picture bilinearUpscale(const Picture& source, uint32_t width, uint32_t height) {
  Picture result{width, height, std::vector<float>(size_t(width) * height * 3)};
  auto texel = [&](int x, int y, size_t c) {
    x = std::clamp(x, 0, int(source.width) - 1);
    y = std::clamp(y, 0, int(source.height) - 1);
    return source.rgb[(size_t(y) * source.width + size_t(x)) * 3 + c];
  };
  for (uint32_t y = 0; y < height; ++y) {
    const float v = (float(y) + 0.5f) * float(source.height) / float(height) - 0.5f;
    const int y0 = int(std::floor(v));
    const float fy = v - float(y0);
    for (uint32_t x = 0; x < width; ++x) {
      const float u = (float(x) + 0.5f) * float(source.width) / float(width) - 0.5f;
      const int x0 = int(std::floor(u));
      const float fx = u - float(x0);
      for (size_t c = 0; c < 3; ++c) {
        const float top = texel(x0, y0, c) * (1 - fx) + texel(x0 + 1, y0, c) * fx;
        const float bottom = texel(x0, y0 + 1, c) * (1 - fx) + texel(x0 + 1, y0 + 1, c) * fx;
        result.rgb[(size_t(y) * width + x) * 3 + c] = top * (1 - fy) + bottom * fy;
      }
    }
  }
  return result;
}

std::vector<float> luminance(const Picture& picture) {
  std::vector<float> result;
  result.reserve(picture.rgb.size() / 3);
  for (size_t i = 0; i < picture.rgb.size(); i += 3)
    result.push_back(0.2126f * picture.rgb[i] + 0.7152f * picture.rgb[i + 1] +
                     0.0722f * picture.rgb[i + 2]);
  return result;
}

class UpscaleBench {
 public:
  UpscaleBench(const game::Level& level, const Options& options)
      : level_(level),
        options_(options),
        walk_(walkWithRoom(level, kWalkPerFrame * float(kLongestWalkFrames))),
        scene_(game::buildSceneDesc(level)),
        context_(contextOptions(options)),
        compiler_(makeCompiler(findDataRoot())) {}

  std::unique_ptr<render::Renderer> renderer(uint32_t width, uint32_t height, uint32_t outputWidth,
                                             uint32_t outputHeight) {
    render::RendererOptions rendererOptions = rendererOptionsFor(options_, width, height);
    rendererOptions.outputWidth = outputWidth;
    rendererOptions.outputHeight = outputHeight;
    return std::make_unique<render::Renderer>(context_, compiler_, scene_, rendererOptions);
  }

  scene::FrameDesc frame(uint32_t index, const scene::CameraDesc& camera) const {
    scene::FrameDesc frame = frameFor(level_, options_, index);
    frame.camera = camera;
    return frame;
  }

  const char* walkName() const { return walk_.name; }

  // A side of the render size times --picture-scale, as play's dynamic render scale rounds it.
  uint32_t scaledSide(uint32_t side) const {
    return std::clamp(uint32_t(std::lround(float(side) * options_.pictureScale)), 1u, side);
  }

  // The camera walking at walking speed where the whole moving run has room, and past the run's
  // last frame back and forth over it: a player walks for longer than a second.
  scene::CameraDesc walkedAt(uint32_t frame) const {
    scene::CameraDesc camera = level_.camera;
    const uint32_t phase = frame % (2u * kLongestWalkFrames);
    const uint32_t along = phase <= kLongestWalkFrames ? phase : 2u * kLongestWalkFrames - phase;
    camera.position += walk_.direction * (kWalkPerFrame * float(along));
    return camera;
  }

  // The average, in linear light, of `samples` native frames at the output size with camera
  // rays jittered over the pixel (and raw soft-shadow samples accumulated).
  Picture reference(const scene::CameraDesc& camera, uint32_t width, uint32_t height,
                    uint32_t samples) {
    auto r = renderer(width, height, 0, 0);
    std::vector<double> sum(size_t(width) * height * 3, 0.0);
    for (uint32_t i = 0; i < samples; ++i) {
      scene::FrameDesc desc = frame(kReferenceFirstFrame + i, camera);
      desc.referenceAccumulation = true;
      desc.resetHistory = i == 0;
      desc.jitter = render::TemporalUpscaler::jitter(i * 7u + 3u) * 0.999f;
      r->renderFrame(desc, true);
      const Picture picture = pictureOf(*r);
      for (size_t k = 0; k < sum.size(); ++k) sum[k] += scene::srgbToLinear(picture.rgb[k]);
    }
    Picture result{width, height, std::vector<float>(sum.size())};
    for (size_t k = 0; k < sum.size(); ++k)
      result.rgb[k] = scene::linearToSrgb(float(sum[k] / samples));
    return result;
  }

  // A plain render at width x height after the denoiser settled, bilinearly upscaled.
  std::pair<Picture, double> plain(uint32_t width, uint32_t height, uint32_t outputWidth,
                                   uint32_t outputHeight) {
    auto r = renderer(width, height, 0, 0);
    render::FrameStats stats;
    for (uint32_t i = 0; i < kSettleFrames; ++i)
      stats = r->renderFrame(frame(i, level_.camera), i + 1 == kSettleFrames);
    return {bilinearUpscale(pictureOf(*r), outputWidth, outputHeight), stats.gpu.tonemapMs};
  }

  // Temporal upscaling after each of `checkpoints` frames, frame i seen from cameraAt(i).
  std::vector<std::pair<Picture, double>> upscaled(
      const std::vector<uint32_t>& checkpoints,
      const std::function<scene::CameraDesc(uint32_t)>& cameraAt, uint32_t outputWidth,
      uint32_t outputHeight) {
    auto r = renderer(options_.width, options_.height, outputWidth, outputHeight);
    r->setPictureSize(scaledSide(options_.width), scaledSide(options_.height));
    std::vector<std::pair<Picture, double>> results;
    const uint32_t last = checkpoints.back();
    for (uint32_t i = 1; i <= last; ++i) {
      const bool measured =
          std::find(checkpoints.begin(), checkpoints.end(), i) != checkpoints.end();
      const render::FrameStats stats = r->renderFrame(frame(i - 1, cameraAt(i - 1)), measured);
      if (measured) results.push_back({pictureOf(*r), stats.gpu.tonemapMs});
    }
    return results;
  }

  const render::Context& context() const { return context_; }

 private:
  const game::Level& level_;
  const Options& options_;
  Walk walk_;  // where the moving run has room
  scene::SceneDesc scene_;
  render::Context context_;
  render::ShaderCompiler compiler_;
};

void writePicture(const fs::path& file, const Picture& picture) {
  render::Rgba8Image image{picture.width, picture.height, {}};
  for (size_t i = 0; i < picture.rgb.size(); i += 3) {
    for (size_t c = 0; c < 3; ++c)
      image.pixels.push_back(
          uint8_t(std::lround(std::clamp(picture.rgb[i + c], 0.0f, 1.0f) * 255)));
    image.pixels.push_back(255);
  }
  render::writePng(file, image);
}

Row measure(const std::string& name, uint32_t frames, double gpuMs, const Picture& picture,
            const Picture& reference) {
  const std::vector<float> actual = luminance(picture), expected = luminance(reference);
  return {name, frames, gpuMs, render::rootMeanSquareError(expected, actual),
          render::structuralSimilarity(expected, actual, reference.width, reference.height)};
}

// RMSE against frames, one polyline per series (static, moving) and a line per fixed method.
void writePlot(const fs::path& file, const std::vector<Row>& rows, const std::string& title) {
  double maxError = 0.0;
  for (const Row& row : rows) maxError = std::max(maxError, row.rmse);
  const PlotArea area;
  const double left = area.left, top = area.top, plotWidth = area.width, plotHeight = area.height;
  const double maxFrames = 32;
  auto px = [&](double frames) { return left + frames / maxFrames * plotWidth; };
  auto py = [&](double error) { return top + (1.0 - error / (maxError * 1.1)) * plotHeight; };
  std::ofstream svg(file);
  writePlotFrame(svg, area, title, "frames", "luminance RMSE");
  for (int frames = 0; frames <= 32; frames += 8)
    svg << "<text x='" << px(frames) - 6 << "' y='" << top + plotHeight + 16 << "'>" << frames
        << "</text>\n";
  const std::vector<std::pair<std::string, std::string>> series = {
      {"TAAU static", "#0072B2"}, {"TAAU moving", "#009E73"}, {kStillAtWalkEnd, "#CC79A7"}};
  int legend = 0;
  for (const auto& [prefix, colour] : series) {
    std::string points;
    for (const Row& row : rows) {
      if (row.configuration.rfind(prefix, 0) != 0) continue;
      points += std::to_string(px(row.frames)) + "," + std::to_string(py(row.rmse)) + " ";
      svg << "<circle cx='" << px(row.frames) << "' cy='" << py(row.rmse) << "' r='4' fill='"
          << colour << "'/>\n";
    }
    svg << "<polyline points='" << points << "' fill='none' stroke='" << colour << "'/>\n"
        << "<text x='" << left + plotWidth - 250 << "' y='" << top + 20 + 16 * legend++
        << "' fill='" << colour << "'>" << prefix << "</text>\n";
  }
  for (const Row& row : rows) {
    if (row.configuration.rfind("TAAU", 0) == 0) continue;
    svg << "<line x1='" << left << "' x2='" << left + plotWidth << "' y1='" << py(row.rmse)
        << "' y2='" << py(row.rmse) << "' stroke='#D55E00' stroke-dasharray='4 3'/>\n"
        << "<text x='" << left + plotWidth - 250 << "' y='" << py(row.rmse) - 4
        << "' fill='#D55E00'>" << row.configuration << "</text>\n";
  }
  svg << "</svg>\n";
}

}  // namespace

int commandBenchUpscale(const Options& options) {
  if (options.positional.size() != 1) throw UsageError("bench-upscale: expected one level file");
  const fs::path levelFile = options.positional[0];
  const game::Level level = game::loadLevel(levelFile, levelLoadOptions());
  UpscaleBench bench(level, options);
  const auto [outputWidth, outputHeight] =
      options.upscaleSize.value_or(std::pair<uint32_t, uint32_t>(1280, 720));
  const uint32_t samples = options.samplesPerPixel;
  std::printf("%s: %ux%u -> %ux%u on %s; reference: %u jittered samples per pixel at %ux%u\n",
              level.name.c_str(), options.width, options.height, outputWidth, outputHeight,
              bench.context().deviceInfo().name.c_str(), samples, outputWidth, outputHeight);
  std::printf("moving: the camera walks %s at %.2f m a frame for %u frames, then back and forth\n",
              bench.walkName(), double(kWalkPerFrame), kLongestWalkFrames + 1);
  if (options.pictureScale < 1.0f)
    std::printf("the upscaled runs trace %ux%u of the %ux%u (--picture-scale %g)\n",
                bench.scaledSide(options.width), bench.scaledSide(options.height), options.width,
                options.height, double(options.pictureScale));

  const fs::path outDirectory = options.out.value_or(fs::path("out"));
  fs::create_directories(outDirectory);
  const std::string stem = levelFile.stem().string();
  std::vector<Row> rows;
  const Picture still = bench.reference(level.camera, outputWidth, outputHeight, samples);
  const auto [today, todayMs] =
      bench.plain(options.width, options.height, outputWidth, outputHeight);
  rows.push_back(measure("bilinear upscale (today)", 0, todayMs, today, still));
  writePicture(outDirectory / ("upscale_" + stem + "_bilinear.png"), today);
  writePicture(outDirectory / ("upscale_" + stem + "_reference.png"), still);
  const auto [native2x, native2xMs] =
      bench.plain(options.width * 2, options.height * 2, outputWidth, outputHeight);
  rows.push_back(measure("native 2x, bilinear upscale", 0, native2xMs, native2x, still));
  const std::vector<uint32_t> checkpoints = {1, 8, 16, 32};
  const auto atStart = [&](uint32_t) { return level.camera; };
  const auto walking = [&](uint32_t frame) { return bench.walkedAt(frame); };
  const auto atWalkEnd = [&](uint32_t) { return bench.walkedAt(kLongestWalkFrames); };
  const auto staticRuns = bench.upscaled(checkpoints, atStart, outputWidth, outputHeight);
  for (size_t i = 0; i < checkpoints.size(); ++i) {
    rows.push_back(measure("TAAU static after " + std::to_string(checkpoints[i]), checkpoints[i],
                           staticRuns[i].second, staticRuns[i].first, still));
  }
  writePicture(outDirectory / ("upscale_" + stem + "_taau_16.png"), staticRuns[2].first);
  // What play does on a CPU driver: upscaled to twice the render size, then scaled bilinearly.
  const auto doubled = bench.upscaled({16}, atStart, options.width * 2, options.height * 2);
  rows.push_back(measure("TAAU 2x after 16, bilinear upscale", 16, doubled[0].second,
                         bilinearUpscale(doubled[0].first, outputWidth, outputHeight), still));
  // After 96 frames the camera has walked the run out, back and out again, and just turned.
  const std::vector<uint32_t> movingCheckpoints = {8, 32, 96};
  const auto movingRuns = bench.upscaled(movingCheckpoints, walking, outputWidth, outputHeight);
  Picture walkEnd;
  for (size_t i = 0; i < movingCheckpoints.size(); ++i) {
    const uint32_t frames = movingCheckpoints[i];
    const Picture moved =
        bench.reference(bench.walkedAt(frames - 1), outputWidth, outputHeight, samples);
    rows.push_back(measure("TAAU moving after " + std::to_string(frames), frames,
                           movingRuns[i].second, movingRuns[i].first, moved));
    writePicture(outDirectory / ("upscale_" + stem + "_moving_" + std::to_string(frames) + ".png"),
                 movingRuns[i].first);
    if (frames - 1 == kLongestWalkFrames) walkEnd = moved;
  }
  // The same view as the moving run's last, held still: what walking there costs, apart from
  // what the view there holds.
  const auto stillAtWalkEnd = bench.upscaled({32}, atWalkEnd, outputWidth, outputHeight);
  rows.push_back(
      measure(kStillAtWalkEnd, 32, stillAtWalkEnd[0].second, stillAtWalkEnd[0].first, walkEnd));
  writePicture(outDirectory / ("upscale_" + stem + "_walk_end_still_32.png"),
               stillAtWalkEnd[0].first);
  writePicture(outDirectory / ("upscale_" + stem + "_walk_end_reference.png"), walkEnd);

  const fs::path csv = outDirectory / ("upscale_" + stem + ".csv");
  const fs::path svg = outDirectory / ("upscale_" + stem + ".svg");
  std::ofstream table(csv);
  table << "configuration,frames,tonemap_and_upscale_ms,rmse,ssim\n";
  std::printf("%-30s %8s %14s %10s %8s\n", "configuration", "frames", "tonemap+up ms", "RMSE",
              "SSIM");
  for (const Row& row : rows) {
    table << csvField(row.configuration) << "," << row.frames << "," << row.gpuMs << "," << row.rmse
          << "," << row.ssim << "\n";
    std::printf("%-30s %8u %14.3f %10.5f %8.4f\n", row.configuration.c_str(), row.frames, row.gpuMs,
                row.rmse, row.ssim);
  }
  writePlot(svg, rows, level.name + ": presented picture's error against a supersampled one");
  auto find = [&](const std::string& name) {
    return *std::find_if(rows.begin(), rows.end(),
                         [&](const Row& row) { return row.configuration == name; });
  };
  const Row taau16 = find("TAAU static after 16"), native = find("native 2x, bilinear upscale");
  const Row moving32 = find("TAAU moving after 32"), static32 = find("TAAU static after 32");
  const Row stillThere = find(kStillAtWalkEnd);
  const Row doubled16 = find("TAAU 2x after 16, bilinear upscale");
  std::printf(
      "target: TAAU 2x after 16 frames, upscaled, below native 2x upscaled: %.5f vs %.5f "
      "-> %s\n",
      doubled16.rmse, native.rmse, doubled16.rmse < native.rmse ? "met" : "not met");
  std::printf("target: TAAU after 16 frames below native 2x upscaled: %.5f vs %.5f -> %s\n",
              taau16.rmse, native.rmse, taau16.rmse < native.rmse ? "met" : "not met");
  std::printf(
      "target: moving within 1.5x the static error of the same view: %.5f vs %.5f -> %s "
      "(%.2fx; against the static error at the start, %.5f: %.2fx)\n",
      moving32.rmse, stillThere.rmse, moving32.rmse <= 1.5 * stillThere.rmse ? "met" : "not met",
      moving32.rmse / stillThere.rmse, static32.rmse, moving32.rmse / static32.rmse);
  std::printf("wrote %s and %s\n", fs::absolute(csv).c_str(), fs::absolute(svg).c_str());
  return validationExitCode(bench.context());
}

}  // namespace app
