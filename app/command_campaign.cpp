// `sightline campaign`: every shipped level's replays, the steps and game time of each win,
// and the campaign's figures checked (docs/LEVELS.md, "How to design a puzzle").
#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "app/commands.hpp"
#include "app/data_paths.hpp"
#include "app/replay_runner.hpp"
#include "app/session.hpp"
#include "game/level_order.hpp"
#include "game/progress.hpp"
#include "render/context.hpp"

namespace app {
namespace fs = std::filesystem;

namespace {

// What the campaign must have (issue: "A campaign worth finishing").
constexpr size_t kMinLevels = 16;
constexpr size_t kMinStepsForAPuzzle = 3;
constexpr size_t kMinPuzzles = 8;          // levels whose win takes kMinStepsForAPuzzle steps
constexpr size_t kMinLevelsWithRules = 4;  // levels whose win fires a rule that changes things
constexpr double kMinMedianWinSeconds = 30.0;

struct LevelRuns {
  game::OrderedLevel level;
  std::vector<game::Replay> replays;
  std::vector<ReplayResult> results;  // parallel to replays
  const ReplayResult* win = nullptr;  // the first passing replay that expects a win
  bool hasFail = false;               // a passing replay that expects a loss or neither
};

// What no level of the campaign uses: every interactable kind and rule action must appear.
std::vector<std::string> unusedKinds(const std::vector<const game::Level*>& levels) {
  std::set<std::string> used;
  for (const game::Level* level : levels) {
    for (const game::Entity& entity : level->entities)
      if (entity.interactable)
        used.insert(std::string("interactable ") +
                    game::interactableName(entity.interactable->type));
    for (const game::Rule& rule : level->rules)
      for (const game::Action& action : rule.actions)
        used.insert(std::string("action ") + game::actionName(action.type));
  }
  std::vector<std::string> every;
  for (int type = 0; type <= int(game::Interactable::Type::Switch); ++type)
    every.push_back(std::string("interactable ") +
                    game::interactableName(game::Interactable::Type(type)));
  for (int type = 0; type <= int(game::Action::Type::Lose); ++type)
    every.push_back(std::string("action ") + game::actionName(game::Action::Type(type)));
  std::vector<std::string> unused;
  for (const std::string& kind : every)
    if (!used.contains(kind)) unused.push_back(kind);
  return unused;
}

std::string stepsText(const std::vector<game::SolutionStep>& steps) {
  std::string text;
  for (const game::SolutionStep& step : steps)
    text += (text.empty() ? "" : ", ") + step.what + " @" + std::to_string(step.tick);
  return text;
}

}  // namespace

int commandCampaign(const Options& options) {
  const fs::path dataRoot = findDataRoot();
  const fs::path levelsDirectory = fs::weakly_canonical(dataRoot / "levels");
  std::vector<LevelRuns> runs;
  std::map<std::string, size_t> indexOf;  // level file name -> runs index
  for (const game::OrderedLevel& level : game::loadCampaign(levelsDirectory)) {
    indexOf[level.file] = runs.size();
    runs.push_back({level, {}, {}, nullptr, false});
  }
  // Every replay in replays/ whose level is in the order, by file name.
  std::vector<fs::path> replayFiles;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(dataRoot / "replays", error))
    if (entry.path().extension() == ".json") replayFiles.push_back(entry.path());
  std::sort(replayFiles.begin(), replayFiles.end());
  std::vector<std::vector<game::Level>> levels(runs.size());
  for (const fs::path& file : replayFiles) {
    game::Replay replay = game::loadReplay(file);
    const fs::path level = fs::weakly_canonical(replay.level);
    if (level.parent_path() != levelsDirectory) continue;
    const auto index = indexOf.find(level.filename().string());
    if (index == indexOf.end()) continue;
    levels[index->second].push_back(loadReplayLevel(replay));
    runs[index->second].replays.push_back(std::move(replay));
  }

  render::Context context(contextOptions(options));
  render::ShaderCompiler compiler = makeCompiler(dataRoot);
  std::vector<std::string> problems;
  for (size_t i = 0; i < runs.size(); ++i) {
    LevelRuns& run = runs[i];
    run.results.reserve(run.replays.size());
    for (size_t r = 0; r < run.replays.size(); ++r) {
      run.results.push_back(runReplay(context, compiler, run.replays[r], levels[i][r], options));
      const ReplayResult& result = run.results.back();
      for (const std::string& failure : result.failures) std::printf("  %s\n", failure.c_str());
      if (!result.passed) {
        problems.push_back(run.replays[r].file.string() + " fails");
        continue;
      }
      if (run.replays[r].outcome.outcome == game::ReplayOutcome::Won) {
        if (!run.win) run.win = &result;
      } else {
        run.hasFail = true;
      }
    }
    if (!run.win) problems.push_back(run.level.file + " has no passing replay that wins");
    if (!run.hasFail)
      problems.push_back(run.level.file + " has no passing replay that loses or misses");
  }

  std::printf("\n%-3s %-10s %-28s %8s %6s %s\n", "#", "chapter", "level", "win", "steps",
              "what the win did");
  std::vector<double> winSeconds;
  size_t puzzles = 0, withRules = 0;
  for (size_t i = 0; i < runs.size(); ++i) {
    const LevelRuns& run = runs[i];
    const ReplayResult* win = run.win;
    std::printf("%-3zu %-10s %-28s %8s %6zu %s\n", i + 1, run.level.chapter.c_str(),
                run.level.file.c_str(), win ? game::gameTimeText(win->ticks).c_str() : "-",
                win ? win->steps.size() : 0, win ? stepsText(win->steps).c_str() : "");
    if (!win) continue;
    winSeconds.push_back(double(win->ticks) / 60.0);
    if (win->steps.size() >= kMinStepsForAPuzzle) ++puzzles;
    if (std::any_of(win->steps.begin(), win->steps.end(),
                    [](const game::SolutionStep& step) { return step.what.starts_with("rule "); }))
      ++withRules;
  }
  const double medianSeconds = median(winSeconds);
  std::printf(
      "\n%zu levels (at least %zu), %zu with %zu or more steps (at least %zu), %zu whose "
      "win fires a rule (at least %zu), median win %.1f s (at least %.0f s)\n",
      runs.size(), kMinLevels, puzzles, kMinStepsForAPuzzle, kMinPuzzles, withRules,
      kMinLevelsWithRules, medianSeconds, kMinMedianWinSeconds);
  std::vector<const game::Level*> loaded;
  for (const std::vector<game::Level>& replayed : levels)
    if (!replayed.empty()) loaded.push_back(&replayed.front());
  for (const std::string& kind : unusedKinds(loaded))
    problems.push_back("no level uses the " + kind);
  if (runs.size() < kMinLevels) problems.push_back("too few levels");
  if (puzzles < kMinPuzzles) problems.push_back("too few levels of three or more steps");
  if (withRules < kMinLevelsWithRules) problems.push_back("too few levels whose win fires a rule");
  if (medianSeconds < kMinMedianWinSeconds) problems.push_back("the median win is too short");
  for (const std::string& problem : problems) std::printf("problem: %s\n", problem.c_str());
  std::printf("campaign: %s\n", problems.empty() ? "every figure holds" : "figures missed");
  const int validation = validationExitCode(context);
  return problems.empty() ? validation : 1;
}

}  // namespace app
