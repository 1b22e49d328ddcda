#include "game/settings.hpp"

#include <charconv>
#include <cstdlib>
#include <string_view>

#include "game/user_json_file.hpp"
#include "game/user_paths.hpp"

namespace game {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

constexpr int kSettingsVersion = 1;
const std::string kVersionKey = "settings";
const std::string kWhenIgnored = "using the default settings";

// The names of GLFW's GLFW_KEY_* constants without the prefix, so a settings file reads like the
// GLFW documentation. Letters, digits and F1..F25 are generated in isKeyName.
constexpr std::string_view kNamedKeys[] = {
    "SPACE",       "APOSTROPHE",    "COMMA",        "MINUS",        "PERIOD",        "SLASH",
    "SEMICOLON",   "EQUAL",         "LEFT_BRACKET", "BACKSLASH",    "RIGHT_BRACKET", "GRAVE_ACCENT",
    "WORLD_1",     "WORLD_2",       "ESCAPE",       "ENTER",        "TAB",           "BACKSPACE",
    "INSERT",      "DELETE",        "RIGHT",        "LEFT",         "DOWN",          "UP",
    "PAGE_UP",     "PAGE_DOWN",     "HOME",         "END",          "CAPS_LOCK",     "SCROLL_LOCK",
    "NUM_LOCK",    "PRINT_SCREEN",  "PAUSE",        "KP_0",         "KP_1",          "KP_2",
    "KP_3",        "KP_4",          "KP_5",         "KP_6",         "KP_7",          "KP_8",
    "KP_9",        "KP_DECIMAL",    "KP_DIVIDE",    "KP_MULTIPLY",  "KP_SUBTRACT",   "KP_ADD",
    "KP_ENTER",    "KP_EQUAL",      "LEFT_SHIFT",   "LEFT_CONTROL", "LEFT_ALT",      "LEFT_SUPER",
    "RIGHT_SHIFT", "RIGHT_CONTROL", "RIGHT_ALT",    "RIGHT_SUPER",  "MENU"};

// The shortest text that reads back as the same float: 0.1f is written "0.1", not the
// 0.100000001490116 its double conversion would print.
std::string formatFloat(float value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

double asShortestDouble(float value) {
  return std::strtod(formatFloat(value).c_str(), nullptr);
}

enum class LowerBound { exclusive, inclusive };

class SettingsReader {
 public:
  explicit SettingsReader(UserJsonFile& file) : file_(file) {}

  Settings read() {
    Settings settings;
    file_.reportUnknownKeys(
        "", {kVersionKey, "mouse_sensitivity", "invert_y", "field_of_view_degrees", "render_scale",
             "vsync", "dynamic_render_scale", "key_bindings"});
    readNumber("mouse_sensitivity", kMinMouseSensitivity, LowerBound::exclusive,
               kMaxMouseSensitivity, settings.mouseSensitivity);
    readBoolean("invert_y", settings.invertY);
    // null (the default) keeps each level's own camera field of view.
    if (const Json* fov = member("field_of_view_degrees"); fov && !fov->is_null()) {
      float degrees = 0.0f;
      if (readNumber("field_of_view_degrees", kMinFieldOfViewDegrees, LowerBound::inclusive,
                     kMaxFieldOfViewDegrees, degrees, "null (the level's)"))
        settings.fieldOfViewDegrees = degrees;
    }
    readNumber("render_scale", kMinRenderScale, LowerBound::exclusive, kMaxRenderScale,
               settings.renderScale);
    readBoolean("vsync", settings.vsync);
    readBoolean("dynamic_render_scale", settings.dynamicRenderScale);
    readKeyBindings(settings.keyBindings);
    return settings;
  }

 private:
  const Json* member(const std::string& key) const {
    const auto found = file_.root().find(key);
    return found == file_.root().end() ? nullptr : &*found;
  }

  // Leaves `value` (the default) alone unless the file holds a number in range; returns
  // whether it read one. `defaultText` names the default in the message (else `value`).
  bool readNumber(const std::string& key, float min, LowerBound lowerBound, float max, float& value,
                  const std::string& defaultText = "") {
    const Json* json = member(key);
    if (!json) return false;
    const bool minInclusive = lowerBound == LowerBound::inclusive;
    const bool aboveMin = json->is_number() &&
                          (minInclusive ? json->get<double>() >= min : json->get<double>() > min);
    if (aboveMin && json->get<double>() <= max) {
      value = json->get<float>();
      return true;
    }
    const std::string range =
        std::string(minInclusive ? "[" : "(") + formatFloat(min) + ", " + formatFloat(max) + "]";
    file_.reportValue("/" + key, "expected a number in " + range + ", got " + describeJson(*json) +
                                     "; using the default " +
                                     (defaultText.empty() ? formatFloat(value) : defaultText));
    return false;
  }

  void readBoolean(const std::string& key, bool& value) {
    const Json* json = member(key);
    if (!json) return;
    if (json->is_boolean()) {
      value = json->get<bool>();
      return;
    }
    file_.reportValue("/" + key, "expected true or false, got " + describeJson(*json) +
                                     "; using the default " + (value ? "true" : "false"));
  }

  // Actions the file leaves out keep their default keys, so a file from before an action
  // existed still binds it.
  void readKeyBindings(std::map<std::string, std::string>& bindings) {
    const Json* json = member("key_bindings");
    if (!json) return;
    if (!json->is_object()) {
      file_.reportValue("/key_bindings", "expected an object mapping actions to key names, got " +
                                             describeJson(*json) + "; using the default bindings");
      return;
    }
    for (const auto& [action, key] : json->items()) {
      const std::string pointer = "/key_bindings/" + escapeJsonPointerToken(action);
      const auto binding = bindings.find(action);
      if (binding == bindings.end()) {
        file_.reportKey(pointer, "unknown action; ignored");
      } else if (!key.is_string() || !isKeyName(key.get<std::string>())) {
        file_.reportValue(pointer, "expected a GLFW key name such as \"W\" or \"SPACE\", got " +
                                       describeJson(key) + "; using the default \"" +
                                       binding->second + "\"");
      } else {
        binding->second = key.get<std::string>();
      }
    }
  }

  UserJsonFile& file_;
};

}  // namespace

std::map<std::string, std::string> Settings::defaultKeyBindings() {
  return {{"forward", "W"},    {"back", "S"},     {"left", "A"},        {"right", "D"},
          {"jump", "SPACE"},   {"interact", "E"}, {"adjust_down", "Q"}, {"adjust_up", "R"},
          {"pause", "ESCAPE"}, {"restart", "F5"}, {"fullscreen", "F11"}};
}

bool isKeyName(const std::string& name) {
  if (name.size() == 1)
    return (name[0] >= 'A' && name[0] <= 'Z') || (name[0] >= '0' && name[0] <= '9');
  if (name.size() >= 2 && name.size() <= 3 && name[0] == 'F' && name[1] != '0') {
    int number = 0;
    const auto result = std::from_chars(name.data() + 1, name.data() + name.size(), number);
    if (result.ec == std::errc() && result.ptr == name.data() + name.size())
      return number >= 1 && number <= 25;
  }
  for (const std::string_view key : kNamedKeys) {
    if (key == name) return true;
  }
  return false;
}

SettingsLoad loadSettings(const fs::path& file) {
  SettingsLoad load;
  if (auto opened =
          UserJsonFile::open(file, kVersionKey, kSettingsVersion, kWhenIgnored, load.messages))
    load.settings = SettingsReader(*opened).read();
  return load;
}

void saveSettings(const Settings& settings, const fs::path& file) {
  Json json;
  json[kVersionKey] = kSettingsVersion;
  json["mouse_sensitivity"] = asShortestDouble(settings.mouseSensitivity);
  json["invert_y"] = settings.invertY;
  json["field_of_view_degrees"] = settings.fieldOfViewDegrees
                                      ? Json(asShortestDouble(*settings.fieldOfViewDegrees))
                                      : Json(nullptr);
  json["render_scale"] = asShortestDouble(settings.renderScale);
  json["vsync"] = settings.vsync;
  json["dynamic_render_scale"] = settings.dynamicRenderScale;
  json["key_bindings"] = Json::object();
  for (const auto& [action, key] : settings.keyBindings) json["key_bindings"][action] = key;
  writeFileAtomically(file, json.dump(2) + "\n");
}

}  // namespace game
