#include "game/tick_clock.hpp"

#include <cmath>

namespace game {

int TickClock::advance(double elapsedSeconds) {
  if (!std::isfinite(elapsedSeconds) || elapsedSeconds < 0.0) elapsedSeconds = 0.0;
  backlogSeconds_ += elapsedSeconds;
  const double dueTicks = std::floor(backlogSeconds_ / TICK_SECONDS);
  if (dueTicks > MAX_TICKS_PER_FRAME) {
    droppedTicks_ += uint64_t(dueTicks) - MAX_TICKS_PER_FRAME;
    backlogSeconds_ = 0.0;  // the rest of the backlog, whole ticks and the fraction, is dropped
    return MAX_TICKS_PER_FRAME;
  }
  const int due = int(dueTicks);
  backlogSeconds_ -= due * TICK_SECONDS;
  return due;
}

}  // namespace game
