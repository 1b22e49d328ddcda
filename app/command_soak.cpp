// soak: a long headless run of a level with its movers going, watching that resident memory
// stops growing after a warm-up and (with --validate) that no Vulkan object is left at exit.
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>

#include "app/commands.hpp"
#include "app/data_paths.hpp"
#include "app/session.hpp"
#include "game/level_loader.hpp"
#include "sim/simulation.hpp"

namespace app {
namespace fs = std::filesystem;

namespace {

constexpr uint32_t kDefaultFrames = 3000;
constexpr uint32_t kWarmUpFrames = 500;       // caches, pools and allocator arenas settle by then
constexpr double kMaxDriftBytes = 1.0e6;      // 1 MB, between the warm-up and the last frame
constexpr uint32_t kPictureEveryFrames = 10;  // a picture read back like a replay checkpoint
constexpr uint32_t kReportEveryFrames = 500;

// Resident set size from /proc/self/statm (its second field, in pages).
double residentBytes() {
  std::ifstream statm("/proc/self/statm");
  uint64_t sizePages = 0, residentPages = 0;
  if (!(statm >> sizePages >> residentPages)) return 0.0;
  return double(residentPages) * double(sysconf(_SC_PAGESIZE));
}

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SIGHTLINE_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define SIGHTLINE_ASAN 1
#endif

// Bytes the C allocator has handed out and not had back (glibc's count); AddressSanitizer's
// allocator keeps no such count.
std::optional<double> heapInUseBytes() {
#ifdef SIGHTLINE_ASAN
  return std::nullopt;
#else
  return double(mallinfo2().uordblks);
#endif
}

double megabytes(double bytes) {
  return bytes / 1.0e6;
}

}  // namespace

int commandSoak(const Options& options) {
  if (options.positional.size() != 1) throw UsageError("soak: expected one level file");
  const fs::path levelFile = options.positional[0];
  const uint32_t frames = options.frames.value_or(kDefaultFrames);
  if (frames <= kWarmUpFrames) {
    throw UsageError("soak: --frames must be more than the " + std::to_string(kWarmUpFrames) +
                     " warm-up frames, got " + std::to_string(frames));
  }
  // One malloc arena unless MALLOC_ARENA_MAX says otherwise. By default glibc gives the driver's
  // worker threads arenas of their own, whose resident size wanders by 1 to 3 MB while the bytes
  // in use stay flat (docs/ROBUSTNESS.md, "Soak"): noise as large as the leak this looks for.
  const char* arenaSetting = std::getenv("MALLOC_ARENA_MAX");
  if (!arenaSetting) mallopt(M_ARENA_MAX, 1);
  const uint32_t width = options.sizeGiven ? options.width : 64;
  const uint32_t height = options.sizeGiven ? options.height : 36;
  const game::Level level = game::loadLevel(levelFile, levelLoadOptions());
  render::Context context(contextOptions(options));
  render::ShaderCompiler compiler = makeCompiler(findDataRoot());
  std::printf(
      "soak: %s, %u frames at %ux%u on %s (%s); each frame a world tick and a probe "
      "frame, every %uth also a picture read back; malloc arenas: %s\n",
      levelFile.c_str(), frames, width, height, context.deviceInfo().name.c_str(),
      context.deviceInfo().driver.c_str(), kPictureEveryFrames, arenaSetting ? arenaSetting : "1");
  std::fflush(stdout);

  double warmResident = 0.0, peakResident = 0.0, lastResident = 0.0;
  std::optional<double> warmHeap, lastHeap;
  const auto start = std::chrono::steady_clock::now();
  {
    sim::SimulationOptions simulationOptions;
    simulationOptions.width = width;
    simulationOptions.height = height;
    simulationOptions.probeEveryTicks = 1;
    sim::Simulation simulation(context, compiler, level, simulationOptions);
    // The player stands and turns slowly, so the camera moves as well as the movers.
    game::TickInput input;
    input.yawDeltaDegrees = 0.5f;
    for (uint32_t frame = 1; frame <= frames; ++frame) {
      simulation.step(input);
      if (frame % kPictureEveryFrames == 0) simulation.renderPicture();
      // Every frame from the warm-up on, so the highest value is the highest there was.
      if (frame < kWarmUpFrames && frame % kReportEveryFrames != 0) continue;
      lastResident = residentBytes();
      lastHeap = heapInUseBytes();
      if (frame == kWarmUpFrames) {
        warmResident = lastResident;
        warmHeap = lastHeap;
      }
      if (frame >= kWarmUpFrames) peakResident = std::max(peakResident, lastResident);
      if (frame % kReportEveryFrames == 0 || frame == frames) {
        std::printf("frame %6u: resident %8.2f MB", frame, megabytes(lastResident));
        if (lastHeap) std::printf(", heap in use %8.2f MB", megabytes(*lastHeap));
        std::printf("\n");
        std::fflush(stdout);
      }
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Destroying the device and instance now lets the validation layer report, into the count
  // below, any Vulkan object still alive.
  context.close();

  const double drift = lastResident - warmResident;
  std::printf("%u frames in %.1f s (%.0f frames/s)\n", frames, seconds, frames / seconds);
  std::printf(
      "resident memory: %.2f MB at frame %u, %.2f MB at frame %u: drift %+.3f MB "
      "(limit %.1f MB); highest after warm-up %.2f MB (%+.3f MB)\n",
      megabytes(warmResident), kWarmUpFrames, megabytes(lastResident), frames, megabytes(drift),
      megabytes(kMaxDriftBytes), megabytes(peakResident), megabytes(peakResident - warmResident));
  if (lastHeap && warmHeap) {
    std::printf("heap in use: %+.3f MB between frame %u and frame %u\n",
                megabytes(*lastHeap - *warmHeap), kWarmUpFrames, frames);
  }
  int status = 0;
  if (drift > kMaxDriftBytes) {
    std::printf("FAIL: resident memory grew by %.3f MB after the warm-up\n", megabytes(drift));
    status = 1;
  }
  if (context.validationEnabled()) {
    std::printf("validation: %zu message(s), Vulkan objects left at exit included\n",
                context.validationMessageCount());
    if (context.validationMessageCount() > 0) status = status ? status : 3;
  } else {
    std::printf("validation: off (--validate also checks for Vulkan objects left at exit)\n");
  }
  return status;
}

}  // namespace app
