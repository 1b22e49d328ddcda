#pragma once
// Running a replay headless: its level loaded, its input stepped through the simulation, its
// expectations checked, and the steps the run took counted (game/solution_steps.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include "app/options.hpp"
#include "game/level.hpp"
#include "game/replay.hpp"
#include "game/solution_steps.hpp"

namespace render {
class Context;
class ShaderCompiler;
}  // namespace render

namespace app {

struct ReplayResult {
  bool passed = true;
  std::vector<std::string> failures;
  game::ReplayOutcome outcome = game::ReplayOutcome::Playing;
  uint64_t ticks = 0;  // when it ended: the outcome's tick, or the replay's length
  std::vector<game::SolutionStep> steps;
};

// The replay's level, or a ReplayError that names where the replay names it.
game::Level loadReplayLevel(const game::Replay& replay);

// Runs `replay` on `level` and prints its one-line report (PASS or FAIL, outcome, speed).
// Uses --trace and --update-images from `options`.
ReplayResult runReplay(const render::Context& context, render::ShaderCompiler& compiler,
                       const game::Replay& replay, const game::Level& level,
                       const Options& options);

}  // namespace app
