#pragma once
// The player's input: presses and wheel turns from GLFW's callbacks, the key bindings, held
// keys and the gamepad, and mouse look.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "game/replay.hpp"
#include "game/settings.hpp"

struct GLFWwindow;

namespace play {

// Presses and wheel turns since the last frame, gathered by GLFW's callbacks.
struct PendingEvents {
  std::vector<int> keysPressed;
  double wheel = 0.0;
};

// Points the window's key and scroll callbacks at `events` (the window's user pointer), which
// must stay where it is while they are installed.
void installEventCallbacks(GLFWwindow* window, PendingEvents& events);

// action -> GLFW key, from the settings' key names.
using KeyCodes = std::map<std::string, int>;

KeyCodes keyCodesFor(const game::Settings& settings);
// GLFW_KEY_UNKNOWN for an action without a key.
int keyFor(const KeyCodes& keyCodes, const std::string& action);

// What a key pressed while playing (or paused) does. The bound actions are checked first, so a
// key bound to one of them no longer toggles vsync, the probe values or a screenshot.
enum class KeyAction {
  None,
  Pause,
  Restart,
  Fullscreen,
  Vsync,
  AuthorOverlay,  // F3
  FlyCamera,      // F4
  CopyView,       // F6
  Screenshot,
};
KeyAction keyActionFor(const KeyCodes& keyCodes, int key);

// The settings screen waits for a key: binds `action` to it unless it is Escape (which keeps
// the old key) or a key settings.json has no name for.
void rebindAction(game::Settings& settings, KeyCodes& keyCodes, const std::string& action, int key);

// Start on the first gamepad went down since the last call (`startWasDown` remembers).
bool gamepadStartPressed(bool& startWasDown);

// What is held now, from the keyboard and a gamepad; look comes separately.
game::TickInput heldInput(GLFWwindow* window, const KeyCodes& keyCodes);

struct MouseLook {
  glm::vec2 pending{0.0f};  // yaw, pitch degrees from the mouse since the last tick
  double cursorX = 0.0, cursorY = 0.0;
  // Frames whose cursor movement is not look: GLFW centres a newly captured cursor, and on X11
  // that warp shows up as movement a frame or two later, by half the window at some sizes.
  int settlingFrames = 0;
};

// Playing captures the mouse for looking; paused gives it back. Either way looking starts
// again from where the cursor is now, with nothing pending.
void setMouseCaptured(GLFWwindow* window, MouseLook& look, bool captured);
// Adds the cursor's movement since the last call to the pending look.
void gatherMouseLook(GLFWwindow* window, MouseLook& look, const game::Settings& settings);

// A wheel turn adjusts for a few ticks (a notch would otherwise last one tick, too short to see).
struct WheelAdjust {
  float direction = 0.0f;
  uint32_t ticksLeft = 0;
};

// The frame's wheel turns (if any) start a new adjust, replacing what was left of the last.
void startWheelAdjust(WheelAdjust& wheel, double turns);
// Adds the wheel's adjust to one tick's input while it lasts.
void applyWheelAdjust(WheelAdjust& wheel, game::TickInput& input);

}  // namespace play
