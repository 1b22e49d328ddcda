// bench: median frame and pass times, ray throughput against the Embree CPU reference, and
// level switch time of every shipped level; a table, and optionally CSV and JSON.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/csv_field.hpp"
#include "app/data_paths.hpp"
#include "app/quality_plot.hpp"
#include "app/session.hpp"
#include "game/level.hpp"
#include "game/level_loader.hpp"
#include "reference/embree_tracer.hpp"
#include "render/frame_time_percentiles.hpp"
#include "render/pipeline_variant.hpp"
#include "render/renderer.hpp"
#include "sim/simulation.hpp"

namespace app {
namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct Measurement {
  double medianMs = 0.0;                     // host time from submit to fence
  render::FrameTimePercentiles percentiles;  // of the same host times
  render::PassTimes passMedians;             // each pass's median GPU time on its own
  uint64_t surfaceRays = 0, secondaryRays = 0;
  size_t triangles = 0;
  uint64_t rays() const { return surfaceRays + secondaryRays; }
};

struct ReferenceMeasurement {
  uint32_t frames = 0;
  double medianMs = 0.0;
  uint64_t rays = 0;
  double mraysPerSecond() const { return double(rays) / (medianMs * 1000.0); }
};

// Embree frames of the same rays, spread evenly between the renderer's frames so both see the
// same load on the machine (their ratio then holds on a busy machine too).
struct InterleavedReference {
  reference::EmbreeTracer* tracer = nullptr;  // none: no reference frames
  uint32_t frames = 0;
  ReferenceMeasurement result;
};

// The frame bench renders as its `index`th: the level's view, or with --strafe the view
// strafed kStrafeStepMetres (1 cm) a frame, as bench-quality's moving runs, back and forth over
// 32 of them.
scene::FrameDesc benchFrame(const game::Level& level, const Options& options, uint32_t index) {
  constexpr uint32_t kStrafeSteps = 32;
  scene::FrameDesc frame = frameFor(level, options, index);
  if (options.strafe) {
    const uint32_t phase = index % (2 * kStrafeSteps);
    const uint32_t steps = phase <= kStrafeSteps ? phase : 2 * kStrafeSteps - phase;
    frame.camera = strafed(level.camera, kStrafeStepMetres * float(steps));
  }
  return frame;
}

// Median host and per-pass GPU times over `frames` frames after 3 warm-up frames.
Measurement measure(const render::Context& context, render::ShaderCompiler& compiler,
                    const game::Level& level, const Options& options, uint32_t width,
                    uint32_t height, uint32_t frames, bool allFeatures,
                    InterleavedReference* reference = nullptr) {
  render::RendererOptions rendererOptions = rendererOptionsFor(options, width, height);
  rendererOptions.allFeatures = allFeatures;
  render::Renderer renderer(context, compiler, game::buildSceneDesc(level), rendererOptions);
  constexpr uint32_t kWarmUpFrames = 3;
  for (uint32_t i = 0; i < kWarmUpFrames; ++i)
    renderer.renderFrame(benchFrame(level, options, i), false);
  const bool withReference = reference && reference->tracer && reference->frames > 0;
  if (withReference) reference->tracer->traceFrame(level.camera, width, height);  // warm-up
  std::vector<double> times, trace, denoise, tonemap, readback, referenceTimes;
  Measurement result;
  for (uint32_t i = 0; i < frames; ++i) {
    const render::FrameStats stats =
        renderer.renderFrame(benchFrame(level, options, kWarmUpFrames + i), false);
    const uint64_t referenceFramesDue =
        withReference ? uint64_t(i + 1) * reference->frames / frames : 0;
    while (referenceTimes.size() < referenceFramesDue) {
      const reference::ReferenceFrame traced =
          reference->tracer->traceFrame(level.camera, width, height);
      referenceTimes.push_back(traced.milliseconds);
      reference->result.rays = traced.rays();
    }
    times.push_back(stats.milliseconds);
    trace.push_back(stats.gpu.traceMs);
    denoise.push_back(stats.gpu.denoiseMs);
    tonemap.push_back(stats.gpu.tonemapMs);
    readback.push_back(stats.gpu.readbackMs);
    result.surfaceRays = stats.surfaceRays;
    result.secondaryRays = stats.secondaryRays;
  }
  result.medianMs = median(times);
  result.percentiles = render::frameTimePercentiles(times);
  result.passMedians = {median(trace), median(denoise), median(tonemap), median(readback)};
  result.triangles = renderer.triangleCount();
  if (withReference) {
    reference->result.frames = reference->frames;
    reference->result.medianMs = median(referenceTimes);
  }
  return result;
}

// Switching to a level as play does it: load the file, then build the simulation (renderer,
// acceleration structures, pipeline variant, the first probe frame) and run each of the
// picture's pipelines once (Simulation::preparePictures).
struct LevelSwitch {
  double loadMs = 0.0, buildMs = 0.0;
  double totalMs() const { return loadMs + buildMs; }
};

LevelSwitch measureLevelSwitch(const render::Context& context, render::ShaderCompiler& compiler,
                               const fs::path& levelFile, uint32_t width, uint32_t height) {
  LevelSwitch result;
  const Clock::time_point start = Clock::now();
  const game::Level level = game::loadLevel(levelFile, levelLoadOptions());
  result.loadMs = millisecondsSince(start);
  const Clock::time_point buildStart = Clock::now();
  sim::SimulationOptions simulationOptions;
  simulationOptions.width = width;
  simulationOptions.height = height;
  sim::Simulation simulation(context, compiler, level, simulationOptions);
  simulation.preparePictures();
  result.buildMs = millisecondsSince(buildStart);
  return result;
}

struct BenchRow {
  std::string level;
  uint32_t width = 0, height = 0, frames = 0;
  Measurement own, all;
  LevelSwitch levelSwitch;
  std::optional<ReferenceMeasurement> embree;

