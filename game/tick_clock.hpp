#pragma once
// Real frame times into the world's fixed 60 Hz ticks, for play. A frame runs at most
// MAX_TICKS_PER_FRAME ticks: after a long frame (a debugger pause, a hitch, a dragged window)
// the rest of the backlog is dropped and the game falls behind real time, instead of spending
// ever longer frames catching up. Ticks are the only time the world sees, so a long frame's
// ticks are exactly the ticks a run of normal frames would have run.
#include <cstdint>

#include "game/world.hpp"

namespace game {

class TickClock {
 public:
  static constexpr double TICK_SECONDS = World::TICK_SECONDS;
  static constexpr int MAX_TICKS_PER_FRAME = 5;  // 83 ms of game time per frame at most

  // Adds a frame's real time and returns how many ticks to run now (0..MAX_TICKS_PER_FRAME).
  // A negative or non-finite time (a clock that jumped back) counts as none.
  int advance(double elapsedSeconds);
  // Forgets the backlog (a new level: loading time is not play time).
  void reset() { backlogSeconds_ = 0.0; }

  double backlogSeconds() const { return backlogSeconds_; }  // real time not yet ticked
  uint64_t droppedTicks() const { return droppedTicks_; }    // whole ticks dropped so far

 private:
  double backlogSeconds_ = 0.0;
  uint64_t droppedTicks_ = 0;
};

}  // namespace game
