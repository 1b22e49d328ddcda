#include "game/gltf_material.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>

#include "game/gltf_checks.hpp"
#include "game/texture_file.hpp"

namespace game::gltf {

namespace {

namespace fs = std::filesystem;

// Maps glTF's metallic-roughness material onto ours and decodes the textures it uses.
class MaterialMapper {
 public:
  MaterialMapper(const tinygltf::Model& model, const fs::path& file,
                 std::vector<std::string>& warnings)
      : model_(model), file_(file), warnings_(warnings) {}

  GltfMaterial map(int materialIndex) {
    const tinygltf::Material& material = model_.materials[static_cast<std::size_t>(materialIndex)];
    label_ = material.name.empty() ? "material " + std::to_string(materialIndex)
                                   : "material \"" + material.name + "\"";
    const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
    GltfMaterial result;
    result.name =
        material.name.empty() ? "material " + std::to_string(materialIndex) : material.name;
    result.baseColor = factors<3>(pbr.baseColorFactor, "baseColorFactor", result.baseColor);
    result.roughness = factor(pbr.roughnessFactor, "roughnessFactor");
    result.metallic = factor(pbr.metallicFactor, "metallicFactor");
    if (pbr.baseColorFactor.size() == 4)
      result.alpha = factor(pbr.baseColorFactor[3], "baseColorFactor");
    if (material.alphaMode == "MASK")
      result.alphaCutoff = factor(material.alphaCutoff, "alphaCutoff");
    result.emissive = factors<3>(material.emissiveFactor, "emissiveFactor", result.emissive);
    if (const auto strength = material.extensions.find("KHR_materials_emissive_strength");
        strength != material.extensions.end()) {
      const tinygltf::Value& value = strength->second.Get("emissiveStrength");
      if (value.IsNumber()) {
        const double scale = value.GetNumberAsDouble();
        if (!(std::isfinite(scale) && scale >= 0.0 && scale <= 1e6)) {
          fail(file_, label_ +
                          " KHR_materials_emissive_strength: emissiveStrength must be a "
                          "number in [0, 1e6], got " +
                          std::to_string(scale));
        }
        result.emissive *= float(scale);
      }
    }
    result.alphaBlend = material.alphaMode == "BLEND";
    if (!std::isfinite(material.normalTexture.scale) ||
        std::abs(material.normalTexture.scale) > 1e3) {
      fail(file_, label_ + " normalTexture scale must be a number in [-1000, 1000]");
    }
    result.normalScale = float(material.normalTexture.scale);
    result.occlusionStrength =
        factor(material.occlusionTexture.strength, "occlusionTexture strength");
    using scene::TextureRole;
    result.colorTexture = texture(pbr.baseColorTexture, TextureRole::BaseColor, "baseColorTexture",
                                  /*srgb=*/true, result);
    result.normalTexture = texture(material.normalTexture, TextureRole::Normal, "normalTexture",
                                   /*srgb=*/false, result);
    result.metallicRoughnessTexture =
        texture(pbr.metallicRoughnessTexture, TextureRole::MetallicRoughness,
                "metallicRoughnessTexture", /*srgb=*/false, result);
    result.occlusionTexture = texture(material.occlusionTexture, TextureRole::Occlusion,
                                      "occlusionTexture", /*srgb=*/false, result);
    result.emissiveTexture = texture(material.emissiveTexture, TextureRole::Emissive,
                                     "emissiveTexture", /*srgb=*/true, result);
    // Exporters write BLEND for surfaces nothing makes transparent (the Khronos sample
    // BoxVertexColors does); as glass such a surface would be a filter of its colour, black
    // where two faces of different colours overlap.
    if (result.alphaBlend && result.alpha >= 1.0f && !result.colorTexture) {
      warnings_.push_back(file_.string() + ": " + label_ +
                          " has alphaMode BLEND with an opaque base colour and no base colour "
                          "texture: drawn opaque (vertex colours' alpha is not read)");
      result.alphaBlend = false;
    }
    return result;
  }

 private:
  // glTF factors lie in [0, 1]; values outside are clamped rather than refused, as viewers do.
  float factor(double value, const std::string& name) const {
    if (!std::isfinite(value)) fail(file_, label_ + " " + name + " is not a finite number");
    return static_cast<float>(std::clamp(value, 0.0, 1.0));
  }

  template <int N>
  glm::vec<N, float> factors(const std::vector<double>& values, const std::string& name,
                             const glm::vec<N, float>& fallback) const {
    if (values.empty()) return fallback;
    if (values.size() < N) fail(file_, label_ + " " + name + " has too few components");
    glm::vec<N, float> result;
    for (int i = 0; i < N; ++i) result[i] = factor(values[static_cast<std::size_t>(i)], name);
    return result;
  }

