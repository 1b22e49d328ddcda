// Shared by the denoiser passes.
#ifndef DENOISER_GROUP_SIZE  // the renderer defines it (Denoiser::kGpuGroupSize, kCpuGroupSize)
#define DENOISER_GROUP_SIZE 16
#endif
// A work-group covers DENOISER_GROUP_SIZE x DENOISER_GROUP_SIZE pixels (a tile of the a-trous
// iterations' list); the temporal pass may give each invocation several pixels of a column.
#ifndef DENOISER_GROUP_ROWS
#define DENOISER_GROUP_ROWS DENOISER_GROUP_SIZE
#endif
layout(local_size_x = DENOISER_GROUP_SIZE, local_size_y = DENOISER_GROUP_ROWS) in;

// Push constants of the passes (render::DenoiserPass).
layout(push_constant) uniform Pass {
  int stepSize;      // a-trous: the taps' spacing
  int readFromA;     // a-trous: 1: A -> B, 0: B -> A
  int writeHistory;  // a-trous: the first iteration's output is the next frame's history
  // This frame's stamp: the temporal pass writes it into filterTilesImage for each work-group
  // that holds a pixel with variance, and lists that work-group once for the a-trous iterations
  // (the other work-groups they leave alone).
  uint tileStamp;
} pass;

// The tile grid's width: one texel of filterTilesImage per work-group. The temporal pass lists
// work-groups in rows of this length, and the a-trous iterations read them back so.
uint tileRowLength() { return uint(imageSize(filterTilesImage).x); }

// Below this variance the temporal pass writes its output to both filter images: it may read
// back as 0 from a half float (whichever rounding, denormals flushed or not), and an a-trous
// iteration neither changes nor stores a pixel of variance 0.
const float UNFILTERED_VARIANCE_BOUND = 1.0e-4;

float luminance(vec3 rgb) { return dot(rgb, vec3(0.2126, 0.7152, 0.0722)); }

bool isFinite(vec3 v) { return !any(isnan(v)) && !any(isinf(v)); }

bool insideImage(ivec2 pixel) {
  return all(greaterThanEqual(pixel, ivec2(0))) &&
         all(lessThan(pixel, ivec2(frame.sizeFrameLights.xy)));
}

// The history images hold the previous full frame's picture, whose size differs from this
// frame's after a change of the render scale.
bool insidePreviousImage(ivec2 pixel) {
  return all(greaterThanEqual(pixel, ivec2(0))) &&
         all(lessThan(pixel, ivec2(frame.previousSize.xy)));
}

// The raw visibility estimate (rgb; ray-gen writes it finite, in [0, 1]: writeDenoiserInputs)
// and the width of the penumbra there in pixels (a; below 0 where no sample met a caster).
vec4 rawSample(ivec2 pixel) {
  vec4 value = imageLoad(visibilityRawImage, pixel);
  return vec4(value.rgb, isnan(value.a) ? -1.0 : value.a);
}
