// `sightline replay`: runs replays headless and checks what they expect.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/data_paths.hpp"
#include "app/replay_runner.hpp"
#include "app/session.hpp"
#include "render/context.hpp"

namespace app {
namespace fs = std::filesystem;

int commandReplay(const Options& options) {
  if (options.positional.empty()) throw UsageError("replay: expected replay files");
  if (options.trace && options.positional.size() != 1)
    throw UsageError("replay: --trace takes exactly one replay file");
  // Every file and its level are read and checked before anything runs; each bad one is
  // reported, and then nothing runs.
  std::vector<game::Replay> replays;
  std::vector<game::Level> levels;
  std::vector<std::string> problems;
  for (const std::string& file : options.positional) {
    try {
      game::Replay replay = game::loadReplay(file);
      levels.push_back(loadReplayLevel(replay));
      replays.push_back(std::move(replay));
    } catch (const game::ReplayError& error) {
      problems.push_back(error.what());
    }
  }
  if (problems.size() == 1) throw game::ReplayError(problems.front());
  if (!problems.empty()) {
    for (const std::string& problem : problems) std::fprintf(stderr, "%s\n", problem.c_str());
    std::fprintf(stderr, "%zu of %zu replays are malformed; none was run\n", problems.size(),
                 options.positional.size());
    return 1;
  }
  render::Context context(contextOptions(options));
  render::ShaderCompiler compiler = makeCompiler(findDataRoot());
  int failed = 0;
  for (size_t i = 0; i < replays.size(); ++i) {
    const ReplayResult result = runReplay(context, compiler, replays[i], levels[i], options);
    if (result.passed) continue;
    ++failed;
    for (const std::string& failure : result.failures) std::printf("  %s\n", failure.c_str());
  }
  std::printf("%zu replays, %d failed\n", replays.size(), failed);
  const int validation = validationExitCode(context);
  return failed ? 1 : validation;
}

}  // namespace app
