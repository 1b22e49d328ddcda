#pragma once
// One reader per section of a level file, each in its own <section>_section.cpp. Each reads the
// value at `pointer` and fails through `reader` with the file, place and what was expected.
#include <cstdint>
#include <string>
#include <vector>

#include "game/level.hpp"
#include "game/level_format/level_reader.hpp"
#include "scene/scene_desc.hpp"

namespace game::level_format {

scene::CameraDesc readCamera(const LevelReader& reader, const OrderedJson& camera,
                             const std::string& pointer);
// The most mirror bounces a path may take, and whether light is routed via mirrors.
void readRendering(const LevelReader& reader, const OrderedJson& rendering,
                   const std::string& pointer, Level& level);
scene::EnvironmentDesc readEnvironment(const LevelReader& reader, const OrderedJson& environment,
                                       const std::string& pointer);
scene::MaterialDesc readMaterial(LevelReader& reader, const OrderedJson& material,
                                 const std::string& pointer, Level& level);
scene::MeshData readMesh(LevelReader& reader, const OrderedJson& mesh, const std::string& pointer,
                         Level& level);
// A light and the entity it rides on, if any.
scene::LightDesc readLight(const LevelReader& reader, const OrderedJson& light,
                           const std::string& pointer, std::optional<uint32_t>& carrier);
Entity readEntity(LevelReader& reader, const std::string& id, const OrderedJson& entity,
                  const std::string& pointer, Level& level);
Goal readGoal(const LevelReader& reader, const OrderedJson& goal, const std::string& pointer,
              int depth);
// The "logic" section; read last, as its rules refer to every other kind of id.
void readLogic(LevelReader& reader, const OrderedJson& logic, const std::string& pointer,
               Level& level);
std::vector<LoseCondition> readLoseConditions(const LevelReader& reader, const OrderedJson& lose,
                                              const std::string& pointer);

}  // namespace game::level_format
