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

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= int(frame.sizeFrameLights.x) || pixel.y >= int(frame.sizeFrameLights.y)) return;
  vec3 radiance = imageLoad(hdrImage, pixel).rgb;
#if SOFT_SHADOWS
  // The filter's last iteration wrote A after an even number of iterations, else B.
  vec3 visibility = (frame.denoise.z % 2u) == 0u ? imageLoad(filterAImage, pixel).rgb
                                                 : imageLoad(filterBImage, pixel).rgb;
  radiance += imageLoad(softLightImage, pixel).rgb * visibility;
#endif
  radiance *= frame.exposureTonemap.x;
  // Saturate, never overflow: both curves are flat at 1 long before 1e4 (ACES from 7.3), and
  // ACES squares its input (infinite past 1.8e19, and infinity over infinity is NaN).
  radiance = clamp(mix(radiance, vec3(0.0), isnan(radiance)), 0.0, 1.0e4);
  vec3 display = uint(frame.exposureTonemap.y) == TONEMAP_ACES ? acesFilmic(radiance)
                                                                : clamp(radiance, 0.0, 1.0);
  // Quantize here with round-to-nearest so the UNORM store is exact on every driver.
  vec3 encoded = round(clamp(linearToSrgb(display), 0.0, 1.0) * 255.0) / 255.0;
  imageStore(outputImage, pixel, vec4(encoded, 1.0));
}