  // The texture `info` names (none when it names none) and, in result.textureMappings, where
  // it is sampled.
  template <typename TextureInfo>
  std::optional<scene::TextureDesc> texture(const TextureInfo& info, scene::TextureRole role,
                                            const std::string& roleName, bool srgb,
                                            GltfMaterial& result) {
    if (info.index < 0) return std::nullopt;
    const std::string where = label_ + " " + roleName;
    scene::TextureMapping& mapping = result.textureMappings[static_cast<std::size_t>(role)];
    int texCoord = info.texCoord;
    if (const auto transform = info.extensions.find("KHR_texture_transform");
        transform != info.extensions.end()) {
      texCoord = textureTransform(transform->second, where, texCoord, mapping);
    }
    if (texCoord < 0 || texCoord > 1) {
      warnings_.push_back(file_.string() + ": " + where + " uses TEXCOORD_" +
                          std::to_string(texCoord) +
                          "; only TEXCOORD_0 and TEXCOORD_1 are read, so TEXCOORD_0 is used");
      texCoord = 0;
    }
    mapping.uvSet = static_cast<uint32_t>(texCoord);
    return decoded(info.index, where, srgb);
  }

  // Reads KHR_texture_transform into `mapping`; returns the UV set it names (or `texCoord`).
  int textureTransform(const tinygltf::Value& transform, const std::string& where, int texCoord,
                       scene::TextureMapping& mapping) const {
    const std::string label = where + " KHR_texture_transform";
    if (!transform.IsObject()) fail(file_, label + " must be an object");
    auto pair = [&](const char* key, glm::vec2 fallback) {
      if (!transform.Has(key)) return fallback;
      const tinygltf::Value& value = transform.Get(key);
      if (!value.IsArray() || value.ArrayLen() != 2 || !finiteNumber(value.Get(0)) ||
          !finiteNumber(value.Get(1))) {
        fail(file_, label + " " + key + " must be an array of 2 numbers in [-1e6, 1e6]");
      }
      return glm::vec2(float(value.Get(0).GetNumberAsDouble()),
                       float(value.Get(1).GetNumberAsDouble()));
    };
    mapping.offset = pair("offset", glm::vec2(0.0f));
    mapping.scale = pair("scale", glm::vec2(1.0f));
    if (transform.Has("rotation")) {
      if (!finiteNumber(transform.Get("rotation")))
        fail(file_, label + " rotation must be a number in [-1e6, 1e6] (radians)");
      mapping.rotationRadians = float(transform.Get("rotation").GetNumberAsDouble());
    }
    if (transform.Has("texCoord")) {
      const tinygltf::Value& value = transform.Get("texCoord");
      if (!value.IsInt() || value.GetNumberAsInt() < 0)
        fail(file_, label + " texCoord must be a whole number >= 0");
      texCoord = value.GetNumberAsInt();
    }
    return texCoord;
  }

  static bool finiteNumber(const tinygltf::Value& value) {
    return value.IsNumber() && std::isfinite(value.GetNumberAsDouble()) &&
           std::abs(value.GetNumberAsDouble()) <= 1e6;
  }

  scene::TextureDesc decoded(int textureIndex, const std::string& where, bool srgb) {
    if (!validIndex(textureIndex, model_.textures)) {
      fail(file_,
           where + " refers to texture " + std::to_string(textureIndex) + ", which does not exist");
    }
    const int imageIndex = model_.textures[static_cast<std::size_t>(textureIndex)].source;
    if (!validIndex(imageIndex, model_.images)) {
      fail(file_, where + " uses texture " + std::to_string(textureIndex) +
                      ", which has no PNG or JPEG image");
    }
    const tinygltf::Image& image = model_.images[static_cast<std::size_t>(imageIndex)];
    const std::string imageLabel =
        "image " + std::to_string(imageIndex) + (image.uri.empty() ? "" : " \"" + image.uri + "\"");
    // An external image is named by its path; an embedded one by the model and its index.
    const std::string name = image.uri.empty()
                                 ? file_.string() + " image " + std::to_string(imageIndex)
                                 : (file_.parent_path() / image.uri).lexically_normal().string();
    const std::span<const uint8_t> bytes = encodedBytes(image, where + " " + imageLabel);
    try {
      return decodeTexture(bytes, name, srgb);
    } catch (const LevelError& error) {
      fail(file_, where + ": " + error.what());
    }
  }

  std::span<const uint8_t> encodedBytes(const tinygltf::Image& image,
                                        const std::string& label) const {
    if (image.bufferView < 0) {
      if (image.image.empty()) fail(file_, label + " was not found or could not be read");
      return image.image;
    }
    if (!validIndex(image.bufferView, model_.bufferViews)) {
      fail(file_, label + " has no valid buffer view");
    }
    const tinygltf::BufferView& view =
        model_.bufferViews[static_cast<std::size_t>(image.bufferView)];
    if (!validIndex(view.buffer, model_.buffers)) {
      fail(file_, label + " uses a buffer view without a valid buffer");
    }
    const std::vector<unsigned char>& buffer =
        model_.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset) {
      fail(file_, label + " reads past the end of its buffer");
    }
    return {buffer.data() + view.byteOffset, view.byteLength};
  }

  const tinygltf::Model& model_;
  const fs::path& file_;
  std::vector<std::string>& warnings_;
  std::string label_;  // names the material in messages
};

}  // namespace

GltfMaterial mapMaterial(const tinygltf::Model& model, const fs::path& file, int materialIndex,
                         std::vector<std::string>& warnings) {
  return MaterialMapper(model, file, warnings).map(materialIndex);
}

}  // namespace game::gltf
