#include "play/hud.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>

#include <imgui.h>

#include "game/author_view.hpp"
#include "play/level_flow.hpp"
#include "play/level_list.hpp"
#include "render/renderer.hpp"
#include "sim/simulation.hpp"

namespace play {
namespace {

// The HUD's bars, in fractions of the picture: rows grow upwards from the bottom one.
constexpr float kBarTop = 0.93f, kBarGap = 0.045f, kBarHeight = 0.025f, kBarWidth = 0.36f;
constexpr float kGoalBarLeft = 0.02f, kExposureBarLeft = 0.62f;
constexpr size_t kHudRows = 4;

ImU32 colour(uint8_t red, uint8_t green, uint8_t blue) {
  return IM_COL32(red, green, blue, 255);
}

// Text with a dark drop shadow, readable over bright and dark parts of the picture.
void shadowedText(ImDrawList* list, ImVec2 at, ImU32 textColour, const std::string& text,
                  float size, float wrapWidth = 0.0f) {
  ImFont* font = ImGui::GetFont();
  list->AddText(font, size, ImVec2(at.x + 1.5f, at.y + 1.5f), IM_COL32(0, 0, 0, 220), text.c_str(),
                nullptr, wrapWidth);
  list->AddText(font, size, at, textColour, text.c_str(), nullptr, wrapWidth);
}

// The exposure meters that get the HUD's rows (game::hudMeters), from the latest readings.
std::vector<size_t> shownMeters(const sim::Simulation& simulation) {
  const auto& readings = simulation.latestReadings();
  static const std::vector<float> kNone;
  return game::hudMeters(simulation.layout().exposure, readings ? readings->exposure : kNone,
                         kHudRows);
}

std::string percent(float share) {
  return std::to_string(int(std::clamp(share, 0.0f, 1.0f) * 100.0f + 0.5f)) + "%";
}

// F3: what the rules see, for level authors tuning goals.
void drawAuthorOverlay(const PlayedLevel& played) {
  const sim::Simulation& simulation = *played.simulation;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 10.0f, display.y * 0.15f), ImGuiCond_Always,
                          ImVec2(1.0f, 0.0f));
  ImGui::SetNextWindowBgAlpha(0.7f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav |
                                 ImGuiWindowFlags_NoInputs;
  if (ImGui::Begin("Probe values (F3)", nullptr, flags)) {
    // Probes at the render size; the picture at the dynamic render scale's part of it.
    const render::Renderer& renderer = simulation.renderer();
    ImGui::Text("tick %llu, probes %ux%u, picture %ux%u",
                static_cast<unsigned long long>(simulation.tick()), played.renderWidth,
                played.renderHeight, renderer.pictureWidth(), renderer.pictureHeight());
    // What the crosshair is on, for placing things and naming them in rules.
    if (const auto target = game::crosshairTarget(simulation.world())) {
      for (const std::string& line :
           game::describeCrosshair(*played.level, simulation.world(), *target))
        ImGui::TextUnformatted(line.c_str());
    } else {
      ImGui::TextUnformatted("nothing under the crosshair");
    }
    ImGui::Separator();
    if (const auto& readings = simulation.latestReadings()) {
      ImGui::Text("readings of tick %llu", static_cast<unsigned long long>(readings->tick));
      for (size_t i = 0; i < readings->focusCoverage.size(); ++i)
        ImGui::Text("focus %zu coverage  %.4f", i, double(readings->focusCoverage[i]));
      for (size_t i = 0; i < readings->exposure.size(); ++i)
        ImGui::Text("exposure %zu  %.4f", i, double(readings->exposure[i]));
    } else {
      ImGui::TextUnformatted("no readings yet");
    }
    for (const game::GoalProgress& goal : simulation.rules().progress())
      ImGui::Text("%s  %.4f%s", goal.label.c_str(), double(goal.progress),
                  goal.met ? " (met)" : "");
    const game::Logic& logic = simulation.logic();
    for (size_t i = 0; i < logic.ruleCount(); ++i) {
      const std::vector<uint64_t>& firings = logic.firings(i);
      ImGui::Text("rule %s  %s, fired %zu%s", logic.ruleId(i).c_str(),
                  logic.holding(i) ? "holds" : "does not hold", firings.size(),
                  firings.empty()
                      ? ""
                      : (" (last on tick " + std::to_string(firings.back()) + ")").c_str());
    }
  }
  ImGui::End();
}

}  // namespace

