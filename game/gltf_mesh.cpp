#include "game/gltf_mesh.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <vector>

#include <tiny_gltf.h>

#include "game/gltf_checks.hpp"
#include "game/gltf_file_access.hpp"
#include "game/gltf_material.hpp"
#include "game/gltf_mesh_assembler.hpp"
#include "game/gltf_unsupported.hpp"
#include "game/json_document.hpp"
#include "game/json_reader.hpp"

namespace game {

namespace {

namespace fs = std::filesystem;

// Refuses a model whose JSON (a .glb's JSON chunk) nests deeper than kMaxJsonNesting or holds
// more than kMaxJsonValues values, before tinygltf builds a tree of it.
void checkJsonNesting(const fs::path& file, bool binary) {
  constexpr std::size_t kMaxJsonBytes = 256u << 20;  // the most tinygltf is given to read
  std::ifstream stream(file, std::ios::binary);
  std::size_t jsonBytes = kMaxJsonBytes;
  if (binary) {
    // "glTF", version, length, then the JSON chunk: its length, "JSON", its bytes.
    char header[20] = {};
    uint32_t chunkBytes = 0;
    if (!stream.read(header, sizeof header)) return;  // tinygltf says what is wrong
    std::memcpy(&chunkBytes, header + 12, sizeof chunkBytes);
    jsonBytes = std::min<std::size_t>(chunkBytes, kMaxJsonBytes);
  }
  std::string text = readAtMostPastLimit(stream, jsonBytes);
  text.resize(std::min(text.size(), jsonBytes));
  if (const std::optional<JsonShapeProblem> problem = jsonShapeProblem(text)) {
    const SourcePosition at = positionOfOffset(text, problem->offset);
    gltf::fail(file, "invalid glTF JSON at line " + std::to_string(at.line) + ", column " +
                         std::to_string(at.column) + ": " + problem->message);
  }
}

// A BLEND surface is drawn as glass, which is a whole entity's kind: in a model that has opaque
// materials too, the BLEND ones are drawn opaque, with a warning saying how to keep them.
void keepBlendWhereAlone(std::vector<GltfMaterial>& materials, const fs::path& file,
                         std::vector<std::string>& warnings) {
  const auto blends = [](const GltfMaterial& material) { return material.alphaBlend; };
  if (std::all_of(materials.begin(), materials.end(), blends) ||
      std::none_of(materials.begin(), materials.end(), blends)) {
    return;
  }
  for (GltfMaterial& material : materials) {
    if (!material.alphaBlend) continue;
    warnings.push_back(file.string() + ": material \"" + material.name +
                       "\" has alphaMode BLEND next to opaque materials in the same mesh: drawn "
                       "opaque; give its part an entity of its own (\"node\" or \"mesh\") to "
                       "draw it transparent");
    material.alphaBlend = false;
  }
}

using gltf::fail;
using gltf::validIndex;

// Error messages list at most this many node or mesh names.
constexpr std::size_t kMaxListedNames = 20;

// tinygltf's messages end in newlines and may hold several lines; messages here are one line.
std::string oneLine(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  std::string joined;
  for (const char c : text) {
    if (c == '\n') {
      joined += "; ";
    } else if (c != '\r') {
      joined.push_back(c);
    }
  }
  return joined.empty() ? "unknown error" : joined;
}

// tinygltf passes nlohmann's exception text on ("[json.exception.parse_error.101] parse error at
// line 4, column 1: ..."): said as the JSON mistake it is.
std::string readableLoadError(const std::string& loadError) {
  std::string text = oneLine(loadError);
  const std::size_t tag = text.find("[json.exception.");
  if (tag == std::string::npos) return text;
  const std::size_t tagEnd = text.find("] ", tag);
  if (tagEnd == std::string::npos) return text;
  return text.substr(0, tag) + "invalid JSON: " + text.substr(tagEnd + 2);
}

template <typename Named>
std::string namesOf(const std::vector<Named>& items) {
  std::string names;
  const std::size_t listed = std::min(items.size(), kMaxListedNames);
  for (std::size_t i = 0; i < listed; ++i) {
    if (!names.empty()) names += ", ";
    names += items[i].name.empty() ? "(unnamed #" + std::to_string(i) + ")"
                                   : "\"" + items[i].name + "\"";
  }
  if (items.size() > listed) names += " and " + std::to_string(items.size() - listed) + " more";
  return names.empty() ? "none" : names;
}

}  // namespace

GltfModel loadGltfModel(const fs::path& file, const fs::path& allowedRoot,
                        const GltfSelection& selection) {
  const std::string extension = toLower(file.extension().string());
  if (extension != ".gltf" && extension != ".glb") {
    fail(file, "expected a .gltf or .glb file");
  }
  if (!selection.node.empty() && !selection.mesh.empty()) {
    fail(file, "select a node or a mesh, not both");
  }
  gltf::FileAccessGuard guard;
  std::error_code error;
  guard.root = fs::weakly_canonical(allowedRoot, error);
  if (error) fail(file, "cannot resolve the directory " + allowedRoot.string());
  if (!fs::is_regular_file(file, error)) fail(file, "cannot open glTF file");
  if (!guard.allows(file.string())) {
    fail(file, "is outside the directory " + allowedRoot.string());
  }

  // tinygltf indexes an empty .glb before checking its size (a raw std::out_of_range).
  if (fs::file_size(file, error) == 0 && !error) fail(file, "cannot load glTF: the file is empty");

  checkJsonNesting(file, extension == ".glb");

  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&gltf::keepEncodedImage, nullptr);
  loader.SetFsCallbacks(gltf::guardedFsCallbacks(guard));

