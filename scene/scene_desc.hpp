#pragma once
// Plain descriptions that cross from the game into the renderer. No Vulkan here.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace scene {

struct Vertex {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  glm::vec2 uv{0.0f};     // texture coordinates; (0, 0) top-left of the image, as in glTF
  glm::vec4 color{1.0f};  // linear, multiplies the material's base colour (glTF COLOR_0)
  glm::vec2 uv1{0.0f};    // a second set (glTF TEXCOORD_1), for textures that ask for it
};

// A decoded texture, RGBA8, rows top to bottom.
struct TextureDesc {
  std::string name;  // file it came from, for messages and debug names
  uint32_t width = 0;
  uint32_t height = 0;
  bool srgb = true;  // colour textures: sRGB-encoded; normal maps: linear
  std::vector<uint8_t> rgba;
};

struct MeshData {
  std::string name;
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;  // three per triangle, counter-clockwise front faces
  // Per triangle, which of the mesh's own materials it has (a glTF model's primitives); empty
  // when one material covers the whole mesh.
  std::vector<uint32_t> triangleMaterials;
};

enum class MaterialKind : uint32_t {
  Diffuse = 0,  // Lambert + Blinn-Phong highlight
  Mirror = 1,   // perfect reflection times mirrorTint
  Glass = 2,    // transmittance glassTint per front face crossed, no refraction
};

// What a material's texture is for (glTF's texture slots); indexes MaterialDesc::textureMappings.
enum class TextureRole : uint32_t {
  BaseColor = 0,
  Normal = 1,
  MetallicRoughness = 2,
  Occlusion = 3,
  Emissive = 4,
};
constexpr uint32_t kTextureRoles = 5;

// Where a texture is sampled: which UV set, moved by glTF's KHR_texture_transform,
// uv' = offset + rotate(rotation) (scale * uv), rotation counter-clockwise in UV space.
struct TextureMapping {
  uint32_t uvSet = 0;  // 0: Vertex::uv, 1: Vertex::uv1
  glm::vec2 offset{0.0f};
  float rotationRadians = 0.0f;
  glm::vec2 scale{1.0f};
};

// Colours are linear (already converted from the sRGB the author wrote).
struct MaterialDesc {
  MaterialKind kind = MaterialKind::Diffuse;
  glm::vec3 baseColor{0.8f};  // diffuse albedo
  float specular = 0.0f;      // Blinn-Phong lobe weight in [0, 1]
  float roughness = 0.5f;     // (0, 1]; Blinn-Phong exponent 2/r^4 - 2, or GGX alpha = r^2
  // glTF's metallic-roughness model (GGX, Smith visibility, Schlick Fresnel) instead of
  // Blinn-Phong: F0 = mix(0.04, baseColor, metallic), diffuse baseColor (1 - metallic) / pi.
  bool metallicRoughness = false;
  float metallic = 0.0f;  // [0, 1]
  // glTF alphaMode MASK: a surface point whose alpha (the colour texture's alpha times `alpha`
  // times the vertex colour's) is below the cutoff is a hole for every ray. 0: opaque.
  float alphaCutoff = 0.0f;
  float alpha = 1.0f;  // the base colour factor's alpha
  // glTF alphaMode BLEND (kind Glass): a non-refracting tinted transparency whose tint at a
  // point is mix(white, base colour x texture x vertex colour, their alpha x `alpha`), for
  // light crossing either face; glassTint holds the tint of the factors alone.
  bool alphaBlend = false;
  glm::vec3 emissive{0.0f};    // emitted radiance, added unlit
  glm::vec3 mirrorTint{1.0f};  // Mirror: reflectance times tint, linear
  glm::vec3 glassTint{1.0f};   // Glass: linear transmittance per front face
  int32_t colorTexture = -1;   // index into SceneDesc::textures (sRGB), multiplies baseColor
  int32_t normalTexture = -1;  // index into SceneDesc::textures (linear, tangent space)
  float normalScale = 1.0f;    // scales the normal map's x and y (glTF normalTexture.scale)
  // glTF's metallicRoughnessTexture (linear; green multiplies roughness, blue metallic).
  int32_t metallicRoughnessTexture = -1;
  int32_t occlusionTexture = -1;  // linear; red darkens the ambient light by occlusionStrength
  float occlusionStrength = 1.0f;
  int32_t emissiveTexture = -1;                                 // sRGB, multiplies emissive
  std::array<TextureMapping, kTextureRoles> textureMappings{};  // by TextureRole
};