  double fps() const { return 1000.0 / own.medianMs; }
  double mraysPerSecond() const { return double(own.rays()) / (own.medianMs * 1000.0); }
  // The rate over the trace pass alone (what the Embree frame does), or over the whole frame
  // where the device has no timestamps.
  double traceMraysPerSecond() const {
    const double ms = own.passMedians.traceMs > 0.0 ? own.passMedians.traceMs : own.medianMs;
    return double(own.rays()) / (ms * 1000.0);
  }
  double ownOverAll() const { return own.medianMs / all.medianMs; }
  // The trace pass's ray rate as a fraction of Embree's (only with an Embree measurement).
  double traceOverEmbree() const { return traceMraysPerSecond() / embree->mraysPerSecond(); }
};

void writeCsv(const fs::path& file, const std::vector<BenchRow>& rows) {
  std::ofstream out(file);
  out << "level,width,height,frames,median_ms,fps,mrays_per_s,rays_per_frame,trace_ms,"
         "denoise_ms,tonemap_ms,readback_ms,triangles,all_features_ms,own_over_all,"
         "level_load_ms,level_build_ms,level_switch_ms,trace_mrays_per_s,embree_frames,"
         "embree_median_ms,embree_rays_per_frame,embree_mrays_per_s,trace_over_embree\n";
  for (const BenchRow& row : rows) {
    const render::PassTimes& pass = row.own.passMedians;
    out << csvField(row.level) << ',' << row.width << ',' << row.height << ',' << row.frames << ','
        << row.own.medianMs << ',' << row.fps() << ',' << row.mraysPerSecond() << ','
        << row.own.rays() << ',' << pass.traceMs << ',' << pass.denoiseMs << ',' << pass.tonemapMs
        << ',' << pass.readbackMs << ',' << row.own.triangles << ',' << row.all.medianMs << ','
        << row.ownOverAll() << ',' << row.levelSwitch.loadMs << ',' << row.levelSwitch.buildMs
        << ',' << row.levelSwitch.totalMs() << ',' << row.traceMraysPerSecond() << ',';
    if (row.embree) {
      out << row.embree->frames << ',' << row.embree->medianMs << ',' << row.embree->rays << ','
          << row.embree->mraysPerSecond() << ',' << row.traceOverEmbree() << '\n';
    } else {
      out << "0,,,,\n";
    }
  }
  if (!out) throw std::runtime_error("bench: cannot write the CSV file " + file.string());
}

void writeJson(const fs::path& file, const render::Context& context, const Options& options,
               uint32_t embreeThreads, const std::vector<BenchRow>& rows) {
  nlohmann::ordered_json document;
  document["device"] = {{"name", context.deviceInfo().name},
                        {"driver", context.deviceInfo().driver},
                        {"type", render::deviceTypeName(context.deviceInfo().type)}};
  document["embree_threads"] = embreeThreads;
  // How the rows were rendered: the camera (--strafe) and the temporal upscaling (--upscale).
  document["camera"] = options.strafe ? "strafing" : "still";
  document["upscaled_to"] = options.upscaleSize
                                ? nlohmann::ordered_json{{"width", options.upscaleSize->first},
                                                         {"height", options.upscaleSize->second}}
                                : nlohmann::ordered_json(nullptr);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const BenchRow& row : rows) {
    const render::PassTimes& pass = row.own.passMedians;
    nlohmann::ordered_json entry = {{"level", row.level},
                                    {"width", row.width},
                                    {"height", row.height},
                                    {"frames", row.frames},
                                    {"median_ms", row.own.medianMs},
                                    {"p95_ms", row.own.percentiles.p95},
                                    {"p99_ms", row.own.percentiles.p99},
                                    {"worst_ms", row.own.percentiles.worst},
                                    {"fps", row.fps()},
                                    {"mrays_per_s", row.mraysPerSecond()},
                                    {"surface_rays_per_frame", row.own.surfaceRays},
                                    {"secondary_rays_per_frame", row.own.secondaryRays},
                                    {"gpu_pass_median_ms",
                                     {{"trace", pass.traceMs},
                                      {"denoise", pass.denoiseMs},
                                      {"tonemap", pass.tonemapMs},
                                      {"readback", pass.readbackMs}}},
                                    {"triangles", row.own.triangles},
                                    {"all_features_ms", row.all.medianMs},
                                    {"own_over_all", row.ownOverAll()},
                                    {"level_switch_ms",
                                     {{"load", row.levelSwitch.loadMs},
                                      {"build", row.levelSwitch.buildMs},
                                      {"total", row.levelSwitch.totalMs()}}},
                                    {"trace_mrays_per_s", row.traceMraysPerSecond()}};
    if (row.embree) {
      entry["embree"] = {{"frames", row.embree->frames},
                         {"median_ms", row.embree->medianMs},
                         {"rays_per_frame", row.embree->rays},
                         {"mrays_per_s", row.embree->mraysPerSecond()},
                         {"trace_over_embree", row.traceOverEmbree()}};
    } else {
      entry["embree"] = nullptr;
    }
    list.push_back(std::move(entry));
  }
  document["rows"] = std::move(list);
  std::ofstream out(file);
  out << document.dump(2) << '\n';
  if (!out) throw std::runtime_error("bench: cannot write the JSON file " + file.string());
}

