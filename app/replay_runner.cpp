// Runs one replay headless and checks what it expects (`sightline replay`, `sightline campaign`).
#include "app/replay_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "app/data_paths.hpp"
#include "game/level_loader.hpp"
#include "render/context.hpp"
#include "render/image_io.hpp"
#include "render/shader_compiler.hpp"
#include "sim/simulation.hpp"

namespace app {
namespace fs = std::filesystem;

namespace {

std::string formatValue(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4f", double(value));
  return text;
}

game::ReplayOutcome replayOutcomeOf(game::Outcome outcome) {
  switch (outcome) {
    case game::Outcome::Won:
      return game::ReplayOutcome::Won;
    case game::Outcome::Lost:
      return game::ReplayOutcome::Lost;
    case game::Outcome::Playing:
      break;
  }
  return game::ReplayOutcome::Playing;
}

// The value an expectation names, now; false when there is none yet (no readings).
bool currentValue(const sim::Simulation& simulation, const game::ValueExpectation& expectation,
                  float& value, std::string& why) {
  const auto& readings = simulation.latestReadings();
  switch (expectation.kind) {
    case game::ValueExpectation::Kind::Focus:
    case game::ValueExpectation::Kind::Exposure: {
      const bool focus = expectation.kind == game::ValueExpectation::Kind::Focus;
      const size_t count =
          focus ? simulation.layout().focus.size() : simulation.layout().exposure.size();
      if (expectation.index >= count) {
        why = std::string("the level has ") + std::to_string(count) +
              (focus ? " focus" : " exposure") + " probes";
        return false;
      }
      if (!readings) {
        why = "no probe readings have arrived yet";
        return false;
      }
      value = focus ? readings->focusCoverage[expectation.index]
                    : readings->exposure[expectation.index];
      return true;
    }
    case game::ValueExpectation::Kind::Progress: {
      const auto progress = simulation.rules().progress();
      if (expectation.index >= progress.size()) {
        why = "the level has " + std::to_string(progress.size()) + " goals";
        return false;
      }
      value = progress[expectation.index].progress;
      return true;
    }
  }
  return false;
}

class TraceWriter {
 public:
  TraceWriter(const fs::path& file, const sim::Simulation& simulation) : out_(file) {
    if (!out_) throw std::runtime_error("cannot write the trace " + file.string());
    out_ << "tick,feet_x,feet_y,feet_z,yaw,pitch,readings_tick";
    for (size_t i = 0; i < simulation.layout().focus.size(); ++i) out_ << ",focus" << i;
    for (size_t i = 0; i < simulation.layout().exposure.size(); ++i) out_ << ",exposure" << i;
    for (size_t i = 0; i < simulation.rules().progress().size(); ++i) out_ << ",progress" << i;
    // Per rule: how many times it has fired so far.
    for (size_t i = 0; i < simulation.logic().ruleCount(); ++i)
      out_ << ",rule:" << simulation.logic().ruleId(i);
    out_ << ",outcome\n";
  }
  void write(const sim::Simulation& simulation) {
    const glm::vec3 feet = simulation.world().feetPosition();
    out_ << simulation.tick() << "," << feet.x << "," << feet.y << "," << feet.z << ","
         << simulation.world().yawDegrees() << "," << simulation.world().pitchDegrees() << ",";
    const auto& readings = simulation.latestReadings();
    out_ << (readings ? std::to_string(readings->tick) : std::string("-"));
    for (size_t i = 0; i < simulation.layout().focus.size(); ++i)
      out_ << "," << (readings ? readings->focusCoverage[i] : 0.0f);
    for (size_t i = 0; i < simulation.layout().exposure.size(); ++i)
      out_ << "," << (readings ? readings->exposure[i] : 0.0f);
    for (const auto& goal : simulation.rules().progress()) out_ << "," << goal.progress;
    for (size_t i = 0; i < simulation.logic().ruleCount(); ++i)
      out_ << "," << simulation.logic().firings(i).size();
    out_ << "," << game::outcomeName(replayOutcomeOf(simulation.outcome())) << "\n";
  }

