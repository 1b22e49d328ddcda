#pragma once
// The level format's reader: the JSON toolkit plus what every section of a level needs to
// share — the format's limits, the ids each section declares (so a reference can be checked
// and explained), the file path rules, the textures and files read so far, the triangle budget,
// and the materials glTF models bring for the entities that use them.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "game/gltf_mesh.hpp"
#include "game/json_reader.hpp"
#include "game/level.hpp"
#include "game/level_loader.hpp"

namespace game::level_format {

// ----- limits (docs/LEVELS.md, "Limits") -----

inline constexpr std::size_t kMaxLevelFileBytes = 16u << 20;
inline constexpr int kSupportedFormat = 1;
inline constexpr std::size_t kMaxEntities = 4096;
inline constexpr std::size_t kMaxMeshes = 1024;
inline constexpr std::size_t kMaxLights = 64;
inline constexpr std::size_t kMaxMaterials = 256;
inline constexpr std::size_t kMaxTextures = 64;
inline constexpr std::size_t kMaxTriangles = 2'000'000;
inline constexpr std::size_t kMinKeyframes = 2;
inline constexpr std::size_t kMaxKeyframes = 256;
inline constexpr std::size_t kMaxGoalChildren = 16;
inline constexpr std::size_t kMaxRules = 256;
inline constexpr std::size_t kMaxActions = 64;
// Not in the format's limits: keeps the recursive goal reader off deep stacks.
inline constexpr int kMaxGoalDepth = 8;
inline constexpr std::size_t kMaxNameCharacters = 80;
inline constexpr std::size_t kMaxStringCharacters = 2000;
inline constexpr double kMaxCoordinate = 100000.0;
inline constexpr double kMaxIntensity = 1e9;
// Bounds on tessellation so a typo cannot allocate gigabytes.
inline constexpr int64_t kMaxSegments = 4096;
inline constexpr int64_t kMaxRings = 2048;
inline constexpr int64_t kMaxMirrorBounces = 31;

inline constexpr const char* kCoordinateLimit = "positions and sizes are limited to ±100000 m";
inline constexpr const char* kIntensityLimit = "intensities are limited to 1e9";

inline constexpr NumberRule kCoordinate{-kMaxCoordinate, true, kMaxCoordinate, true,
                                        kCoordinateLimit};
inline constexpr NumberRule kLength{0.0, false, kMaxCoordinate, true, kCoordinateLimit};
inline constexpr NumberRule kIntensity{0.0, true, kMaxIntensity, true, kIntensityLimit};

// The kinds of id a level declares; references name one of them.
enum class IdKind { Material, Mesh, Entity, Light, Rule };

const char* nounOf(IdKind kind);
const char* pluralOf(IdKind kind);
// The top-level key of the section that declares ids of `kind` ("logic" for rules).
const char* sectionOf(IdKind kind);
// "a mesh", "an entity".
std::string withArticle(const std::string& noun);

// A file a level names, found and checked against the path rules.
struct ResolvedFile {
  std::filesystem::path path;         // as opened and shown in messages (lexically normal)
  std::filesystem::path allowedRoot;  // the directory it lies in (the level's or the asset root)
};

class LevelReader : public JsonReader {
 public:
  LevelReader(const std::string& text, const std::filesystem::path& file,
              const LevelLoadOptions& options);

  // ----- ids (level_reader.cpp) -----

  // The ids of one section: an object of valid ids, at most the limit, at least one where the
  // level needs one. Remembers them, in the order written, for readReference.
  void declareIds(const OrderedJson& section, const std::string& pointer, IdKind kind);
  const std::vector<std::string>& idsOf(IdKind kind) const;
  // The index of the `kind` id named at `pointer`; otherwise says what the name is instead.
  uint32_t readReference(const OrderedJson& value, const std::string& pointer, IdKind kind) const;
  [[noreturn]] void failDuplicateKey(const JsonPositions::DuplicateKey& duplicate) const;

