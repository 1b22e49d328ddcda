#pragma once
// The heads-up display over the picture: its shapes, which the presenter draws, and its text,
// drawn with Dear ImGui.
#include <string>
#include <vector>

#include "render/presenter.hpp"

namespace sim {
class Simulation;
}

namespace play {

struct PlayedLevel;

// Each focus region's frame, a crosshair, a bar per goal (blue, green when met), a meter per
// exposure probe that has a row (game::hudMeters; orange, with a mark where its reading starts
// to count), and a band at the top once the level is won (green) or lost (red-orange).
std::vector<render::HudRect> hudRects(const sim::Simulation& simulation);

// Level name and hint (top left), fps (top right), a label beside each HUD bar (a meter says
// what it measures), how to use what the crosshair is on, a rule's message, the outcome on a
// panel,
// and with `authorOverlay` (F3) the raw probe readings. Between UiLayer's beginFrame and
// endFrame.
void drawScreenText(const PlayedLevel& played, const render::Presenter& presenter, double fps,
                    bool authorOverlay, const std::string& interactKey);

// While a level loads (its pipelines compile; seconds on a CPU driver the first time): the
// level's name, "Loading..." and a bar `progress` (0 to 1) full, centred over black.
// `compilesSlowly`: say that the first time takes several seconds. Between UiLayer's
// beginFrame and endFrame.
void drawLoadingScreen(const std::string& levelName, float progress, bool compilesSlowly);

}  // namespace play
