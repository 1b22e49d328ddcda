#pragma once
// Builds small glTF documents in tests: one binary buffer (embedded as a data URI), one buffer
// view per accessor.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <stb/stb_image_write.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "temp_dir_fixture.hpp"

namespace test {

inline constexpr int kFloat = 5126, kUnsignedByte = 5121, kUnsignedShort = 5123;

inline std::string base64(const std::string& bytes) {
  static const char* const alphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string encoded;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t group = static_cast<uint32_t>(static_cast<unsigned char>(bytes[i])) << 16;
    if (i + 1 < bytes.size()) group |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) group |= static_cast<unsigned char>(bytes[i + 2]);
    encoded += alphabet[(group >> 18) & 63];
    encoded += alphabet[(group >> 12) & 63];
    encoded += i + 1 < bytes.size() ? alphabet[(group >> 6) & 63] : '=';
    encoded += i + 2 < bytes.size() ? alphabet[group & 63] : '=';
  }
  return encoded;
}

// `pixels` (rows top to bottom, `channels` bytes each) encoded as a PNG.
inline std::string pngBytes(int width, int height, int channels, const uint8_t* pixels) {
  std::string png;
  stbi_write_png_to_func(
      [](void* context, void* data, int bytes) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                   static_cast<std::size_t>(bytes));
      },
      &png, width, height, channels, pixels, width * channels);
  return png;
}

template <typename T>
inline std::string packed(const std::vector<T>& values) {
  std::string bytes(values.size() * sizeof(T), '\0');
  std::memcpy(bytes.data(), values.data(), bytes.size());  // little-endian, as glTF
  return bytes;
}

inline std::string packedVec3s(const std::vector<glm::vec3>& points) {
  std::vector<float> floats;
  for (const glm::vec3& p : points) floats.insert(floats.end(), {p.x, p.y, p.z});
  return packed(floats);
}

// Builds a glTF document with one binary buffer, one buffer view per accessor.
struct GltfBuilder {
  nlohmann::json document = {{"asset", {{"version", "2.0"}}},
                             {"bufferViews", nlohmann::json::array()},
                             {"accessors", nlohmann::json::array()}};
  std::string buffer;

  int addView(const std::string& bytes) {
    buffer.resize((buffer.size() + 3) / 4 * 4, '\0');  // keep every view 4-byte aligned
    document["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", buffer.size()}, {"byteLength", bytes.size()}});
    buffer += bytes;
    return static_cast<int>(document["bufferViews"].size()) - 1;
  }

  int addAccessor(const std::string& bytes, int componentType, std::size_t count,
                  const std::string& type, bool normalized = false) {
    nlohmann::json accessor = {{"bufferView", addView(bytes)},
                               {"componentType", componentType},
                               {"count", count},
                               {"type", type}};
    if (normalized) accessor["normalized"] = true;
    document["accessors"].push_back(accessor);
    return static_cast<int>(document["accessors"].size()) - 1;
  }

  // A primitive with positions (and u16 indices unless `indices` is empty); returns it so
  // tests can add attributes or a material.
  nlohmann::json primitive(const std::vector<glm::vec3>& positions,
                           const std::vector<uint16_t>& indices = {}) {
    nlohmann::json result = {
        {"attributes",
         {{"POSITION", addAccessor(packedVec3s(positions), kFloat, positions.size(), "VEC3")}}}};
    if (!indices.empty()) {
      result["indices"] = addAccessor(packed(indices), kUnsignedShort, indices.size(), "SCALAR");
    }
    return result;
  }

  // A vector, not json: a braced single json would be copied rather than wrapped in an array.
  int addMesh(const std::string& name, const std::vector<nlohmann::json>& primitives) {
    document["meshes"].push_back({{"name", name}, {"primitives", primitives}});
    return static_cast<int>(document["meshes"].size()) - 1;
  }

  // Writes `path` with the buffer embedded as a data URI.
  void write(const std::filesystem::path& path) {
    document["buffers"] = {{{"byteLength", buffer.size()},
                            {"uri", "data:application/octet-stream;base64," + base64(buffer)}}};
    writeFile(path, document.dump(1));
  }
};

}  // namespace test
