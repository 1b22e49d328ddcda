#pragma once
// Loads triangle geometry from a glTF 2.0 file (.gltf or .glb) for use as a level mesh.
#include <filesystem>
#include <string>

#include "render/scene_desc.hpp"

namespace game {

// Reads `file` and merges its triangle primitives into one mesh with positions and normals
// (area-weighted normals are computed where the file has none).
//  - `meshName` empty: every mesh instance reachable from the default scene's nodes, with the
//    node transforms applied (every mesh, untransformed, if the file has no scenes).
//  - `meshName` set: only the mesh of that name, in its own coordinates.
// Every file tinygltf reads (the model itself, buffers, images) must resolve inside
// `allowedRoot`. Images are never decoded. Throws game::LevelError("<file>: <problem>").
render::MeshData loadGltfMesh(const std::filesystem::path& file,
                              const std::filesystem::path& allowedRoot,
                              const std::string& meshName = {});

}  // namespace game
