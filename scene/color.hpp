#pragma once
// sRGB <-> linear conversions (IEC 61966-2-1). Authors write sRGB; the renderer works in linear.
#include <cmath>

#include <glm/glm.hpp>

namespace scene {

// The exact sRGB EOTF: encoded value in [0, 1] -> linear.
inline float srgbToLinear(float encoded) {
  const double c = encoded;
  return static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

// The exact sRGB OETF: linear value in [0, 1] -> encoded.
inline float linearToSrgb(float linear) {
  const double u = linear;
  return static_cast<float>(u < 0.0031308 ? 12.92 * u : 1.055 * std::pow(u, 1.0 / 2.4) - 0.055);
}

inline glm::vec3 srgbToLinear(const glm::vec3& encoded) {
  return {srgbToLinear(encoded.r), srgbToLinear(encoded.g), srgbToLinear(encoded.b)};
}

inline glm::vec3 linearToSrgb(const glm::vec3& linear) {
  return {linearToSrgb(linear.r), linearToSrgb(linear.g), linearToSrgb(linear.b)};
}

}  // namespace scene
