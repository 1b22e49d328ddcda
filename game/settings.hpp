#pragma once
// The player's settings (settings.json in configDirectory()): read forgivingly, written
// atomically. docs: README.md, "Settings and progress".
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace game {

struct Settings {
  float mouseSensitivity = 0.1f;  // degrees of turn per pixel of mouse movement
  bool invertY = false;
  // Vertical; unset (null in the file): each level's own camera field of view.
  std::optional<float> fieldOfViewDegrees;
  float renderScale = 0.25f;  // internal resolution as a fraction of the window, (0.1, 1]
  bool vsync = true;
  // Trace fewer pixels while frames take longer than 30 fps allows (play/dynamic_scale.hpp).
  bool dynamicRenderScale = true;
  // Action -> GLFW key name without the GLFW_KEY_ prefix ("W", "SPACE", "F5").
  std::map<std::string, std::string> keyBindings = defaultKeyBindings();

  static std::map<std::string, std::string> defaultKeyBindings();
  bool operator==(const Settings&) const = default;
};

// The ranges a loaded value must fall in; outside them the default is used.
inline constexpr float kMinMouseSensitivity = 0.0f;  // exclusive
inline constexpr float kMaxMouseSensitivity = 10.0f;
inline constexpr float kMinFieldOfViewDegrees = 30.0f;
inline constexpr float kMaxFieldOfViewDegrees = 120.0f;
inline constexpr float kMinRenderScale = 0.1f;  // exclusive
inline constexpr float kMaxRenderScale = 1.0f;

// Whether `name` is a GLFW key name as bindings spell it ("A", "KP_ENTER", "LEFT_SHIFT").
bool isKeyName(const std::string& name);

struct SettingsLoad {
  Settings settings;
  // One line each: "<file>:<line>:<column>: <field>: <problem>; using the default <value>".
  std::vector<std::string> messages;
};

// Never throws: a missing file gives the defaults silently; an unreadable or corrupt one gives
// the defaults and one message; a bad field (unknown key, wrong type, out of range, unknown
// action or key name) gives a message and that field's default, keeping the others.
SettingsLoad loadSettings(const std::filesystem::path& file);

// Writes {"settings": 1, ...} through writeFileAtomically; throws UserFileError.
void saveSettings(const Settings& settings, const std::filesystem::path& file);

}  // namespace game