constexpr uint32_t kEmbreeThreads = 2;

}  // namespace

int commandBench(const Options& options) {
  const fs::path dataRoot = app::findDataRoot();
  std::vector<fs::path> levels(options.positional.begin(), options.positional.end());
  if (levels.empty()) levels = app::shippedLevels(dataRoot);
  std::vector<std::pair<uint32_t, uint32_t>> sizes = {{320, 180}, {640, 360}};
  if (options.sizeGiven) sizes = {{options.width, options.height}};
  const uint32_t frames = options.frames.value_or(300);
  render::Context context(contextOptions(options));
  render::ShaderCompiler compiler = makeCompiler(dataRoot);
  std::printf("device: %s (%s), %s\n", context.deviceInfo().name.c_str(),
              context.deviceInfo().driver.c_str(),
              render::deviceTypeName(context.deviceInfo().type));
  std::printf(
      "own variant = the pipeline built for the level's features; all = every feature on.\n"
      "trace, denoise, tonemap, readback: median GPU ms of each pass (timestamp queries).\n"
      "Mrays/s: rays the ray-gen shader counts (camera, mirror, shadow and glass rays) over the\n"
      "median frame; trace Mr/s: the same over the median trace pass; Embree: the same rays on\n"
      "the CPU, %u threads, single-ray calls, median of %u frames interleaved with the own\n"
      "variant's; switch: load, build, first probe frame, each picture pipeline run once.\n",
      kEmbreeThreads, options.embreeFrames);
  if (options.strafe)
    std::printf("the camera strafes 1 cm a frame, back and forth over 32 cm (--strafe).\n");
  std::printf("%-22s %-9s %6s %8s %7s %6s %7s %7s %7s %8s %8s %7s %9s %10s %9s %8s\n", "level",
              "size", "frames", "median", "fps", "trace", "denoise", "tonemap", "readbk", "Mrays/s",
              "all ms", "own/all", "switch ms", "trace Mr/s", "Embree", "/Embree");
  std::vector<BenchRow> rows;
  for (const fs::path& levelFile : levels) {
    const game::Level level = game::loadLevel(levelFile, levelLoadOptions());
    std::optional<reference::EmbreeTracer> tracer;
    if (options.embreeFrames > 0) {
      const scene::SceneDesc scene = game::buildSceneDesc(level);
      tracer.emplace(scene, render::featuresOf(scene), kEmbreeThreads);
    }
    for (const auto& [width, height] : sizes) {
      BenchRow row;
      row.level = levelFile.stem().string();
      row.width = width;
      row.height = height;
      row.frames = frames;
      // First, before this size's renderers: the switch as a player meets it.
      row.levelSwitch = measureLevelSwitch(context, compiler, levelFile, width, height);
      InterleavedReference reference{tracer ? &*tracer : nullptr, options.embreeFrames, {}};
      row.own =
          measure(context, compiler, level, options, width, height, frames, false, &reference);
      if (tracer) row.embree = reference.result;
      row.all = measure(context, compiler, level, options, width, height, frames, true);
      const render::PassTimes& pass = row.own.passMedians;
      std::printf(
          "%-22s %4ux%-4u %6u %8.2f %7.1f %6.2f %7.2f %7.2f %7.2f %8.2f %8.2f %7.2f %9.1f "
          "%10.2f",
          row.level.c_str(), width, height, frames, row.own.medianMs, row.fps(), pass.traceMs,
          pass.denoiseMs, pass.tonemapMs, pass.readbackMs, row.mraysPerSecond(), row.all.medianMs,
          row.ownOverAll(), row.levelSwitch.totalMs(), row.traceMraysPerSecond());
      if (row.embree)
        std::printf(" %9.2f %8.2f\n", row.embree->mraysPerSecond(), row.traceOverEmbree());
      else
        std::printf(" %9s %8s\n", "-", "-");
      std::fflush(stdout);
      rows.push_back(std::move(row));
    }
  }
  // The slow tail, which a player feels more than the median.
  std::printf("\nframe time percentiles of the own variant (host, submit to fence):\n");
  for (const BenchRow& row : rows) {
    std::printf("%-22s %4ux%-4u %s\n", row.level.c_str(), row.width, row.height,
                row.own.percentiles.text().c_str());
  }
  if (options.csv) writeCsv(*options.csv, rows);
  if (options.json) writeJson(*options.json, context, options, kEmbreeThreads, rows);
  return validationExitCode(context);
}

}  // namespace app
