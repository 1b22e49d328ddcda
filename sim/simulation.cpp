#include "sim/simulation.hpp"

#include <algorithm>

#include "game/player_body.hpp"
#include "render/context.hpp"
#include "render/shader_compiler.hpp"

namespace sim {
namespace {

// Candidate points on a sensor; those facing the light are traced (at most EXPOSURE_SAMPLES).
constexpr uint32_t kSensorSamples = 64;
constexpr uint64_t kUnfiltered = ~uint64_t(0);
constexpr uint32_t kPictureFrames = 1u << 30;  // first sequence index of pictures

render::RendererOptions rendererOptions(const SimulationOptions& options) {
  render::RendererOptions result;
  result.width = options.width;
  result.height = options.height;
  result.outputWidth = options.outputWidth;
  result.outputHeight = options.outputHeight;
  result.whileWaiting = options.whileWaiting;
  return result;
}

// The level's scene as `world` has it and, after its entities' instances, the player's body.
scene::SceneDesc sceneFor(const game::Level& level, const game::World& world,
                          const game::ProbeLayout& layout) {
  scene::SceneDesc scene = game::buildSceneDesc(level, world);
  scene.exposureProbes = !layout.exposure.empty();
  scene::InstanceDesc body;
  body.mesh = uint32_t(scene.meshes.size());
  body.material = uint32_t(scene.materials.size());
  body.playerBody = true;
  scene.meshes.push_back(game::playerBodyMesh());
  scene.materials.push_back(game::playerBodyMaterial());
  scene.instances.push_back(body);
  return scene;
}

}  // namespace

Simulation::Simulation(const render::Context& context, render::ShaderCompiler& compiler,
                       const game::Level& level, const SimulationOptions& options)
    : level_(level),
      options_(options),
      world_(level),
      layout_(game::probeLayout(level)),
      rules_(level, layout_),
      logic_(level, layout_),
      renderer_(std::make_unique<render::Renderer>(
          context, compiler, sceneFor(level, world_, layout_), rendererOptions(options))) {
  for (const game::ExposureProbe& probe : layout_.exposure) {
    sensorSamples_.push_back(
        probe.target == game::ExposureProbe::Target::Entity
            ? game::surfaceSamples(level.meshes[level.entities[probe.entity].mesh], kSensorSamples)
            : std::vector<game::SurfaceSample>{});
  }
  for (const scene::LightDesc& light : level.lights) lightStates_.push_back(light.enabled);
  lightPoses_ = level.lights;
  visibleStates_.assign(level.entities.size(), true);
  glows_.assign(level.entities.size(), 0.0f);
  warmths_.assign(level.lights.size(), 0.0f);
  if (options_.verticalFovDegrees) world_.setVerticalFovDegrees(*options_.verticalFovDegrees);
  transformsChanged_ = true;  // the player's body goes to the spawn point
  bodyFeet_ = world_.feetPosition();
  // Probe frame 0 shows the world before the first tick.
  syncRenderer();
  inFlight_.push_back(renderProbeFrame());
  if (options_.probeLatency == 0) {  // due at tick 0 itself: the rules start with it
    latest_ = std::move(inFlight_.front());
    inFlight_.pop_front();
  }
}

game::Outcome Simulation::outcome() const {
  return authoring() ? game::Outcome::Playing : rules_.outcome();
}

void Simulation::setAuthoring(bool authoring) {
  world_.setFlying(authoring);
}

void Simulation::placePlayer(const glm::vec3& feet, float yawDegrees, float pitchDegrees) {
  world_.placePlayer(feet, yawDegrees, pitchDegrees);
}

void Simulation::syncRenderer() {
  if (transformsChanged_) {
    transformsChanged_ = false;
    std::vector<glm::mat4> transforms;
    for (size_t i = 0; i < level_.entities.size(); ++i)
      transforms.push_back(world_.entityTransform(uint32_t(i)));
    transforms.push_back(game::playerBodyTransform(world_.feetPosition()));
    renderer_->setInstanceTransforms(transforms);
  }
  // Lights that ride entities follow them.
  const bool lightsRide = std::any_of(level_.lightCarriers.begin(), level_.lightCarriers.end(),
                                      [](const auto& carrier) { return carrier.has_value(); });
  if (lightsRide) {
    const std::vector<scene::LightDesc> lights = world_.lights();
    for (uint32_t light = 0; light < lights.size(); ++light) {
      scene::LightDesc& sent = lightPoses_[light];
      if (lights[light].position == sent.position && lights[light].direction == sent.direction)
        continue;
      sent = lights[light];
      renderer_->setLightPose(light, sent.position, sent.direction);
    }
  }
  for (uint32_t light = 0; light < lightStates_.size(); ++light) {
    const bool enabled = world_.lightEnabled(light);
    if (enabled == lightStates_[light]) continue;
    lightStates_[light] = enabled;
    renderer_->setLightEnabled(light, enabled);
  }
  for (uint32_t entity = 0; entity < visibleStates_.size(); ++entity) {
    const bool visible = world_.visible(entity);
    if (visible == visibleStates_[entity]) continue;
    visibleStates_[entity] = visible;
    renderer_->setInstanceVisible(entity, visible);
  }
  syncFeedback();
}

// Feedback in the world, so the game reads without the HUD: an orb glows as its focus score
// rises, a sensor with its exposure, and a watcher's light warms as it sees the player. Only
// the picture changes: probes count instances and visibility, not colours.
void Simulation::syncFeedback() {
  constexpr float kOrbGlow = 1.5f, kSensorGlow = 1.0f;
  const glm::vec3 kWarmest(1.6f, 0.55f, 0.35f);
  std::vector<float> glows(glows_.size(), 0.0f), warmths(warmths_.size(), 0.0f);
  for (const game::GoalProgress& goal : rules_.progress()) {
    if (goal.orb < 0) continue;
    float& glow = glows[size_t(goal.orb)];
    glow = std::max(glow, kOrbGlow * goal.progress);
  }
  if (latest_) {
    for (size_t i = 0; i < layout_.exposure.size() && i < latest_->exposure.size(); ++i) {
      const game::ExposureProbe& probe = layout_.exposure[i];
      const float reading = latest_->exposure[i];
      if (probe.target == game::ExposureProbe::Target::Entity) {
        glows[probe.entity] = std::max(glows[probe.entity], kSensorGlow * reading);
      } else {
        warmths[probe.light] = std::max(warmths[probe.light], reading);
      }
    }
  }
  for (uint32_t entity = 0; entity < glows.size(); ++entity) {
    if (glows[entity] == glows_[entity]) continue;
    glows_[entity] = glows[entity];
    renderer_->setInstanceGlow(entity, glows[entity]);
  }
  for (uint32_t light = 0; light < warmths.size(); ++light) {
    if (warmths[light] == warmths_[light]) continue;
    warmths_[light] = warmths[light];
    renderer_->setLightTint(light, glm::mix(glm::vec3(1.0f), kWarmest, warmths[light]));
  }
}

game::ProbeReadings Simulation::renderProbeFrame() {
  scene::ProbeRequest request;
  const std::vector<scene::LightDesc> lights = world_.lights();  // where they are now
  for (const game::FocusProbe& focus : layout_.focus)
    request.focus.push_back({focus.entity, focus.region});
  for (size_t i = 0; i < layout_.exposure.size(); ++i) {
    const game::ExposureProbe& probe = layout_.exposure[i];
    const scene::LightDesc& light = lights[probe.light];
    scene::ExposureProbeDesc desc;
    desc.light = probe.light;
    desc.channel = probe.channel;
    desc.onPlayerBody = probe.target == game::ExposureProbe::Target::Player;
    // A hidden sensor sees nothing: it reads 0.
    if (probe.target == game::ExposureProbe::Target::Player) {
      desc.points = game::playerExposurePoints(world_.feetPosition(), light);
    } else if (world_.visible(probe.entity)) {
      desc.points = game::sensorExposurePoints(sensorSamples_[i],
                                               world_.entityTransform(probe.entity), light);
    }
    request.exposure.push_back(std::move(desc));
  }
  renderer_->setProbes(request);
  scene::FrameDesc frame;
  frame.camera = world_.camera();
  frame.frameIndex = frameIndex_++;
  renderer_->renderProbeFrame(frame);
  const scene::ProbeCounts& counts = renderer_->probeCounts();
  game::ProbeReadings readings;
  readings.tick = world_.tick();
  for (size_t i = 0; i < layout_.focus.size(); ++i)
    readings.focusCoverage.push_back(counts.focusCoverage(i));
  // Exposure is filtered over probe frames in 16.16 fixed point, halving the step each frame:
  // exact, order-free integer arithmetic, so replays agree on every machine.
  exposureFiltered_.resize(layout_.exposure.size(), kUnfiltered);
  for (size_t i = 0; i < layout_.exposure.size(); ++i) {
    const uint64_t points = counts.exposurePoints[i];
    const uint64_t current =
        points ? (uint64_t(counts.exposureFixed[i]) << 16) / (points * counts.exposureOne) : 0;
    uint64_t& filtered = exposureFiltered_[i];
    filtered = filtered == kUnfiltered ? current : (filtered + current) / 2;
    readings.exposure.push_back(float(filtered) / 65536.0f);
  }
  ++probeFrames_;
  return readings;
}

void Simulation::step(const game::TickInput& input) {
  world_.step(input);
  // Changes between probe frames count too: the next frame shows where everything is now.
  transformsChanged_ =
      transformsChanged_ || !world_.changedEntities().empty() || world_.feetPosition() != bodyFeet_;
  bodyFeet_ = world_.feetPosition();
  const uint64_t now = world_.tick();
  const uint64_t k = options_.probeEveryTicks;
  if (now % k == 0) {
    syncRenderer();
    inFlight_.push_back(renderProbeFrame());
  }
  arrivedThisTick_ = false;
  if (!inFlight_.empty() && inFlight_.front().tick + options_.probeLatency * k == now) {
    latest_ = std::move(inFlight_.front());
    inFlight_.pop_front();
    arrivedThisTick_ = true;
  }
  const game::ProbeReadings* arrived = arrivedThisTick_ ? &*latest_ : nullptr;
  logic_.update(now, world_, arrived);
  rules_.update(now, world_, arrived);
  if (const std::optional<game::Outcome> decided = logic_.outcome())
    rules_.decide(*decided, logic_.outcomeTick(), logic_.reason());
}

scene::FrameDesc Simulation::pictureFrame() const {
  scene::FrameDesc frame;
  frame.camera = world_.camera();
  // Sample sequences of their own, so taking a picture changes no probe frame's samples.
  frame.frameIndex = kPictureFrames + pictureFrames_;
  return frame;
}

void Simulation::preparePictures(
    const std::function<void(uint32_t done, uint32_t frames)>& afterEachFrame) {
  syncRenderer();
  renderer_->runEachPicturePipelineOnce(pictureFrame(), afterEachFrame);
}

const std::vector<uint8_t>& Simulation::renderPicture(bool readback) {
  syncRenderer();
  const scene::FrameDesc frame = pictureFrame();
  ++pictureFrames_;
  lastPictureStats_ = renderer_->renderFrame(frame, readback);
  return renderer_->pixels();
}

}  // namespace sim
