#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#include "temporal_upscale.glsl"

// The resolve on GPUs (temporal_upscale.glsl): a compute shader storing the picture and the
// history.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = BINDING_UPSCALE_HISTORY_NEXT, rgba32ui) uniform writeonly uimage2D
    historyNextImage;
layout(set = 0, binding = BINDING_DISPLAY_IMAGE, rgba8) uniform writeonly image2D displayImage;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(frame.upscale.zw)))) return;
  vec4 display;
  uvec4 historyNext;
  resolvePixel(pixel, display, historyNext);
  imageStore(historyNextImage, pixel, historyNext);
  imageStore(displayImage, pixel, display);
}
