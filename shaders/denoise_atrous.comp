#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#define DENOISER_BINDINGS
#include "frame_bindings.glsl"
#include "denoise_common.glsl"

// One edge-avoiding a-trous iteration (3x3 taps spaced `stepSize` apart), stopped by depth,
// normal, instance and visibility differences scaled by the estimated variance. Weighted
// differences from the centre keep uniform regions exactly as they are (fully lit stays 1).

const float YOUNG_HISTORY_LENGTH = 4.0;
// An iteration filters a pixel fully while its tap spacing is at most this many times the
// penumbra's width there, and less in proportion beyond (bench-quality at 320x180, as a hard
// cut: 1 left 02's first frame 23 % worse than without the limit, 2 under 4 %, with 07's
// first frame 28 % better). Gradual, so that a slightly different blocker distance (a level
// far from the origin) changes the picture slightly.
const float PENUMBRA_STEP_SCALE = 2.0;

vec4 loadFiltered(ivec2 pixel) {
  return pass.readFromA != 0 ? imageLoad(filterAImage, pixel) : imageLoad(filterBImage, pixel);
}

void main() {
  // Dispatched for the work-groups the temporal pass listed: one where no pixel has variance
  // stays as that pass left it, in both filter images.
  uint entry = gl_WorkGroupID.y * tileRowLength() + gl_WorkGroupID.x;
  if (entry >= listedTiles) return;  // the last row's rest
  uint tile = filterTiles[entry];
  ivec2 pixel = ivec2(uvec2(tile & 0xffffu, tile >> 16) * gl_WorkGroupSize.xy +
                      gl_LocalInvocationID.xy);
  if (!insideImage(pixel)) return;
  vec4 centre = loadFiltered(pixel);
  vec4 result = centre;
  // A pixel whose estimate has no variance (fully lit or fully shadowed, every sample alike)
  // keeps its value: with a luminance scale of 1e-4 every differing tap weighs nothing. Only
  // the penumbrae are filtered (work-groups without one are not dispatched at all). Its
  // surface is not even read: within a listed work-group most pixels may be such, and on
  // lavapipe every image read counts (on the H100 it makes no measurable difference).
  vec4 surface = vec4(0.0, 0.0, 0.0, -1.0);
  uint instance = 0u;
  vec4 moments = vec4(0.0);
  if (centre.a > 0.0) {
    uvec4 packedSurface = imageLoad(surfaceImage, pixel);
    surface = unpackSurface(packedSurface.xy);
    instance = packedSurface.z;
    moments = imageLoad(momentsNextImage, pixel);
  }
  // No blur wider than the penumbra where its width is known (w, pixels): a nearly hard
  // shadow's edge is sharp, and samples across it are not noise to average away.
  float withinPenumbra =
      moments.w >= 0.0
          ? clamp(PENUMBRA_STEP_SCALE * moments.w / float(pass.stepSize), 0.0, 1.0)
          : 1.0;
  if (surface.w >= 0.0 && centre.a > 0.0 && withinPenumbra > 0.0) {
    const float kernel[3] = float[3](0.25, 0.5, 0.25);
    float centreLuminance = luminance(centre.rgb);
    float luminanceScale = 4.0 * sqrt(max(centre.a, 0.0)) + 1e-4;
    // Relative to the distance, so the filter behaves the same at every scale of the level.
    float depthScale = max(0.02 * surface.w * float(pass.stepSize), 1e-30);
    float weightSum = kernel[1] * kernel[1];
    vec3 differenceSum = vec3(0.0);
    float varianceSum = weightSum * weightSum * centre.a;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0) continue;
        ivec2 tap = pixel + ivec2(dx, dy) * pass.stepSize;
        if (!insideImage(tap)) continue;
        uvec4 packedTap = imageLoad(surfaceImage, tap);
        if (packedTap.z != instance) continue;
        vec4 tapSurface = unpackSurface(packedTap.xy);
        vec4 value = loadFiltered(tap);
        float weight = kernel[dx + 1] * kernel[dy + 1] *
                       exp(-abs(tapSurface.w - surface.w) / depthScale) *
                       pow(max(dot(tapSurface.xyz, surface.xyz), 0.0), 64.0) *
                       exp(-abs(luminance(value.rgb) - centreLuminance) / luminanceScale);
        differenceSum += weight * (value.rgb - centre.rgb);
        weightSum += weight;
        varianceSum += weight * weight * value.a;
      }
    }
    result = vec4(clamp(centre.rgb + withinPenumbra * differenceSum / weightSum, 0.0, 1.0),
                  mix(centre.a, varianceSum / (weightSum * weightSum), withinPenumbra));
  }
  if (centre.a == 0.0) return;  // kept its value, which both images hold
  if (pass.readFromA != 0) {
    imageStore(filterBImage, pixel, result);
  } else {
    imageStore(filterAImage, pixel, result);
  }
  // While the history is young the first iteration's output becomes the next frame's history
  // (steadier early frames). Past that, feeding blurred values back would compound the blur
  // every frame into a bias the average never loses (measured with bench-quality: 32 static
  // frames, visibility RMSE 0.0095 with the feedback, 0.0050 without), so the temporal
  // pass's own integration, already stored there, is kept.
  // A pixel without variance kept its value, which the history already holds.
  if (pass.writeHistory != 0 && centre.a > 0.0 && moments.z < YOUNG_HISTORY_LENGTH)
    imageStore(historyNextImage, pixel, vec4(result.rgb, moments.z));
}
