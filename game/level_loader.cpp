#include "game/level_loader.hpp"

#include <fstream>
#include <map>

#include "game/json_document.hpp"
#include "game/level_format/level_reader.hpp"
#include "game/level_format/sections.hpp"
#include "scene/flat_faces.hpp"

namespace game {

namespace {

namespace fs = std::filesystem;
using namespace level_format;

// The top level of a level file: which sections there are and the order they are read in.
Level readLevel(LevelReader& reader, const std::string& text) {
  if (text.size() > kMaxLevelFileBytes) {
    throw LevelError(reader.file().string() + ": level file is larger than the 16 MiB limit");
  }
  const OrderedJson root = reader.parse();
  if (const auto& duplicate = reader.positions().firstDuplicateKey()) {
    reader.failDuplicateKey(*duplicate);
  }

  Level level;
  level.file = reader.file();
  level.sourceFiles.push_back(reader.file());
  if (!root.is_object()) reader.expected(root, "", "an object");
  // The format decides what every other key means, so it is checked before them.
  if (!root.contains("format")) reader.failMissing("", "format");
  level.format = reader.readFormat(root["format"]);
  reader.checkKeys(
      root, "",
      {"format", "name", "description", "author", "hint", "camera", "environment", "rendering",
       "materials", "meshes", "entities", "lights", "goal", "lose", "logic"},
      {"name", "camera", "materials", "meshes", "entities"});
  level.name = reader.readName(root["name"], "/name");
  level.description = reader.readOptionalString(root, "description", "");
  level.author = reader.readOptionalString(root, "author", "");
  level.hint = reader.readOptionalString(root, "hint", "");
  level.camera = readCamera(reader, root["camera"], "/camera");
  if (root.contains("environment")) {
    level.environment = readEnvironment(reader, root["environment"], "/environment");
  }
  if (root.contains("rendering")) {
    readRendering(reader, root["rendering"], "/rendering", level);
  }

  // Every id is known before any reference is read, so a reference can say what an id of the
  // wrong kind is.
  const std::map<IdKind, const char*> sectionKeys{{IdKind::Material, "materials"},
                                                  {IdKind::Mesh, "meshes"},
                                                  {IdKind::Entity, "entities"},
                                                  {IdKind::Light, "lights"},
                                                  {IdKind::Rule, "logic"}};
  for (const auto& [kind, key] : sectionKeys) {
    if (root.contains(key)) reader.declareIds(root[key], std::string("/") + key, kind);
  }

  reader.forEachEntry(
      root["materials"], "/materials",
      [&](const std::string& id, const OrderedJson& value, const std::string& pointer) {
        level.materialIds.push_back(id);
        level.materials.push_back(readMaterial(reader, value, pointer, level));
      });
  reader.forEachEntry(
      root["meshes"], "/meshes",
      [&](const std::string& id, const OrderedJson& value, const std::string& pointer) {
        level.meshIds.push_back(id);
        level.meshMaterialNames.emplace_back();
        level.meshes.push_back(readMesh(reader, value, pointer, level));
        level.meshes.back().name = id;
      });
  if (root.contains("lights")) {
    reader.forEachEntry(
        root["lights"], "/lights",
        [&](const std::string& id, const OrderedJson& value, const std::string& pointer) {
          level.lightIds.push_back(id);
          level.lightCarriers.emplace_back();
          level.lights.push_back(readLight(reader, value, pointer, level.lightCarriers.back()));
        });
  }
  reader.forEachEntry(
      root["entities"], "/entities",
      [&](const std::string& id, const OrderedJson& value, const std::string& pointer) {
        level.entities.push_back(readEntity(reader, id, value, pointer, level));
        const Entity& entity = level.entities.back();
        if (level.lightViaMirrors && !level.lights.empty() && level.maxMirrorBounces > 0 &&
            level.materials[entity.material].kind == scene::MaterialKind::Mirror &&
            scene::flatFaces(level.meshes[entity.mesh]).empty())
          level.warnings.push_back(
              reader.placeOf(pointer) +
              "a mirror on a curved mesh shows the reflected view but sends "
              "no light on (only flat mirror faces light surfaces and sensors)");
      });
  if (root.contains("goal")) level.goal = readGoal(reader, root["goal"], "/goal", 1);
  if (root.contains("lose")) level.lose = readLoseConditions(reader, root["lose"], "/lose");
  if (root.contains("logic")) readLogic(reader, root["logic"], "/logic", level);
  return level;
}

}  // namespace

Level parseLevel(const std::string& text, const fs::path& file, const LevelLoadOptions& options) {
  LevelReader reader(text, file, options);
  try {
    return readLevel(reader, text);
  } catch (const JsonInputError& error) {
    throw LevelError(error.what());
  }
}

Level loadLevel(const fs::path& file, const LevelLoadOptions& options) {
  std::error_code error;
  std::ifstream stream;
  if (fs::is_regular_file(file, error)) stream.open(file, std::ios::binary);
  if (!stream.is_open()) throw LevelError(file.string() + ": cannot open level file");
  std::string text = readAtMostPastLimit(stream, kMaxLevelFileBytes);
  if (stream.bad()) throw LevelError(file.string() + ": cannot read level file");
  return parseLevel(text, file, options);
}

}  // namespace game
