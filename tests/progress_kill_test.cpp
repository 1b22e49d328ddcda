// The progress file survives a kill at any moment of writing it: a child process saves two
// progress states in turn as fast as it can, the parent kills it with SIGKILL after a delay that
// sweeps across a whole save, and the file must then load, without a message, as one of the two.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "game/progress.hpp"
#include "game/user_paths.hpp"
#include "temp_dir_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using test::TempDirTest;

constexpr int kKills = 300;

// Two states of different sizes, so a file cut short or mixed from both cannot pass for either.
game::Progress progressWith(const std::string& prefix, int levels) {
  game::Progress progress;
  for (int i = 0; i < levels; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "%s_%04d.json", prefix.c_str(), i);
    progress.completed.insert(name);
  }
  return progress;
}

// The child: saves `first` and `second` in turn until it is killed.
[[noreturn]] void saveForever(const game::Progress& first, const game::Progress& second,
                              const fs::path& file) {
  try {
    for (;;) {
      game::saveProgress(first, file);
      game::saveProgress(second, file);
    }
  } catch (...) {
    _exit(1);  // a save that fails is a finding; the parent sees the exit status
  }
}

TEST_F(TempDirTest, progress_file_is_old_or_new_after_sigkill_at_any_moment_of_a_save) {
  const fs::path file = root_ / "sightline" / "progress.json";
  const game::Progress older = progressWith("older", 300);  // about 7 KB
  const game::Progress newer = progressWith("newer", 700);  // about 16 KB
  game::saveProgress(older, file);

  // The delays sweep from 0 to three saves' time, so kills land before, in and after a write,
  // its flush and its rename.
  const auto start = std::chrono::steady_clock::now();
  constexpr int kTimedSaves = 10;
  for (int i = 0; i < kTimedSaves; ++i) game::saveProgress(i % 2 ? older : newer, file);
  const auto saveTime = (std::chrono::steady_clock::now() - start) / kTimedSaves;

  int killedMidSave = 0;  // a temporary file was left behind: the kill hit inside a save
  int foundOlder = 0, foundNewer = 0;
  for (int kill = 0; kill < kKills; ++kill) {
    const pid_t child = fork();
    ASSERT_GE(child, 0) << "fork failed";
    if (child == 0) saveForever(newer, older, file);
    std::this_thread::sleep_for(saveTime * 3 * kill / kKills);
    ASSERT_EQ(::kill(child, SIGKILL), 0);
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
        << "the child stopped by itself (a save failed) before kill " << kill;

    const game::ProgressLoad load = game::loadProgress(file);
    ASSERT_TRUE(load.messages.empty()) << "kill " << kill << ": " << load.messages.front();
    ASSERT_TRUE(load.progress == older || load.progress == newer)
        << "kill " << kill << ": the file holds " << load.progress.completed.size()
        << " levels, neither the old nor the new state";
    (load.progress == older ? foundOlder : foundNewer) += 1;
    std::error_code ignored;
    if (fs::exists(file.string() + ".tmp", ignored)) ++killedMidSave;
  }
  std::printf(
      "%d kills: %d inside a save (a temporary file was left), file held the older state "
      "%d times and the newer %d times\n",
      kKills, killedMidSave, foundOlder, foundNewer);
  RecordProperty("kills", kKills);
  RecordProperty("killed_mid_save", killedMidSave);

  // A temporary file left by a kill neither blocks the next save nor survives it.
  game::saveProgress(newer, file);
  EXPECT_EQ(game::loadProgress(file).progress, newer);
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
}

TEST_F(TempDirTest, atomic_write_creates_missing_directories_and_leaves_no_temporary_file) {
  const fs::path file = root_ / "a" / "b" / "settings.json";
  game::writeFileAtomically(file, "{}\n");
  EXPECT_EQ(*game::readUserFile(file, 100), "{}\n");
  game::writeFileAtomically(file, "{\"x\": 1}\n");
  EXPECT_EQ(*game::readUserFile(file, 100), "{\"x\": 1}\n");
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(file.parent_path()))
    names.push_back(entry.path().filename().string());
  EXPECT_EQ(names, std::vector<std::string>{"settings.json"});
}

}  // namespace