  tinygltf::Model model;
  std::string loadError, loadWarning;
  bool loaded = false;
  try {
    loaded = extension == ".glb"
                 ? loader.LoadBinaryFromFile(&model, &loadError, &loadWarning, file.string())
                 : loader.LoadASCIIFromFile(&model, &loadError, &loadWarning, file.string());
  } catch (const std::exception& exception) {
    fail(file,
         std::string("cannot load glTF: the file is malformed (the glTF reader stopped with \"") +
             oneLine(exception.what()) + "\")");
  }
  if (!guard.refused.empty()) {
    fail(file, "refers to \"" + guard.refused.front() +
                   "\", which is outside the directory the model was found in (" +
                   guard.root.string() + ")");
  }
  if (!loaded) fail(file, "cannot load glTF: " + readableLoadError(loadError));

  GltfModel result;
  gltf::checkUnsupportedFeatures(model, file, result.warnings);
  gltf::MeshAssembler assembler(model, file);
  std::string meshName = file.stem().string();
  if (!selection.mesh.empty()) {
    const auto found =
        std::find_if(model.meshes.begin(), model.meshes.end(),
                     [&](const tinygltf::Mesh& mesh) { return mesh.name == selection.mesh; });
    if (found == model.meshes.end()) {
      fail(file, "has no mesh named \"" + selection.mesh +
                     "\"; its meshes are: " + namesOf(model.meshes));
    }
    assembler.appendMesh(static_cast<int>(found - model.meshes.begin()), glm::dmat4(1.0));
    meshName = selection.mesh;
  } else if (!selection.node.empty()) {
    const auto found =
        std::find_if(model.nodes.begin(), model.nodes.end(),
                     [&](const tinygltf::Node& node) { return node.name == selection.node; });
    if (found == model.nodes.end()) {
      fail(file,
           "has no node named \"" + selection.node + "\"; its nodes are: " + namesOf(model.nodes));
    }
    const int nodeIndex = static_cast<int>(found - model.nodes.begin());
    std::size_t visits = 0;
    gltf::appendSubtree(model, file, nodeIndex, gltf::ancestorTransform(model, file, nodeIndex),
                        assembler, visits);
    meshName = selection.node;
  } else if (model.scenes.empty()) {
    for (std::size_t i = 0; i < model.meshes.size(); ++i) {
      assembler.appendMesh(static_cast<int>(i), glm::dmat4(1.0));
    }
  } else {
    gltf::appendScene(model, file, assembler);
  }
  result.mesh = assembler.finish(meshName);
  if (assembler.droppedTriangles() > 0) {
    result.warnings.push_back(file.string() + ": dropped " +
                              std::to_string(assembler.droppedTriangles()) +
                              " degenerate triangles");
  }

  const std::vector<int>& materials = assembler.materials();
  if (std::any_of(materials.begin(), materials.end(), [](int index) { return index >= 0; })) {
    for (const int materialIndex : materials) {
      if (materialIndex < 0) {
        GltfMaterial fallback;  // glTF's default material, as mapped
        fallback.name = "default";
        result.materials.push_back(fallback);
        continue;
      }
      if (!validIndex(materialIndex, model.materials)) {
        fail(file,
             "refers to material " + std::to_string(materialIndex) + ", which does not exist");
      }
      result.materials.push_back(gltf::mapMaterial(model, file, materialIndex, result.warnings));
    }
  }
  keepBlendWhereAlone(result.materials, file, result.warnings);

  // The model first, as given, then each buffer and image file in the order tinygltf read them.
  result.filesRead.push_back(file);
  const fs::path normalizedModel = file.lexically_normal();
  for (const fs::path& read : guard.read) {
    if (read != normalizedModel) result.filesRead.push_back(read);
  }
  return result;
}

scene::MeshData loadGltfMesh(const fs::path& file, const fs::path& allowedRoot,
                             const std::string& meshName) {
  GltfSelection selection;
  selection.mesh = meshName;
  return loadGltfModel(file, allowedRoot, selection).mesh;
}

}  // namespace game
