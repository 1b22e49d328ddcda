#include "game/level_loader.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "game/gltf_mesh.hpp"
#include "game/json_positions.hpp"
#include "game/primitives.hpp"
#include "render/color.hpp"

namespace game {

namespace {

namespace fs = std::filesystem;
// Ordered so ids keep the order the author wrote them in.
using Json = nlohmann::ordered_json;

constexpr std::size_t kMaxLevelFileBytes = 16u << 20;
constexpr int kSupportedFormat = 1;
// Bounds on tessellation so a typo cannot allocate gigabytes.
constexpr int64_t kMaxSegments = 4096;
constexpr int64_t kMaxRings = 2048;

std::string formatNumber(double value) {
  std::ostringstream stream;
  stream << value;
  return stream.str();
}

// A short rendering of what the author wrote, for "got ..." in messages.
std::string describe(const Json& value) {
  auto dump = [](const Json& json) {
    return json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  };
  constexpr std::size_t kMaxShown = 40;
  if (value.is_object()) return value.empty() ? "{}" : "an object";
  if (value.is_array()) {
    const std::string text = dump(value);
    return text.size() <= kMaxShown ? text
                                    : "an array of " + std::to_string(value.size()) + " elements";
  }
  if (value.is_string()) {
    const auto& text = value.get_ref<const std::string&>();
    if (text.size() > kMaxShown) return dump(Json(text.substr(0, kMaxShown))) + "...";
  }
  return dump(value);
}

std::string joinQuoted(const std::vector<std::string>& items) {
  constexpr std::size_t kMaxListed = 20;
  if (items.empty()) return "(none)";
  std::string joined;
  for (std::size_t i = 0; i < items.size() && i < kMaxListed; ++i) {
    if (i > 0) joined += ", ";
    joined += "\"" + items[i] + "\"";
  }
  if (items.size() > kMaxListed) joined += ", ... (" + std::to_string(items.size()) + " in all)";
  return joined;
}

bool isValidId(const std::string& id) {
  return !id.empty() && std::all_of(id.begin(), id.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  });
}

bool isHexDigit(char c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

// Which end of a range a number may not cross, and whether touching it is allowed.
struct NumberRule {
  std::optional<double> min;
  bool minInclusive = true;
  std::optional<double> max;
  bool maxInclusive = true;

  bool accepts(double value) const {
    if (min && (minInclusive ? value < *min : value <= *min)) return false;
    if (max && (maxInclusive ? value > *max : value >= *max)) return false;
    return true;
  }

  std::string describe(const char* noun = "a number") const {
    std::string text = noun;
    if (min && max) {
      return text + " in " + (minInclusive ? "[" : "(") + formatNumber(*min) + ", " +
             formatNumber(*max) + (maxInclusive ? "]" : ")");
    }
    if (min) return text + (minInclusive ? " >= " : " > ") + formatNumber(*min);
    if (max) return text + (maxInclusive ? " <= " : " < ") + formatNumber(*max);
    return text;
  }
};

const NumberRule kAnyNumber{};
const NumberRule kPositive{0.0, false, {}, true};
const NumberRule kNonNegative{0.0, true, {}, true};
const NumberRule kUnitInterval{0.0, true, 1.0, true};

class LevelParser {
 public:
  LevelParser(const std::string& text, const fs::path& file, const LevelLoadOptions& options)
      : text_(text), file_(file), options_(options) {}

  Level parse() {
    if (text_.size() > kMaxLevelFileBytes) {
      throw LevelError(file_.string() + ": level file is larger than the 16 MiB limit");
    }
    Json root;
    try {
      root = Json::parse(text_);
    } catch (const Json::exception&) {
      failInvalidJson();
    }
    positions_ = JsonPositions::scan(text_);
    if (const auto& duplicate = positions_.firstDuplicateKey()) {
      const std::string key = duplicate->pointer.substr(duplicate->pointer.rfind('/') + 1);
      failAt(duplicate->position, duplicate->pointer, "duplicate key \"" + key + "\"");
    }

    Level level;
    level.file = file_;
    if (!root.is_object()) expected(root, "", "an object");
    // The format decides what every other key means, so it is checked before them.
    if (!root.contains("format")) failMissing("", "format");
    level.format = readFormat(root["format"]);
    checkKeys(root, "",
              {"format", "name", "description", "camera", "environment", "materials", "meshes",
               "entities", "lights"},
              {"name", "camera", "materials", "meshes", "entities", "lights"});
    level.name = readString(root["name"], "/name", false);
    if (root.contains("description")) {
      level.description = readString(root["description"], "/description", true);
    }
    level.camera = readCamera(root["camera"], "/camera");
    if (root.contains("environment")) {
      level.environment = readEnvironment(root["environment"], "/environment");
    }
    forEachEntry(root["materials"], "/materials", "material", "materials",
                 [&](const std::string& id, const Json& value, const std::string& pointer) {
                   level.materialIds.push_back(id);
                   level.materials.push_back(readMaterial(value, pointer));
                 });
    forEachEntry(root["meshes"], "/meshes", "mesh", "meshes",
                 [&](const std::string& id, const Json& value, const std::string& pointer) {
                   level.meshIds.push_back(id);
                   level.meshes.push_back(readMesh(value, pointer));
                   level.meshes.back().name = id;
                 });
    forEachEntry(root["entities"], "/entities", "entity", "entities",
                 [&](const std::string& id, const Json& value, const std::string& pointer) {
                   level.entities.push_back(readEntity(id, value, pointer, level));
                 });
    if (level.entities.empty()) {
      failValue("/entities", "a level needs at least one entity, got {}");
    }
    forEachEntry(root["lights"], "/lights", "light", "lights",
                 [&](const std::string& id, const Json& value, const std::string& pointer) {
                   level.lightIds.push_back(id);
                   level.lights.push_back(readLight(value, pointer));
                 });
    return level;
  }

 private:
  // ----- messages -----

  // Collects the first error of a SAX parse. Json::parse throws parse_error for syntax errors,
  // which carries a position, but out_of_range (a number too large) without one; the SAX
  // interface reports both with a position.
  struct FirstJsonError : nlohmann::json_sax<Json> {
    std::size_t bytesRead = 0;
    std::string lastToken;
    std::string what;
    bool isSyntaxError = true;

    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override { return true; }
    bool key(string_t&) override { return true; }
    bool end_object() override { return true; }
    bool start_array(std::size_t) override { return true; }
    bool end_array() override { return true; }
    bool parse_error(std::size_t position, const std::string& token,
                     const nlohmann::detail::exception& error) override {
      bytesRead = position;
      lastToken = token;
      what = error.what();
      isSyntaxError = dynamic_cast<const nlohmann::detail::parse_error*>(&error) != nullptr;
      return false;
    }
  };

  [[noreturn]] void failInvalidJson() const {
    FirstJsonError error;
    Json::sax_parse(text_, &error);
    // A syntax error stops at the offending byte; a number that overflows is reported after
    // its token was read, so point at the token's start instead.
    const SourcePosition at =
        error.isSyntaxError ? positionOfParseError(text_, error.bytesRead)
                            : positionOfOffset(text_, error.bytesRead >= error.lastToken.size()
                                                          ? error.bytesRead - error.lastToken.size()
                                                          : 0);
    // what() reads "[json.exception.parse_error.101] parse error at line 1, column 7: <reason>"
    // or "[json.exception.out_of_range.406] <reason>".
    std::string reason = error.what;
    if (const std::size_t prefixEnd = reason.find("] "); prefixEnd != std::string::npos) {
      reason.erase(0, prefixEnd + 2);
    }
    if (reason.rfind("parse error", 0) == 0) {
      if (const std::size_t colon = reason.find(": "); colon != std::string::npos) {
        reason.erase(0, colon + 2);
      }
    }
    throw LevelError(file_.string() + ":" + std::to_string(at.line) + ":" +
                     std::to_string(at.column) + ": invalid JSON: " + reason);
  }

  [[noreturn]] void failAt(SourcePosition at, const std::string& pointer,
                           const std::string& message) const {
    throw LevelError(file_.string() + ":" + std::to_string(at.line) + ":" +
                     std::to_string(at.column) + ": " + (pointer.empty() ? "/" : pointer) + ": " +
                     message);
  }

  [[noreturn]] void failValue(const std::string& pointer, const std::string& message) const {
    failAt(positions_.valueAt(pointer), pointer, message);
  }

  [[noreturn]] void expected(const Json& value, const std::string& pointer,
                             const std::string& what) const {
    failValue(pointer, "expected " + what + ", got " + describe(value));
  }

  [[noreturn]] void failMissing(const std::string& objectPointer, const std::string& key) const {
    failValue(objectPointer, "missing required key \"" + key + "\"");
  }

  // ----- structure -----

  static std::string child(const std::string& pointer, const std::string& key) {
    return pointer + "/" + escapeJsonPointerToken(key);
  }

  static std::string child(const std::string& pointer, std::size_t index) {
    return pointer + "/" + std::to_string(index);
  }

  void requireObject(const Json& value, const std::string& pointer) const {
    if (!value.is_object()) expected(value, pointer, "an object");
  }

  // Unknown keys are reported first (they are often misspelt required ones), then missing ones.
  void checkKeys(const Json& object, const std::string& pointer,
                 std::initializer_list<const char*> allowed,
                 std::initializer_list<const char*> required) const {
    requireObject(object, pointer);
    for (const auto& [key, value] : object.items()) {
      const bool known = std::any_of(allowed.begin(), allowed.end(),
                                     [&](const char* name) { return key == name; });
      if (!known) {
        std::string list;
        for (const char* name : allowed) list += (list.empty() ? "" : ", ") + std::string(name);
        const std::string memberPointer = child(pointer, key);
        failAt(positions_.keyAt(memberPointer), memberPointer,
               "unknown key \"" + key + "\"; allowed keys: " + list);
      }
    }
    for (const char* name : required) {
      if (!object.contains(name)) failMissing(pointer, name);
    }
  }

  template <typename ReadEntry>
  void forEachEntry(const Json& object, const std::string& pointer, const std::string& noun,
                    const std::string& plural, ReadEntry readEntry) const {
    if (!object.is_object()) expected(object, pointer, "an object mapping ids to " + plural);
    for (const auto& [id, value] : object.items()) {
      const std::string entryPointer = child(pointer, id);
      if (!isValidId(id)) {
        failAt(positions_.keyAt(entryPointer), entryPointer,
               "invalid " + noun + " id \"" + id +
                   "\": ids are non-empty and use only letters, digits, '_' and '-'");
      }
      readEntry(id, value, entryPointer);
    }
  }

  // ----- scalars -----

  int readFormat(const Json& value) const {
    if (!value.is_number_integer()) expected(value, "/format", "the integer 1");
    if (value.get<int64_t>() != kSupportedFormat) {
      failValue("/format", "unsupported format " + describe(value) +
                               "; this version reads format " + std::to_string(kSupportedFormat));
    }
    return kSupportedFormat;
  }

  std::string readString(const Json& value, const std::string& pointer, bool mayBeEmpty) const {
    if (!value.is_string() || (!mayBeEmpty && value.get_ref<const std::string&>().empty())) {
      expected(value, pointer, mayBeEmpty ? "a string" : "a non-empty string");
    }
    return value.get<std::string>();
  }

  float readNumber(const Json& value, const std::string& pointer, const NumberRule& rule) const {
    // nlohmann turns out-of-range literals such as 1e999 into infinity, hence the isfinite.
    if (!value.is_number() || !std::isfinite(value.get<double>()) ||
        !rule.accepts(value.get<double>())) {
      expected(value, pointer, rule.describe());
    }
    const auto narrowed = static_cast<float>(value.get<double>());
    if (!std::isfinite(narrowed)) expected(value, pointer, rule.describe("a 32-bit float"));
    return narrowed;
  }

  float readOptionalNumber(const Json& object, const char* key, const std::string& pointer,
                           const NumberRule& rule, float fallback) const {
    return object.contains(key) ? readNumber(object[key], child(pointer, key), rule) : fallback;
  }

  uint32_t readCount(const Json& value, const std::string& pointer, int64_t min,
                     int64_t max) const {
    if (!value.is_number_integer() ||
        (value.is_number_unsigned() && value.get<uint64_t>() > static_cast<uint64_t>(max)) ||
        value.get<int64_t>() < min || value.get<int64_t>() > max) {
      expected(value, pointer,
               "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
    }
    return static_cast<uint32_t>(value.get<int64_t>());
  }

  uint32_t readOptionalCount(const Json& object, const char* key, const std::string& pointer,
                             int64_t min, int64_t max, uint32_t fallback) const {
    return object.contains(key) ? readCount(object[key], child(pointer, key), min, max) : fallback;
  }

  glm::vec3 readVec3(const Json& value, const std::string& pointer, const NumberRule& rule) const {
    if (!value.is_array() || value.size() != 3) {
      expected(value, pointer, "an array of 3 numbers [x, y, z]");
    }
    return {readNumber(value[0], child(pointer, 0), rule),
            readNumber(value[1], child(pointer, 1), rule),
            readNumber(value[2], child(pointer, 2), rule)};
  }

  // Authored in sRGB, returned linear.
  glm::vec3 readColor(const Json& value, const std::string& pointer) const {
    static const std::string kWhat =
        "a colour: [r, g, b] with components in [0, 1] or a string \"#rrggbb\"";
    if (value.is_array() && value.size() == 3) {
      glm::vec3 encoded;
      for (std::size_t i = 0; i < 3; ++i) {
        encoded[static_cast<glm::length_t>(i)] =
            readNumber(value[i], child(pointer, i), kUnitInterval);
      }
      return render::srgbToLinear(encoded);
    }
    if (value.is_string()) {
      const auto& text = value.get_ref<const std::string&>();
      if (text.size() == 7 && text[0] == '#' &&
          std::all_of(text.begin() + 1, text.end(), isHexDigit)) {
        glm::vec3 encoded;
        for (int i = 0; i < 3; ++i) {
          encoded[i] = static_cast<float>(std::stoi(
                           text.substr(1 + 2 * static_cast<std::size_t>(i), 2), nullptr, 16)) /
                       255.0f;
        }
        return render::srgbToLinear(encoded);
      }
    }
    expected(value, pointer, kWhat);
  }

  glm::vec3 readOptionalColor(const Json& object, const char* key, const std::string& pointer,
                              const glm::vec3& fallback) const {
    return object.contains(key) ? readColor(object[key], child(pointer, key)) : fallback;
  }

  // ----- sections -----

  render::CameraDesc readCamera(const Json& camera, const std::string& pointer) const {
    checkKeys(camera, pointer, {"position", "yaw_degrees", "pitch_degrees", "fov_degrees"},
              {"position"});
    render::CameraDesc desc;
    desc.position = readVec3(camera["position"], child(pointer, "position"), kAnyNumber);
    desc.yawDegrees = readOptionalNumber(camera, "yaw_degrees", pointer, kAnyNumber, 0.0f);
    desc.pitchDegrees = readOptionalNumber(camera, "pitch_degrees", pointer, kAnyNumber, 0.0f);
    desc.verticalFovDegrees = readOptionalNumber(camera, "fov_degrees", pointer,
                                                 NumberRule{0.0, false, 179.0, true}, 60.0f);
    return desc;
  }

  render::EnvironmentDesc readEnvironment(const Json& environment,
                                          const std::string& pointer) const {
    checkKeys(environment, pointer, {"sky_zenith", "sky_horizon", "ambient"}, {});
    render::EnvironmentDesc desc;
    desc.skyZenith = readOptionalColor(environment, "sky_zenith", pointer, glm::vec3(0.0f));
    desc.skyHorizon = readOptionalColor(environment, "sky_horizon", pointer, glm::vec3(0.0f));
    desc.ambient = readOptionalColor(environment, "ambient", pointer, glm::vec3(0.0f));
    return desc;
  }

  render::MaterialDesc readMaterial(const Json& material, const std::string& pointer) const {
    checkKeys(material, pointer,
              {"color", "specular", "roughness", "emissive", "emissive_strength"}, {"color"});
    render::MaterialDesc desc;
    desc.baseColor = readColor(material["color"], child(pointer, "color"));
    desc.specular = readOptionalNumber(material, "specular", pointer, kUnitInterval, 0.0f);
    desc.roughness =
        readOptionalNumber(material, "roughness", pointer, NumberRule{0.0, false, 1.0, true}, 0.5f);
    const glm::vec3 emissive = readOptionalColor(material, "emissive", pointer, glm::vec3(0.0f));
    desc.emissive =
        emissive * readOptionalNumber(material, "emissive_strength", pointer, kNonNegative, 1.0f);
    return desc;
  }

  render::MeshData readMesh(const Json& mesh, const std::string& pointer) const {
    checkKeys(mesh, pointer, {"box", "sphere", "plane", "cylinder", "gltf", "mesh"}, {});
    std::vector<std::string> shapes;
    for (const char* shape : {"box", "sphere", "plane", "cylinder", "gltf"}) {
      if (mesh.contains(shape)) shapes.push_back(shape);
    }
    if (shapes.size() != 1) {
      failValue(pointer,
                "expected exactly one of \"box\", \"sphere\", \"plane\", \"cylinder\", "
                "\"gltf\", got " +
                    (shapes.empty() ? std::string("none") : joinQuoted(shapes)));
    }
    const std::string& shape = shapes.front();
    if (shape != "gltf" && mesh.contains("mesh")) {
      failAt(positions_.keyAt(child(pointer, "mesh")), child(pointer, "mesh"),
             "\"mesh\" picks a mesh inside a glTF file and needs \"gltf\"");
    }
    const Json& params = mesh[shape];
    const std::string paramsPointer = child(pointer, shape);
    if (shape == "box") {
      checkKeys(params, paramsPointer, {"size"}, {"size"});
      return primitives::box(readVec3(params["size"], child(paramsPointer, "size"), kPositive));
    }
    if (shape == "sphere") {
      checkKeys(params, paramsPointer, {"radius", "segments", "rings"}, {"radius"});
      return primitives::sphere(
          readNumber(params["radius"], child(paramsPointer, "radius"), kPositive),
          readOptionalCount(params, "segments", paramsPointer, 3, kMaxSegments, 32),
          readOptionalCount(params, "rings", paramsPointer, 2, kMaxRings, 16));
    }
    if (shape == "plane") {
      checkKeys(params, paramsPointer, {"size"}, {"size"});
      const Json& size = params["size"];
      const std::string sizePointer = child(paramsPointer, "size");
      if (!size.is_array() || size.size() != 2) {
        expected(size, sizePointer, "an array of 2 numbers [width, depth]");
      }
      return primitives::plane(readNumber(size[0], child(sizePointer, 0), kPositive),
                               readNumber(size[1], child(sizePointer, 1), kPositive));
    }
    if (shape == "cylinder") {
      checkKeys(params, paramsPointer, {"radius", "height", "segments"}, {"radius", "height"});
      return primitives::cylinder(
          readNumber(params["radius"], child(paramsPointer, "radius"), kPositive),
          readNumber(params["height"], child(paramsPointer, "height"), kPositive),
          readOptionalCount(params, "segments", paramsPointer, 3, kMaxSegments, 32));
    }
    const std::string meshName =
        mesh.contains("mesh") ? readString(mesh["mesh"], child(pointer, "mesh"), false) : "";
    return readGltf(params, paramsPointer, meshName);
  }

  // Where model files are looked up, in order.
  std::vector<fs::path> modelSearchDirectories() const {
    const fs::path levelDirectory = file_.parent_path().empty() ? "." : file_.parent_path();
    std::vector<fs::path> directories{levelDirectory};
    if (!options_.assetRoots.empty()) {
      directories.insert(directories.end(), options_.assetRoots.begin(), options_.assetRoots.end());
    } else {
      const fs::path defaultAssets = levelDirectory / ".." / "assets";
      std::error_code error;
      if (fs::is_directory(defaultAssets, error)) directories.push_back(defaultAssets);
    }
    return directories;
  }

  // Whether `relative`, resolved against `directory` with symlinks followed, stays under it.
  static bool staysInside(const fs::path& directory, const fs::path& relative) {
    std::error_code error;
    const fs::path canonicalDirectory = fs::weakly_canonical(directory, error);
    if (error) return false;
    const fs::path resolved = fs::weakly_canonical(directory / relative, error);
    if (error) return false;
    const fs::path inside = resolved.lexically_relative(canonicalDirectory);
    return !inside.empty() && *inside.begin() != "..";
  }

  render::MeshData readGltf(const Json& value, const std::string& pointer,
                            const std::string& meshName) const {
    const std::string& text = readString(value, pointer, false);
    const fs::path relative(text);
    if (relative.has_root_path()) {
      failValue(pointer,
                "model path \"" + text + "\" must be relative to the level's directory or assets/");
    }
    // Every candidate is checked before any is opened: a path that escapes one directory is an
    // error even when another directory would hold a file of that name.
    const std::vector<fs::path> directories = modelSearchDirectories();
    for (const fs::path& directory : directories) {
      if (!staysInside(directory, relative)) {
        failValue(pointer,
                  "model path \"" + text + "\" must stay inside the level's directory or assets/");
      }
    }
    std::string extension = relative.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".gltf" && extension != ".glb") {
      expected(value, pointer, "a path to a .gltf or .glb file");
    }

    std::vector<std::string> searched;
    for (const fs::path& directory : directories) {
      searched.push_back(directory.lexically_normal().string());
      std::error_code error;
      if (!fs::is_regular_file(directory / relative, error)) continue;
      try {
        return loadGltfMesh((directory / relative).lexically_normal(), directory, meshName);
      } catch (const LevelError& problem) {
        failValue(pointer, problem.what());
      }
    }
    failValue(pointer, "model file \"" + text + "\" not found; looked in: " + joinQuoted(searched));
  }

  uint32_t readReference(const Json& value, const std::string& pointer, const std::string& noun,
                         const std::string& plural, const std::vector<std::string>& known) const {
    if (!value.is_string()) expected(value, pointer, "a " + noun + " id (a string)");
    const auto& id = value.get_ref<const std::string&>();
    const auto found = std::find(known.begin(), known.end(), id);
    if (found == known.end()) {
      failValue(pointer,
                "unknown " + noun + " \"" + id + "\"; known " + plural + ": " + joinQuoted(known));
    }
    return static_cast<uint32_t>(found - known.begin());
  }

  Entity readEntity(const std::string& id, const Json& entity, const std::string& pointer,
                    const Level& level) const {
    checkKeys(entity, pointer, {"mesh", "material", "position", "rotation_degrees", "scale"},
              {"mesh", "material"});
    Entity result;
    result.id = id;
    result.mesh =
        readReference(entity["mesh"], child(pointer, "mesh"), "mesh", "meshes", level.meshIds);
    result.material = readReference(entity["material"], child(pointer, "material"), "material",
                                    "materials", level.materialIds);
    if (entity.contains("position")) {
      result.position = readVec3(entity["position"], child(pointer, "position"), kAnyNumber);
    }
    if (entity.contains("rotation_degrees")) {
      // [pitch about X, yaw about Y, roll about Z], stored in that order.
      result.rotationDegrees =
          readVec3(entity["rotation_degrees"], child(pointer, "rotation_degrees"), kAnyNumber);
    }
    if (entity.contains("scale")) {
      const Json& scale = entity["scale"];
      const std::string scalePointer = child(pointer, "scale");
      if (scale.is_number()) {
        result.scale = glm::vec3(readNumber(scale, scalePointer, kPositive));
      } else if (scale.is_array() && scale.size() == 3) {
        result.scale = readVec3(scale, scalePointer, kPositive);
      } else {
        expected(scale, scalePointer, "a number > 0 or an array of 3 numbers > 0");
      }
    }
    return result;
  }

  render::LightDesc readLight(const Json& light, const std::string& pointer) const {
    requireObject(light, pointer);
    if (!light.contains("type")) failMissing(pointer, "type");
    const Json& type = light["type"];
    render::LightDesc desc;
    if (type == "point") {
      checkKeys(light, pointer, {"type", "position", "color", "intensity"},
                {"position", "intensity"});
      desc.type = render::LightType::Point;
      desc.position = readVec3(light["position"], child(pointer, "position"), kAnyNumber);
    } else if (type == "directional") {
      checkKeys(light, pointer, {"type", "direction", "color", "intensity"},
                {"direction", "intensity"});
      desc.type = render::LightType::Directional;
      desc.direction = readDirection(light["direction"], child(pointer, "direction"));
    } else {
      expected(type, child(pointer, "type"), "\"point\" or \"directional\"");
    }
    desc.color = readOptionalColor(light, "color", pointer, glm::vec3(1.0f));
    desc.intensity = readNumber(light["intensity"], child(pointer, "intensity"), kNonNegative);
    return desc;
  }

  glm::vec3 readDirection(const Json& value, const std::string& pointer) const {
    const glm::dvec3 direction(readVec3(value, pointer, kAnyNumber));
    const double length = glm::length(direction);
    if (!(length > 0.0) || !std::isfinite(length)) {
      expected(value, pointer, "a non-zero direction [x, y, z]");
    }
    return glm::vec3(direction / length);
  }

  const std::string& text_;
  const fs::path& file_;
  const LevelLoadOptions& options_;
  JsonPositions positions_;
};

}  // namespace

Level parseLevel(const std::string& text, const fs::path& file, const LevelLoadOptions& options) {
  return LevelParser(text, file, options).parse();
}

Level loadLevel(const fs::path& file, const LevelLoadOptions& options) {
  std::error_code error;
  std::ifstream stream;
  if (fs::is_regular_file(file, error)) stream.open(file, std::ios::binary);
  if (!stream.is_open()) throw LevelError(file.string() + ": cannot open level file");

  // Read in chunks and stop past the limit, so a huge file is never held in memory whole.
  std::string text;
  char chunk[1 << 16];
  while (text.size() <= kMaxLevelFileBytes &&
         (stream.read(chunk, sizeof chunk) || stream.gcount() > 0)) {
    text.append(chunk, static_cast<std::size_t>(stream.gcount()));
  }
  if (stream.bad()) throw LevelError(file.string() + ": cannot read level file");
  return parseLevel(text, file, options);
}

}  // namespace game
