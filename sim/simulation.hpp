#pragma once
// The game running: the fixed-tick world and rules, fed by probe frames from the renderer.
//
// Probe cadence (the same in play and headless): after every tick t with t % k == 0 a probe
// frame renders the world as it is after tick t; its readings reach the rules at tick
// t + L * k, after that tick's world step (k = probe_every_ticks, L = probe_latency in probe
// frames). Play, which has frames in flight, waits for a readback when the rules need it, so a
// slow machine runs slower but never differently. Exposure readings are filtered over probe
// frames (each new frame moves the reading halfway, in fixed point); focus readings are not.
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "game/level.hpp"
#include "game/logic.hpp"
#include "game/probe_points.hpp"
#include "game/probes.hpp"
#include "game/replay.hpp"
#include "game/rules.hpp"
#include "game/world.hpp"
#include "render/renderer.hpp"

namespace render {
class Context;
class ShaderCompiler;
}  // namespace render

namespace sim {

struct SimulationOptions {
  uint32_t width = 64;
  uint32_t height = 36;
  uint32_t probeEveryTicks = 4;             // k
  uint32_t probeLatency = 2;                // L, in probe frames
  std::optional<float> verticalFovDegrees;  // the level camera's when unset
  // Pictures upscaled temporally to this size (0: none); probes keep width x height.
  uint32_t outputWidth = 0;
  uint32_t outputHeight = 0;
  // While a frame is waited for, every 100 ms (render::RendererOptions::whileWaiting).
  std::function<void()> whileWaiting;
};

class Simulation {
 public:
  Simulation(const render::Context& context, render::ShaderCompiler& compiler,
             const game::Level& level, const SimulationOptions& options);

  // One fixed tick (1/60 s).
  void step(const game::TickInput& input);

  uint64_t tick() const { return world_.tick(); }
  // Playing while authoring (the fly camera): the rules still run and may decide, but the
  // decision is held back; rulesOutcome() is what they decided.
  game::Outcome outcome() const;
  game::Outcome rulesOutcome() const { return rules_.outcome(); }

  // Level authors' tools (play --author, F4, live reload): the fly camera, which also keeps the
  // level from being won or lost, and putting the player where they were before a reload.
  void setAuthoring(bool authoring);
  bool authoring() const { return world_.flying(); }
  void placePlayer(const glm::vec3& feet, float yawDegrees, float pitchDegrees);
  const game::World& world() const { return world_; }
  const game::Rules& rules() const { return rules_; }
  const game::Logic& logic() const { return logic_; }
  const game::ProbeLayout& layout() const { return layout_; }
  // The newest readings the rules have, and whether they arrived on this tick.
  const std::optional<game::ProbeReadings>& latestReadings() const { return latest_; }
  bool readingsArrivedThisTick() const { return arrivedThisTick_; }
  // Probe frames rendered so far.
  uint64_t probeFrames() const { return probeFrames_; }

  // Renders the current state as a picture (denoised), outside the probe cadence; probes are
  // unaffected. Returns RGBA8 rows top to bottom, read back unless `readback` is false (a
  // window presents the renderer's image instead).
  const std::vector<uint8_t>& renderPicture(bool readback = true);
  // Before the first picture: has the renderer run each of the picture's pipelines once
  // (Renderer::runEachPicturePipelineOnce), so that a CPU driver compiles them now, while the
  // level loads, not in the first frames played. The pictures are those it would have made.
  // `afterEachFrame`: as Renderer::runEachPicturePipelineOnce's.
  void preparePictures(
      const std::function<void(uint32_t done, uint32_t frames)>& afterEachFrame = {});
  // The last picture's times: each pass's on the GPU and the host's from submit to fence.
  const render::FrameStats& lastPictureStats() const { return lastPictureStats_; }
  render::Renderer& renderer() { return *renderer_; }
  const render::Renderer& renderer() const { return *renderer_; }

 private:
  scene::FrameDesc pictureFrame() const;  // the next picture's camera and sample sequence
  void syncRenderer();
  void syncFeedback();
  game::ProbeReadings renderProbeFrame();

  const game::Level& level_;
  SimulationOptions options_;
  game::World world_;
  game::ProbeLayout layout_;
  game::Rules rules_;
  game::Logic logic_;
  std::unique_ptr<render::Renderer> renderer_;
  std::vector<std::vector<game::SurfaceSample>> sensorSamples_;  // per exposure probe
  std::vector<bool> lightStates_;
  std::vector<bool> visibleStates_;           // per entity, as the renderer last got them
  std::vector<float> glows_;                  // per entity, as the renderer last got them
  std::vector<float> warmths_;                // per light, as the renderer last got them
  std::vector<scene::LightDesc> lightPoses_;  // per light, as the renderer last got them
  glm::vec3 bodyFeet_{0.0f};                  // where the renderer last got the player's body
  bool transformsChanged_ = false;          // since the renderer last got the entities' transforms
  std::vector<uint64_t> exposureFiltered_;  // 16.16 fixed point, per exposure probe
  std::deque<game::ProbeReadings> inFlight_;
  std::optional<game::ProbeReadings> latest_;
  bool arrivedThisTick_ = false;
  uint64_t probeFrames_ = 0;
  uint32_t frameIndex_ = 0;  // probe frames' sample sequence index
  uint32_t pictureFrames_ = 0;
  render::FrameStats lastPictureStats_;
};

}  // namespace sim
