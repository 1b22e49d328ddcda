#pragma once
// A level's goal, lose conditions and counts said in words, for `sightline info`.
#include <cstddef>
#include <string>

#include "game/level.hpp"

namespace app {

// "1 light", "3 lights".
std::string counted(std::size_t count, const std::string& noun, const std::string& plural = "");

// "keep "orb" in the centre of the view (...)"; nested goals as "all of: a; b".
std::string describeGoal(const game::Level& level, const game::Goal& goal);

// "seen by "watch_lamp" (exposure above 50%) for 0.5 s", "falling below -3 m".
std::string describeLoss(const game::Level& level, const game::LoseCondition& lose);

}  // namespace app
