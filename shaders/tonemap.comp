#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#include "frame_bindings.glsl"
#include "color.glsl"

// Linear HDR -> exposure -> tonemap -> sRGB bytes.
layout(local_size_x = 8, local_size_y = 8) in;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= int(frame.sizeFrameLights.x) || pixel.y >= int(frame.sizeFrameLights.y)) return;
  vec3 radiance = imageLoad(hdrImage, pixel).rgb * frame.exposureTonemap.x;
  vec3 display = uint(frame.exposureTonemap.y) == TONEMAP_ACES ? acesFilmic(radiance)
                                                                : clamp(radiance, 0.0, 1.0);
  // Quantize here with round-to-nearest so the UNORM store is exact on every driver.
  vec3 encoded = round(clamp(linearToSrgb(display), 0.0, 1.0) * 255.0) / 255.0;
  imageStore(outputImage, pixel, vec4(encoded, 1.0));
}