  // ----- values of the level format (level_reader.cpp) -----

  int readFormat(const OrderedJson& value) const;
  std::string readName(const OrderedJson& value, const std::string& pointer) const;
  std::string readOptionalString(const OrderedJson& object, const char* key,
                                 const std::string& pointer) const;
  // A goal's or lose condition's words for the player ("Reach the gate"), 1 to 80 characters.
  std::string readOptionalLabel(const OrderedJson& object, const std::string& pointer) const;
  // Linear multipliers, not colours: no sRGB conversion.
  glm::vec3 readTint(const OrderedJson& value, const std::string& pointer) const;
  glm::vec3 readDirection(const OrderedJson& value, const std::string& pointer) const;
  // Authored in sRGB, returned linear.
  glm::vec3 readColor(const OrderedJson& value, const std::string& pointer) const;
  glm::vec3 readOptionalColor(const OrderedJson& object, const char* key,
                              const std::string& pointer, const glm::vec3& fallback) const;
  // A sensor's "color": "any" (the default: luminance, whatever the light's colour) or the
  // channel it needs, "red", "green" or "blue".
  scene::ExposureChannel readSensorColor(const OrderedJson& object,
                                         const std::string& pointer) const;
  // A focus region: [width, height] as fractions of the screen, at "region" or `fallback`.
  glm::vec2 readOptionalRegion(const OrderedJson& object, const std::string& pointer,
                               const glm::vec2& fallback) const;
  // The box of "min" and "max" corners, min < max on every axis (a reach goal, an inside
  // condition).
  void readBox(const OrderedJson& object, const std::string& pointer, glm::vec3& min,
               glm::vec3& max) const;
  // The numbers at `minKey` <= `maxKey` (an interactable's range, a rotation condition's).
  std::pair<float, float> readOrderedPair(const OrderedJson& object, const std::string& pointer,
                                          const char* minKey, const char* maxKey,
                                          const NumberRule& rule) const;

  // ----- files (level_files.cpp) -----

  // Applies the path rules of docs/LEVELS.md ("Paths") to the string at `pointer`.
  ResolvedFile resolveFile(const OrderedJson& value, const std::string& pointer,
                           const std::string& kind,
                           const std::vector<std::string>& extensions) const;
  void addSourceFile(Level& level, const std::filesystem::path& file) const;
  // The index in level.textures of the texture at `pointer`, loading each file once.
  int32_t readTexture(const OrderedJson& value, const std::string& pointer, bool srgb,
                      Level& level);
  // A texture a glTF model brought, shared with an identical one already in the level.
  int32_t addModelTexture(scene::TextureDesc texture, const std::string& pointer, Level& level);

  // ----- what the sections leave for each other -----

  // Refuses a mesh that would take the level past the triangle limit, before it is built.
  void addTriangles(std::size_t triangles, const std::string& pointer);

  // Per mesh (parallel to Level::meshes): whether it is a glTF model, and the material the model
  // brought, if any, for entities that name no material of their own.
  struct MeshMaterialSource {
    bool isGltf = false;
    std::vector<GltfMaterial> gltfMaterials;  // the model's own, per mesh material
  };
  std::vector<MeshMaterialSource> meshMaterialSources;

 private:
  // The asset root: the first existing directory of options_.assetRoots, or by default the
  // "assets" directory beside the level's directory (levels/x.json -> assets/).
  std::optional<std::filesystem::path> assetRoot() const;
  std::string describeAssetRootCandidates() const;

  const LevelLoadOptions& options_;
  const std::filesystem::path levelDirectory_;
  std::map<IdKind, std::vector<std::string>> ids_;  // declared ids, in the order written
  std::size_t totalTriangles_ = 0;
  std::map<std::pair<std::filesystem::path, bool>, int32_t>
      textureIndices_;  // (file, srgb) -> texture
};

}  // namespace game::level_format