std::vector<render::HudRect> hudRects(const sim::Simulation& simulation) {
  using render::HudColour;
  std::vector<render::HudRect> rects;
  for (const game::FocusProbe& focus : simulation.layout().focus) {
    const float x0 = 0.5f - focus.region.x / 2, x1 = 0.5f + focus.region.x / 2;
    const float y0 = 0.5f - focus.region.y / 2, y1 = 0.5f + focus.region.y / 2;
    constexpr float kLine = 0.004f;
    rects.push_back({x0, y0, x1, y0 + kLine, HudColour::White});
    rects.push_back({x0, y1 - kLine, x1, y1, HudColour::White});
    rects.push_back({x0, y0, x0 + kLine, y1, HudColour::White});
    rects.push_back({x1 - kLine, y0, x1, y1, HudColour::White});
  }
  auto bar = [&](float x0, int row, float value, HudColour fill) {
    const float y0 = kBarTop - kBarGap * float(row), y1 = y0 + kBarHeight;
    rects.push_back({x0, y0, x0 + kBarWidth, y1, HudColour::Shade});
    if (value > 0.0f)
      rects.push_back({x0, y0, x0 + kBarWidth * std::clamp(value, 0.0f, 1.0f), y1, fill});
  };
  const auto& goals = simulation.rules().progress();
  for (size_t i = 0; i < goals.size() && i < kHudRows; ++i)
    bar(kGoalBarLeft, int(i), goals[i].progress,
        goals[i].met ? HudColour::BluishGreen : HudColour::SkyBlue);
  const auto& readings = simulation.latestReadings();
  const std::vector<game::ExposureProbe>& meters = simulation.layout().exposure;
  const std::vector<size_t> shown = shownMeters(simulation);
  for (size_t row = 0; row < shown.size(); ++row) {
    const size_t i = shown[row];
    bar(kExposureBarLeft, int(row), readings ? readings->exposure[i] : 0.0f, HudColour::Orange);
    // Where the reading starts to count (a lit sensor at or above it, a watcher above it): a
    // tick above the bar and one below, so the mark never crosses the label written on the bar.
    const float y0 = kBarTop - kBarGap * float(row), y1 = y0 + kBarHeight,
                x = kExposureBarLeft + kBarWidth * meters[i].threshold;
    constexpr float kTickHalfWidth = 0.002f, kTickLength = 0.008f;
    rects.push_back(
        {x - kTickHalfWidth, y0 - kTickLength, x + kTickHalfWidth, y0, HudColour::White});
    rects.push_back(
        {x - kTickHalfWidth, y1, x + kTickHalfWidth, y1 + kTickLength, HudColour::White});
  }
  // The crosshair: what is picked and what the focus region is centred on.
  constexpr float kArm = 0.012f, kThickness = 0.0015f;
  const float aspect = float(simulation.renderer().width()) / float(simulation.renderer().height());
  rects.push_back({0.5f - kArm / aspect, 0.5f - kThickness, 0.5f + kArm / aspect, 0.5f + kThickness,
                   HudColour::White});
  rects.push_back({0.5f - kThickness / aspect, 0.5f - kArm, 0.5f + kThickness / aspect, 0.5f + kArm,
                   HudColour::White});
  const game::Outcome outcome = simulation.outcome();
  if (outcome != game::Outcome::Playing)
    rects.push_back(
        {0.0f, 0.02f, 1.0f, 0.06f,
         outcome == game::Outcome::Won ? HudColour::BluishGreen : HudColour::Vermillion});
  return rects;
}

