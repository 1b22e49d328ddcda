#include "play/input.hpp"

#include <algorithm>
#include <cmath>

#include <GLFW/glfw3.h>
#include <glm/geometric.hpp>

#include "game/rules.hpp"
#include "play/key_names.hpp"

namespace play {
namespace {

constexpr double kTickSeconds = game::Rules::TICK_SECONDS;
constexpr float kStickDegreesPerSecond = 150.0f;
constexpr float kStickDeadZone = 0.2f;
constexpr uint32_t kWheelAdjustTicks = 6;  // one wheel notch adjusts for 0.1 s
constexpr int kCaptureSettlingFrames = 2;  // frames after capturing the mouse with no look

void onKey(GLFWwindow* window, int key, int, int action, int) {
  if (action == GLFW_PRESS)
    static_cast<PendingEvents*>(glfwGetWindowUserPointer(window))->keysPressed.push_back(key);
}

void onScroll(GLFWwindow* window, double, double y) {
  static_cast<PendingEvents*>(glfwGetWindowUserPointer(window))->wheel += y;
}

float deadZone(float axis) {
  return std::abs(axis) < kStickDeadZone ? 0.0f : axis;
}

// The first connected joystick GLFW knows as a gamepad, if any.
bool readGamepad(GLFWgamepadstate* state) {
  for (int joystick = GLFW_JOYSTICK_1; joystick <= GLFW_JOYSTICK_LAST; ++joystick) {
    if (glfwJoystickIsGamepad(joystick) && glfwGetGamepadState(joystick, state)) return true;
  }
  return false;
}

}  // namespace

void installEventCallbacks(GLFWwindow* window, PendingEvents& events) {
  glfwSetWindowUserPointer(window, &events);
  glfwSetKeyCallback(window, onKey);
  glfwSetScrollCallback(window, onScroll);
}

KeyCodes keyCodesFor(const game::Settings& settings) {
  KeyCodes keyCodes;
  for (const auto& [action, name] : settings.keyBindings) keyCodes[action] = glfwKeyFromName(name);
  return keyCodes;
}

int keyFor(const KeyCodes& keyCodes, const std::string& action) {
  const auto found = keyCodes.find(action);
  return found == keyCodes.end() ? GLFW_KEY_UNKNOWN : found->second;
}

KeyAction keyActionFor(const KeyCodes& keyCodes, int key) {
  if (key == keyFor(keyCodes, "pause")) return KeyAction::Pause;
  if (key == keyFor(keyCodes, "restart")) return KeyAction::Restart;
  if (key == keyFor(keyCodes, "fullscreen")) return KeyAction::Fullscreen;
  switch (key) {
    case GLFW_KEY_V:
      return KeyAction::Vsync;
    case GLFW_KEY_F3:
      return KeyAction::AuthorOverlay;
    case GLFW_KEY_F4:
      return KeyAction::FlyCamera;
    case GLFW_KEY_F6:
      return KeyAction::CopyView;
    case GLFW_KEY_F12:
      return KeyAction::Screenshot;
    default:
      return KeyAction::None;
  }
}

void rebindAction(game::Settings& settings, KeyCodes& keyCodes, const std::string& action,
                  int key) {
  if (key != GLFW_KEY_ESCAPE && !keyNameFromGlfw(key).empty()) {
    settings.keyBindings[action] = keyNameFromGlfw(key);
    keyCodes = keyCodesFor(settings);
  }
}

bool gamepadStartPressed(bool& startWasDown) {
  GLFWgamepadstate pad{};
  const bool hasPad = readGamepad(&pad);
  const bool startPressed = hasPad && pad.buttons[GLFW_GAMEPAD_BUTTON_START] && !startWasDown;
  startWasDown = hasPad && pad.buttons[GLFW_GAMEPAD_BUTTON_START];
  return startPressed;
}

game::TickInput heldInput(GLFWwindow* window, const KeyCodes& keyCodes) {
  auto down = [&](const char* action) {
    const int key = keyFor(keyCodes, action);
    return key != GLFW_KEY_UNKNOWN && glfwGetKey(window, key) == GLFW_PRESS;
  };
  game::TickInput input;
  input.move = {float(down("right")) - float(down("left")),
                float(down("forward")) - float(down("back"))};
  input.jump = down("jump");
  input.interact = down("interact");
  input.adjust = float(down("adjust_up")) - float(down("adjust_down"));
  GLFWgamepadstate pad{};
  if (readGamepad(&pad)) {
    // GLFW's stick y grows downwards.
    input.move += glm::vec2(deadZone(pad.axes[GLFW_GAMEPAD_AXIS_LEFT_X]),
                            -deadZone(pad.axes[GLFW_GAMEPAD_AXIS_LEFT_Y]));
    const float stickDegrees = kStickDegreesPerSecond * float(kTickSeconds);
    input.yawDeltaDegrees = -deadZone(pad.axes[GLFW_GAMEPAD_AXIS_RIGHT_X]) * stickDegrees;
    input.pitchDeltaDegrees = -deadZone(pad.axes[GLFW_GAMEPAD_AXIS_RIGHT_Y]) * stickDegrees;
    input.jump = input.jump || pad.buttons[GLFW_GAMEPAD_BUTTON_A];
    input.interact = input.interact || pad.buttons[GLFW_GAMEPAD_BUTTON_X];
    input.adjust += float(pad.buttons[GLFW_GAMEPAD_BUTTON_RIGHT_BUMPER]) -
                    float(pad.buttons[GLFW_GAMEPAD_BUTTON_LEFT_BUMPER]);
  }
  // Diagonals are no faster than straight lines.
  const float length = glm::length(input.move);
  if (length > 1.0f) input.move /= length;
  input.adjust = std::clamp(input.adjust, -1.0f, 1.0f);
  return input;
}

void setMouseCaptured(GLFWwindow* window, MouseLook& look, bool captured) {
  glfwSetInputMode(window, GLFW_CURSOR, captured ? GLFW_CURSOR_DISABLED : GLFW_CURSOR_NORMAL);
  if (captured && glfwRawMouseMotionSupported())
    glfwSetInputMode(window, GLFW_RAW_MOUSE_MOTION, GLFW_TRUE);
  glfwGetCursorPos(window, &look.cursorX, &look.cursorY);  // no jump from where the cursor was
  look.pending = glm::vec2(0.0f);
  look.settlingFrames = captured ? kCaptureSettlingFrames : 0;
}

void gatherMouseLook(GLFWwindow* window, MouseLook& look, const game::Settings& settings) {
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  if (look.settlingFrames > 0) {
    --look.settlingFrames;
    look.cursorX = x;
    look.cursorY = y;
    return;
  }
  // Right turns right (negative yaw), up looks up (positive pitch).
  look.pending += glm::vec2(-float(x - look.cursorX),
                            -float(y - look.cursorY) * (settings.invertY ? -1.0f : 1.0f)) *
                  settings.mouseSensitivity;
  look.cursorX = x;
  look.cursorY = y;
}

void startWheelAdjust(WheelAdjust& wheel, double turns) {
  if (turns == 0.0) return;
  wheel.direction = turns > 0.0 ? 1.0f : -1.0f;
  wheel.ticksLeft = uint32_t(std::ceil(std::abs(turns))) * kWheelAdjustTicks;
}

void applyWheelAdjust(WheelAdjust& wheel, game::TickInput& input) {
  if (wheel.ticksLeft == 0) return;
  --wheel.ticksLeft;
  input.adjust = std::clamp(input.adjust + wheel.direction, -1.0f, 1.0f);
}

}  // namespace play