struct InstanceDesc {
  uint32_t mesh = 0;
  uint32_t material = 0;
  glm::mat4 objectToWorld{1.0f};
  bool castsShadow = true;
  // With castsShadow: it blocks only the shadow rays towards directional lights (a roof or dome
  // that keeps the sun out of an interior whose own lamps cannot reach past it).
  bool shadowsDirectionalOnly = false;
  // The player's figure: casts shadows and shows in mirrors, but camera rays from the eye and
  // the player's own exposure probes pass through it.
  bool playerBody = false;
  // With a mesh of several materials (MeshData::triangleMaterials): the scene material for each
  // of the mesh's own; empty: `material` everywhere.
  std::vector<uint32_t> meshMaterials;
};

enum class LightType : uint32_t {
  Point = 0,        // intensity: radiant intensity in W/sr (irradiance = I cos / d^2)
  Directional = 1,  // intensity: irradiance in W/m^2 on a surface facing the light
  Sphere = 2,       // intensity: radiance in W/(m^2 sr); radius
  Rectangle = 3,    // intensity: radiance; size, emits along direction
  Disk = 4,         // intensity: radiance; radius, emits along direction
};

struct LightDesc {
  LightType type = LightType::Point;
  glm::vec3 position{0.0f};                // point and area lights
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // directional: the way light travels; rectangle
                                           // and disk: the side they emit from
  glm::vec3 color{1.0f};                   // linear, multiplies intensity
  float intensity = 1.0f;
  float radius = 0.0f;                  // sphere and disk
  glm::vec2 size{0.0f};                 // rectangle: width, height
  float angularDiameterRadians = 0.0f;  // directional: 0 = hard shadows
  bool enabled = true;
};

struct EnvironmentDesc {
  glm::vec3 skyZenith{0.0f};   // linear radiance seen straight up
  glm::vec3 skyHorizon{0.0f};  // linear radiance seen at and below the horizon
  glm::vec3 ambient{0.0f};     // linear irradiance/pi added to every surface, unshadowed
};

struct SceneDesc {
  std::vector<MeshData> meshes;
  std::vector<MaterialDesc> materials;
  std::vector<TextureDesc> textures;
  std::vector<InstanceDesc> instances;
  std::vector<LightDesc> lights;
  EnvironmentDesc environment;
  uint32_t maxMirrorBounces = 4;  // [0, 31]
  bool lightViaMirrors = true;    // false: lights reach surfaces and sensors only directly
  // The level has exposure probes (lit goals, stealth): the pipeline gets the probe ray-gen.
  bool exposureProbes = false;
};

struct CameraDesc {
  glm::vec3 position{0.0f};
  float yawDegrees = 0.0f;    // 0 looks along -Z, positive turns left (towards -X)
  float pitchDegrees = 0.0f;  // positive looks up
  float verticalFovDegrees = 60.0f;
};

enum class Tonemap : uint32_t {
  Identity = 0,  // exposure, then clamp to [0, 1]: tests compute expected bytes from this
  Aces = 1,      // Narkowicz's fit of the ACES filmic curve, after exposure
};

struct FrameDesc {
  CameraDesc camera;
  float exposure = 1.0f;  // linear multiplier applied before the tonemap
  Tonemap tonemap = Tonemap::Aces;
  uint32_t frameIndex = 0;  // seeds the sample sequences; advance it every frame
  // Soft shadows: forget the denoiser's history (a camera cut or teleport).
  bool resetHistory = false;
  // Soft shadows: average raw samples over frames with no filtering (ground truth).
  bool referenceAccumulation = false;
  // The camera rays' offset from the pixel centres (pixels), for supersampled references by a
  // renderer without temporal upscaling (one with it follows its own sequence).
  glm::vec2 jitter{0.0f};
};

}  // namespace scene
