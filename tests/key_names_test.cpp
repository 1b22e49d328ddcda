// The key names settings.json binds actions to, against GLFW's key codes.
#include <string>

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include "game/settings.hpp"
#include "play/key_names.hpp"

TEST(KeyNames, default_bindings_name_the_keys_play_used_before_bindings) {
  const auto bindings = game::Settings::defaultKeyBindings();
  EXPECT_EQ(play::glfwKeyFromName(bindings.at("forward")), GLFW_KEY_W);
  EXPECT_EQ(play::glfwKeyFromName(bindings.at("jump")), GLFW_KEY_SPACE);
  EXPECT_EQ(play::glfwKeyFromName(bindings.at("pause")), GLFW_KEY_ESCAPE);
  EXPECT_EQ(play::glfwKeyFromName(bindings.at("restart")), GLFW_KEY_F5);
  EXPECT_EQ(play::glfwKeyFromName(bindings.at("fullscreen")), GLFW_KEY_F11);
}

TEST(KeyNames, every_glfw_key_with_a_name_round_trips_and_settings_accept_that_name) {
  int named = 0;
  for (int key = GLFW_KEY_SPACE; key <= GLFW_KEY_LAST; ++key) {
    const std::string name = play::keyNameFromGlfw(key);
    if (name.empty()) continue;
    ++named;
    EXPECT_EQ(play::glfwKeyFromName(name), key) << name;
    EXPECT_TRUE(game::isKeyName(name)) << name;
  }
  // 26 letters, 10 digits, F1..F25 and 59 named keys: every key GLFW defines but GLFW_KEY_UNKNOWN.
  EXPECT_EQ(named, 26 + 10 + 25 + 59);
}

TEST(KeyNames, names_that_are_not_keys_have_no_code) {
  for (const char* name : {"", "a", "F0", "F26", "SPACEBAR", "GLFW_KEY_W", "shift"})
    EXPECT_EQ(play::glfwKeyFromName(name), GLFW_KEY_UNKNOWN) << name;
}
