#pragma once
// GLFW key codes and the names settings.json binds actions to ("W", "SPACE", "F5": GLFW's
// GLFW_KEY_ names without the prefix; game::isKeyName checks them).
#include <string>

namespace play {

// GLFW_KEY_UNKNOWN (-1) for a name that is not a key.
int glfwKeyFromName(const std::string& name);
// "" for a key without a name in settings.json.
std::string keyNameFromGlfw(int key);

}  // namespace play