 private:
  std::ofstream out_;
};

}  // namespace

game::Level loadReplayLevel(const game::Replay& replay) {
  game::Level level;
  try {
    level = game::loadLevel(replay.level, levelLoadOptions());
  } catch (const game::LevelError& error) {
    throw game::ReplayError(replay.levelPlace + ": /level: " + error.what());
  }
  for (const game::FiredExpectation& fired : replay.fired) {
    const bool known = std::any_of(level.rules.begin(), level.rules.end(),
                                   [&](const game::Rule& rule) { return rule.id == fired.rule; });
    if (!known) {
      throw game::ReplayError(fired.ruleAt + ": " + fired.place +
                              "/rule: the level has no rule \"" + fired.rule + "\"");
    }
  }
  return level;
}

namespace {

// A fired expectation against the rule's firings: "" when it holds, else what happened.
std::string checkFired(const game::FiredExpectation& expectation, const game::Logic& logic) {
  size_t rule = 0;
  while (logic.ruleId(rule) != expectation.rule) ++rule;
  const std::vector<uint64_t>& firings = logic.firings(rule);
  std::string happened = "it never fired";
  if (!firings.empty()) {
    happened = "it fired on tick";
    for (size_t i = 0; i < firings.size() && i < 8; ++i)
      happened += (i ? ", " : " ") + std::to_string(firings[i]);
    if (firings.size() > 8) happened += ", ... (" + std::to_string(firings.size()) + " times)";
  }
  if (expectation.never) {
    return firings.empty()
               ? ""
               : "expected rule \"" + expectation.rule + "\" never to fire; " + happened;
  }
  const bool within = std::any_of(firings.begin(), firings.end(), [&](uint64_t tick) {
    return tick >= expectation.firstTick && tick <= expectation.lastTick;
  });
  return within ? ""
                : "expected rule \"" + expectation.rule + "\" to fire between ticks " +
                      std::to_string(expectation.firstTick) + " and " +
                      std::to_string(expectation.lastTick) + "; " + happened;
}

}  // namespace

ReplayResult runReplay(const render::Context& context, render::ShaderCompiler& compiler,
                       const game::Replay& replay, const game::Level& level,
                       const Options& options) {
  sim::Simulation simulation(context, compiler, level,
                             {replay.width, replay.height, replay.probeEveryTicks,
                              replay.probeLatency, replay.verticalFovDegrees});
  std::optional<TraceWriter> trace;
  if (options.trace) trace.emplace(*options.trace, simulation);
  game::SolutionSteps steps(level, simulation.world());
  ReplayResult result;
  auto fail = [&](const std::string& message) {
    result.passed = false;
    result.failures.push_back(message);
  };
  auto checkTick = [&](uint64_t tick) {
    for (const game::ValueExpectation& expectation : replay.values) {
      if (expectation.tick != tick) continue;
      float value = 0.0f;
      std::string why;
      if (!currentValue(simulation, expectation, value, why)) {
        fail(expectation.place + " at tick " + std::to_string(tick) + ": " + why);
      } else if (value < expectation.min || value > expectation.max) {
        fail(expectation.place + " at tick " + std::to_string(tick) + ": expected [" +
             formatValue(expectation.min) + ", " + formatValue(expectation.max) + "], got " +
             formatValue(value));
      }
    }
    for (const game::PlayerExpectation& expectation : replay.players) {
      if (expectation.tick != tick) continue;
      const glm::vec3 feet = simulation.world().feetPosition();
      const glm::vec3 off = glm::abs(feet - expectation.feet);
      if (off.x > expectation.tolerance || off.y > expectation.tolerance ||
          off.z > expectation.tolerance) {
        fail(expectation.place + " at tick " + std::to_string(tick) + ": expected feet (" +
             formatValue(expectation.feet.x) + ", " + formatValue(expectation.feet.y) + ", " +
             formatValue(expectation.feet.z) + ") within " + formatValue(expectation.tolerance) +
             " m, got (" + formatValue(feet.x) + ", " + formatValue(feet.y) + ", " +
             formatValue(feet.z) + ")");
      }
    }
    for (const game::ImageCheckpoint& checkpoint : replay.images) {
      if (checkpoint.tick != tick) continue;
      const render::Rgba8Image actual{replay.width, replay.height, simulation.renderPicture()};
      if (options.updateImages) {
        fs::create_directories(checkpoint.png.parent_path());
        render::writePng(checkpoint.png, actual);
        std::printf("  %s: wrote %s\n", checkpoint.place.c_str(), checkpoint.png.c_str());
        continue;
      }
      if (!fs::exists(checkpoint.png)) {
        fail(checkpoint.place + ": " + checkpoint.png.string() +
             " does not exist; run with --update-images to store it");
        continue;
      }
      const render::ImageDifference difference =
          render::compareImages(render::readPng(checkpoint.png), actual, 2);
      if (difference.differingFraction() > checkpoint.maxDifferentShare) {
        fs::path diffFile = checkpoint.png;
        diffFile.replace_extension(".diff.png");
        render::writePng(diffFile, difference.visualization);
        fail(checkpoint.place + " at tick " + std::to_string(tick) + ": " +
             formatValue(float(difference.differingFraction() * 100.0)) +
             " % of pixels differ by more than 2/255 (allowed " +
             formatValue(checkpoint.maxDifferentShare * 100.0f) + " %); difference image " +
             diffFile.string());
      }
    }
  };

  const auto start = std::chrono::steady_clock::now();
  checkTick(0);
  if (trace) trace->write(simulation);
  while (simulation.tick() < replay.ticks && simulation.outcome() == game::Outcome::Playing) {
    simulation.step(replay.inputAt(simulation.tick()));
    steps.observe(simulation.world(), simulation.logic());
    if (trace) trace->write(simulation);
    checkTick(simulation.tick());
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const game::ReplayOutcome got = replayOutcomeOf(simulation.outcome());
  result.outcome = got;
  result.ticks = simulation.tick();
  result.steps = steps.steps();
  const game::OutcomeExpectation& expected = replay.outcome;
  const std::string gotText =
      got == game::ReplayOutcome::Playing
          ? std::string("neither won nor lost in ") + std::to_string(simulation.tick()) + " ticks"
          : std::string(game::outcomeName(got)) + " on tick " + std::to_string(simulation.tick()) +
                " (" + simulation.rules().reason() + ")";
  const std::string expectedText =
      expected.outcome == game::ReplayOutcome::Playing
          ? std::string("neither won nor lost")
          : std::string(game::outcomeName(expected.outcome)) + " between ticks " +
                std::to_string(expected.firstTick) + " and " + std::to_string(expected.lastTick);
  const bool outcomeHolds =
      got == expected.outcome &&
      (got == game::ReplayOutcome::Playing ||
       (simulation.tick() >= expected.firstTick && simulation.tick() <= expected.lastTick));
  if (!outcomeHolds) fail("outcome: expected " + expectedText + ", got " + gotText);
  for (const game::FiredExpectation& expectation : replay.fired) {
    const std::string problem = checkFired(expectation, simulation.logic());
    if (!problem.empty()) fail(expectation.place + ": " + problem);
  }
  std::printf("%s: %s %s; %llu ticks in %.2f s (%.0f ticks/s, %llu probe frames)\n",
              replay.file.c_str(), result.passed ? "PASS" : "FAIL", gotText.c_str(),
              static_cast<unsigned long long>(simulation.tick()), seconds,
              double(simulation.tick()) / std::max(seconds, 1e-9),
              static_cast<unsigned long long>(simulation.probeFrames()));
  return result;
}

}  // namespace app
