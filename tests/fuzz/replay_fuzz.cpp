// Fuzz target for the replay parser: any text must either parse or be rejected with a
// game::ReplayError whose message is one line starting with the file name. A replay that parses
// must also survive the way recording writes replays: replayToJson's output parses again to the
// same level, settings, input events and outcome. Anything else (another exception, a crash, a
// sanitizer report, a hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "game/replay.hpp"

namespace {

// Has no directory on disk; the parser reads no files (levels and images are read by the runner).
constexpr std::string_view kFuzzReplayPath = "<fuzz>/replay.json";

[[noreturn]] void die(const std::string& problem, const std::string& detail) {
  std::fprintf(stderr, "replay_fuzz: %s: %s\n", problem.c_str(), detail.c_str());
  std::abort();
}

bool sameEvent(const game::InputEvent& a, const game::InputEvent& b) {
  return a.tick == b.tick && a.hold == b.hold && a.move == b.move &&
         a.lookDegrees == b.lookDegrees && a.jump == b.jump && a.interact == b.interact &&
         a.adjust == b.adjust;
}

// What replayToJson writes must come back unchanged.
void checkRoundTrip(const game::Replay& replay) {
  const std::string written = game::replayToJson(replay);
  game::Replay again;
  try {
    again = game::parseReplay(written, replay.file);
  } catch (const game::ReplayError& error) {
    die("replayToJson wrote a replay the parser rejects",
        std::string(error.what()) + "\n" + written);
  }
  auto differs = [&](const char* what) { die(std::string("round trip changed ") + what, written); };
  if (again.level != replay.level) differs("the level path");
  if (again.width != replay.width || again.height != replay.height) differs("the size");
  if (again.seed != replay.seed) differs("the seed");
  if (again.probeEveryTicks != replay.probeEveryTicks || again.probeLatency != replay.probeLatency)
    differs("the probe cadence");
  if (again.ticks != replay.ticks) differs("the tick count");
  if (again.events.size() != replay.events.size()) differs("the number of input events");
  for (size_t i = 0; i < replay.events.size(); ++i)
    if (!sameEvent(again.events[i], replay.events[i])) differs("an input event");
  if (again.outcome.outcome != replay.outcome.outcome) differs("the expected outcome");
  if (replay.outcome.outcome != game::ReplayOutcome::Playing &&
      (again.outcome.firstTick != replay.outcome.firstTick ||
       again.outcome.lastTick != replay.outcome.lastTick))
    differs("the outcome's tick range");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  game::Replay replay;
  try {
    replay = game::parseReplay(text, std::string(kFuzzReplayPath));
  } catch (const game::ReplayError& error) {
    // `sightline replay` prints the message as it is: it must name the file, on one line.
    const std::string message = error.what();
    if (message.rfind(std::string(kFuzzReplayPath) + ":", 0) != 0)
      die("ReplayError message does not start with the file", message);
    if (message.find('\n') != std::string::npos) die("ReplayError message spans lines", message);
    return 0;
  }
  checkRoundTrip(replay);
  return 0;
}
