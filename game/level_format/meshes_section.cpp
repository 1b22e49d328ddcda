#include "game/level_format/sections.hpp"

#include "game/primitives.hpp"

// The "meshes" section: built-in shapes and glTF models.
namespace game::level_format {

namespace {

scene::MeshData readGltf(LevelReader& reader, const OrderedJson& mesh, const std::string& pointer,
                         Level& level) {
  if (mesh.contains("node") && mesh.contains("mesh")) {
    reader.failKey(pointer, "mesh",
                   "\"node\" and \"mesh\" both pick part of the model; give only one");
  }
  GltfSelection selection;
  if (mesh.contains("node")) {
    selection.node =
        reader.readString(mesh["node"], childPointer(pointer, "node"), 1, kMaxStringCharacters);
  }
  if (mesh.contains("mesh")) {
    selection.mesh =
        reader.readString(mesh["mesh"], childPointer(pointer, "mesh"), 1, kMaxStringCharacters);
  }
  const std::string gltfPointer = childPointer(pointer, "gltf");
  const ResolvedFile file =
      reader.resolveFile(mesh["gltf"], gltfPointer, "model", {".gltf", ".glb"});
  GltfModel model;
  try {
    model = loadGltfModel(file.path, file.allowedRoot, selection);
  } catch (const LevelError& problem) {
    reader.failValue(gltfPointer, problem.what());
  }
  reader.addTriangles(model.mesh.indices.size() / 3, pointer);
  reader.addSourceFile(level, file.path);
  for (const std::filesystem::path& read : model.filesRead) reader.addSourceFile(level, read);
  level.warnings.insert(level.warnings.end(), model.warnings.begin(), model.warnings.end());
  std::vector<std::string>& names = level.meshMaterialNames.back();
  for (const GltfMaterial& material : model.materials) names.push_back(material.name);
  reader.meshMaterialSources.back().gltfMaterials = std::move(model.materials);
  return std::move(model.mesh);
}

}  // namespace

scene::MeshData readMesh(LevelReader& reader, const OrderedJson& mesh, const std::string& pointer,
                         Level& level) {
  reader.checkKeys(mesh, pointer, {"box", "sphere", "plane", "cylinder", "gltf", "node", "mesh"},
                   {});
  std::vector<std::string> shapes;
  for (const char* shape : {"box", "sphere", "plane", "cylinder", "gltf"}) {
    if (mesh.contains(shape)) shapes.push_back(shape);
  }
  if (shapes.size() != 1) {
    reader.failValue(pointer,
                     "expected exactly one of \"box\", \"sphere\", \"plane\", \"cylinder\", "
                     "\"gltf\", got " +
                         (shapes.empty() ? std::string("none") : joinQuoted(shapes)));
  }
  const std::string& shape = shapes.front();
  for (const char* selector : {"node", "mesh"}) {
    if (shape != "gltf" && mesh.contains(selector)) {
      reader.failKey(
          pointer, selector,
          std::string("\"") + selector + "\" picks part of a glTF model and needs \"gltf\"");
    }
  }
  // Parallel to level.meshes; the material is filled in for glTF models that bring one.
  reader.meshMaterialSources.push_back({shape == "gltf", {}});
  const OrderedJson& params = mesh[shape];
  const std::string paramsPointer = childPointer(pointer, shape);
  if (shape == "box") {
    reader.checkKeys(params, paramsPointer, {"size"}, {"size"});
    const glm::vec3 size =
        reader.readVec3(params["size"], childPointer(paramsPointer, "size"), kLength);
    reader.addTriangles(12, pointer);
    return primitives::box(size);
  }
  if (shape == "sphere") {
    reader.checkKeys(params, paramsPointer, {"radius", "segments", "rings"}, {"radius"});
    const float radius =
        reader.readNumber(params["radius"], childPointer(paramsPointer, "radius"), kLength);
    const uint32_t segments =
        reader.readOptionalCount(params, "segments", paramsPointer, 3, kMaxSegments, 32);
    const uint32_t rings =
        reader.readOptionalCount(params, "rings", paramsPointer, 2, kMaxRings, 16);
    reader.addTriangles(2 * std::size_t{segments} * (rings - 1), pointer);
    return primitives::sphere(radius, segments, rings);
  }
  if (shape == "plane") {
    reader.checkKeys(params, paramsPointer, {"size"}, {"size"});
    const glm::vec2 size = reader.readVec2(params["size"], childPointer(paramsPointer, "size"),
                                           kLength, "an array of 2 numbers [width, depth]");
    reader.addTriangles(2, pointer);
    return primitives::plane(size.x, size.y);
  }
  if (shape == "cylinder") {
    reader.checkKeys(params, paramsPointer, {"radius", "height", "segments"}, {"radius", "height"});
    const float radius =
        reader.readNumber(params["radius"], childPointer(paramsPointer, "radius"), kLength);
    const float height =
        reader.readNumber(params["height"], childPointer(paramsPointer, "height"), kLength);
    const uint32_t segments =
        reader.readOptionalCount(params, "segments", paramsPointer, 3, kMaxSegments, 32);
    reader.addTriangles(4 * std::size_t{segments}, pointer);
    return primitives::cylinder(radius, height, segments);
  }
  return readGltf(reader, mesh, pointer, level);
}

}  // namespace game::level_format
