#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#ifndef SOFT_SHADOWS
#define SOFT_SHADOWS 0
#endif
#if SOFT_SHADOWS
#define DENOISER_BINDINGS
#endif
#include "frame_bindings.glsl"
#include "color.glsl"

// Linear HDR (+ soft light x denoised visibility) -> exposure -> tonemap -> sRGB bytes.
layout(local_size_x = 8, local_size_y = 8) in;

#if SOFT_SHADOWS
vec3 denoisedVisibility(ivec2 pixel) {
  // The filter's last iteration wrote A after an even number of iterations, else B.
  return (frame.denoise.z % 2u) == 0u ? imageLoad(filterAImage, pixel).rgb
                                      : imageLoad(filterBImage, pixel).rgb;
}

// The denoised visibility where this frame's camera ray went through the pixel. A denoised
// pixel averages samples from all over it (ray-gen: chooseSoftSamples), so a temporally
// upscaled picture would show it as one block; interpolated between the pixel centres at the
// ray's offset, and only from pixels of the same instance, the upscaler sees a shadow's edge
// move within the pixel and resolves it as it resolves a silhouette. Without an offset (no
// upscaling), and in reference accumulation (each pixel's own average is the truth there), this
// is the pixel's own value.
vec3 visibilityAtRay(ivec2 pixel) {
  if (frame.upscale.xy == vec2(0.0) || frame.denoise.y != 0u) return denoisedVisibility(pixel);
  vec2 position = vec2(pixel) + frame.upscale.xy;
  ivec2 base = ivec2(floor(position));
  vec2 f = position - vec2(base);
  uint instance = imageLoad(surfaceImage, pixel).z;
  vec3 sum = vec3(0.0);
  float weightSum = 0.0;
  for (int tap = 0; tap < 4; ++tap) {
    ivec2 at = base + ivec2(tap & 1, tap >> 1);
    float weight = ((tap & 1) != 0 ? f.x : 1.0 - f.x) * ((tap >> 1) != 0 ? f.y : 1.0 - f.y);
    if (weight <= 0.0 || !all(lessThan(uvec2(at), frame.sizeFrameLights.xy))) continue;
    if (at != pixel && imageLoad(surfaceImage, at).z != instance) continue;
    sum += weight * denoisedVisibility(at);
    weightSum += weight;
  }
  return weightSum > 0.0 ? sum / weightSum : denoisedVisibility(pixel);
}
#endif

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= int(frame.sizeFrameLights.x) || pixel.y >= int(frame.sizeFrameLights.y)) return;
  vec4 traced = tracedRadiance[pixelIndex(pixel)];
  vec3 radiance = traced.rgb;
#if SOFT_SHADOWS
  radiance += softLights[pixelIndex(pixel)].rgb * visibilityAtRay(pixel);
#endif
  radiance *= frame.exposureTonemap.x;
  // Saturate, never overflow: both curves are flat at 1 long before 1e4 (ACES from 7.3), and
  // ACES squares its input (infinite past 1.8e19, and infinity over infinity is NaN).
  radiance = clamp(mix(radiance, vec3(0.0), isnan(radiance)), 0.0, 1.0e4);
  vec3 display = uint(frame.exposureTonemap.y) == TONEMAP_ACES ? acesFilmic(radiance)
                                                                : clamp(radiance, 0.0, 1.0);
  // Quantize here with round-to-nearest so the UNORM store is exact on every driver.
  vec3 encoded = round(clamp(linearToSrgb(display), 0.0, 1.0) * 255.0) / 255.0;
  // Alpha: ray-gen's (1 unless temporal upscaling, whose resolve reads 0 as "shows something
  // that moved").
  imageStore(outputImage, pixel, vec4(encoded, traced.a));
}