void drawScreenText(const PlayedLevel& played, const render::Presenter& presenter, double fps,
                    bool authorOverlay, const std::string& interactKey) {
  const game::Level& level = *played.level;
  const sim::Simulation& simulation = *played.simulation;
  ImDrawList* list = ImGui::GetForegroundDrawList();
  const render::PictureRect picture =
      presenter.pictureRect(played.renderWidth, played.renderHeight);
  const float size = ImGui::GetFontSize();
  const float margin = std::max(6.0f, picture.width * 0.015f);
  auto at = [&](float x, float y) {
    return ImVec2(picture.x + x * picture.width, picture.y + y * picture.height);
  };
  const ImU32 white = colour(255, 255, 255);
  const ImU32 green = colour(0, 158, 115), vermillion = colour(213, 94, 0);
  ImVec2 top(picture.x + margin, picture.y + picture.height * 0.07f);
  shadowedText(list, top, white, level.name, size * 1.35f);
  if (!level.hint.empty()) {
    top.y += size * 1.6f;
    shadowedText(list, top, colour(230, 230, 230), level.hint, size, picture.width * 0.55f);
  }
  const std::string fpsText = std::to_string(int(fps + 0.5)) + " fps";
  const float fpsWidth = ImGui::CalcTextSize(fpsText.c_str()).x;
  const ImVec2 topRight = at(1.0f, 0.07f);
  shadowedText(list, ImVec2(topRight.x - margin - fpsWidth, topRight.y), white, fpsText, size);
  if (simulation.authoring()) {
    const std::string flyText = "Fly camera (F4): no winning or losing";
    const float flyWidth = ImGui::CalcTextSize(flyText.c_str()).x;
    shadowedText(list, ImVec2(topRight.x - margin - flyWidth, topRight.y + size * 1.4f),
                 colour(240, 228, 66), flyText, size);
  }

  // On the bars hudRects() draws, so the two columns never run into each other: goals on the
  // left, exposure meters on the right.
  auto barText = [&](float left, size_t row, const std::string& text, ImU32 textColour) {
    const float y = kBarTop - kBarGap * float(row) + kBarHeight / 2;
    const ImVec2 position = at(left + 0.006f, y);
    list->PushClipRect(at(left, 0.0f), at(left + kBarWidth, 1.0f), true);
    shadowedText(list, ImVec2(position.x, position.y - size / 2), textColour, text, size);
    list->PopClipRect();
  };
  const auto& goals = simulation.rules().progress();
  for (size_t i = 0; i < goals.size() && i < kHudRows; ++i) {
    barText(kGoalBarLeft, i, goals[i].label + "  " + percent(goals[i].progress),
            goals[i].met ? green : white);
  }
  const auto& readings = simulation.latestReadings();
  const std::vector<game::ExposureProbe>& meters = simulation.layout().exposure;
  const std::vector<size_t> shown = shownMeters(simulation);
  for (size_t row = 0; row < shown.size(); ++row) {
    const size_t i = shown[row];
    barText(kExposureBarLeft, row,
            meters[i].label + "  " + percent(readings ? readings->exposure[i] : 0.0f), white);
  }
  // What the crosshair is on, and how to use it.
  if (const std::optional<uint32_t> picked = simulation.world().pickedEntity()) {
    const game::Interactable& it = *level.entities[*picked].interactable;
    const std::string text =
        it.type == game::Interactable::Type::Switch
            ? "Press " + interactKey + " to switch"
            : "Hold " + interactKey + " and turn the wheel (or Q / R) to " +
                  (it.type == game::Interactable::Type::Rotate ? "turn it" : "slide it");
    // Just below the largest focus region, clear of its frame.
    float below = 0.5f + 0.02f;
    for (const game::FocusProbe& focus : simulation.layout().focus)
      below = std::max(below, 0.5f + focus.region.y / 2 + 0.02f);
    const float width = ImGui::CalcTextSize(text.c_str()).x;
    shadowedText(list, ImVec2(picture.x + (picture.width - width) / 2, at(0, below).y), white, text,
                 size);
  }
  // A message a level rule shows, centred below the focus region.
  if (const std::optional<std::string> message = simulation.logic().message(simulation.tick())) {
    const float width =
        std::min(ImGui::CalcTextSize(message->c_str()).x * 1.2f, picture.width * 0.8f);
    shadowedText(list, ImVec2(picture.x + (picture.width - width) / 2, at(0, 0.68f).y),
                 colour(240, 228, 66), *message, size * 1.2f, picture.width * 0.8f);
  }
  const game::Outcome outcome = simulation.outcome();
  if (outcome != game::Outcome::Playing) {
    const std::string text =
        outcome == game::Outcome::Won
            ? wonText(simulation.tick(), played.bestBefore) +
                  (played.campaignFinished ? "." : ". The next level follows in a moment.")
            : "Lost: " + simulation.rules().reason() + ". Restarting.";
    const float big = size * 1.5f;
    const float width = ImGui::CalcTextSize(text.c_str()).x * 1.5f;
    const ImVec2 corner(picture.x + (picture.width - width) / 2, at(0, 0.3f).y);
    // On a dark panel, so the sentence reads over any wall (it was green on grey, 1.5:1).
    const float pad = size * 0.6f;
    list->AddRectFilled(ImVec2(corner.x - pad, corner.y - pad),
                        ImVec2(corner.x + width + pad, corner.y + big + pad),
                        IM_COL32(0, 0, 0, 200), size * 0.4f);
    shadowedText(list, corner, outcome == game::Outcome::Won ? green : vermillion, text, big);
  }
  if (authorOverlay) drawAuthorOverlay(played);
}

void drawLoadingScreen(const std::string& levelName, float progress, bool compilesSlowly) {
  ImDrawList* list = ImGui::GetForegroundDrawList();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float size = ImGui::GetFontSize();
  auto centred = [&](const std::string& text, float textSize, float y, ImU32 textColour) {
    const float width = ImGui::CalcTextSize(text.c_str()).x * textSize / size;
    shadowedText(list, ImVec2((display.x - width) / 2, y), textColour, text, textSize);
  };
  const float big = size * 2.0f;
  float y = display.y * 0.42f;
  centred(levelName, big, y, colour(255, 255, 255));
  y += big * 1.4f;
  centred("Loading...", size * 1.2f, y, colour(230, 230, 230));
  y += size * 2.0f;
  // The bar: its track in the HUD's shade, filled in sky blue (the goal bars' colours).
  const float left = display.x * 0.35f, right = display.x * 0.65f, height = size * 0.5f;
  list->AddRectFilled(ImVec2(left, y), ImVec2(right, y + height), colour(40, 40, 40));
  list->AddRectFilled(ImVec2(left, y),
                      ImVec2(left + (right - left) * std::clamp(progress, 0.0f, 1.0f), y + height),
                      colour(86, 180, 233));
  if (compilesSlowly) {
    y += size * 1.5f;
    centred("The first time a level is played, its shaders are compiled: several seconds.", size, y,
            colour(190, 190, 190));
  }
}

}  // namespace play
