#pragma once
// A loaded level: plain data, fully validated. No Vulkan here.
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "render/scene_desc.hpp"

namespace game {

struct Entity {
  std::string id;
  uint32_t mesh = 0;      // index into Level::meshes
  uint32_t material = 0;  // index into Level::materials
  glm::vec3 position{0.0f};
  glm::vec3 rotationDegrees{0.0f};  // applied as yaw (Y), then pitch (X), then roll (Z)
  glm::vec3 scale{1.0f};
};

struct Level {
  std::filesystem::path file;  // the JSON it came from
  int format = 1;
  std::string name;
  std::string description;
  render::CameraDesc camera;
  render::EnvironmentDesc environment;
  std::vector<std::string> materialIds;  // parallel to materials
  std::vector<render::MaterialDesc> materials;
  std::vector<std::string> meshIds;  // parallel to meshes
  std::vector<render::MeshData> meshes;
  std::vector<Entity> entities;
  std::vector<std::string> lightIds;  // parallel to lights
  std::vector<render::LightDesc> lights;
};

glm::mat4 entityTransform(const Entity& entity);

// What the renderer needs to draw the level.
render::SceneDesc buildSceneDesc(const Level& level);

}  // namespace game
