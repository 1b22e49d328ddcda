#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_vote : require
#include "shared_types.h"
#define DENOISER_BINDINGS
#include "frame_bindings.glsl"
#include "denoise_common.glsl"

// Temporal pass: reproject last frame's history, reject it where the surface changed (depth,
// normal, instance), clamp it to the range of this frame's 5x5 neighbourhood (below), and blend
// in this frame's sample; also keeps luminance moments for the variance the spatial filter
// steers by.
// In reference mode it is a plain running average with no clamping and no cap.

const float MAX_HISTORY_LENGTH = float(DENOISER_MAX_HISTORY);
const float MIN_MOVING_HISTORY = 4.0;  // the fewest frames a moving view averages
// The history is clamped to the range of this frame's samples in a 5x5 neighbourhood, widened
// by a margin: one-sample visibility is 0 or 1, so in a penumbra a smaller window is often
// uniform by chance and a clamp to it would crush the history (bias that never converges);
// where every sample agrees (a shadow has just left or arrived) the clamp still acts at once.
const int NEIGHBOURHOOD_RADIUS = 2;
const float CLAMP_MARGIN = 0.1;

const float OUTSIDE_IMAGE = -1.0;  // a neighbour's sample outside the image
const float MOTION_GRID = 256.0;    // the reprojection rounds to 1/256 pixel

#ifndef NEIGHBOURHOOD_TILE  // the renderer defines it: 1 on GPUs, 0 on CPU drivers
#define NEIGHBOURHOOD_TILE 0
#endif

#if NEIGHBOURHOOD_TILE
// The work-group's raw samples and the margin its neighbourhoods reach, loaded once into
// shared memory: each sample is read by 25 pixels (on the H100 at 3840x2160 the 5x5 image
// reads were a third of the denoiser's time). On lavapipe the work-group barrier costs more
// than the reads it saves, so the CPU build reads each neighbour from the image.
const ivec2 TILE_SIZE = ivec2(gl_WorkGroupSize.xy) + 2 * NEIGHBOURHOOD_RADIUS;
const int TILE_SAMPLES = TILE_SIZE.x * TILE_SIZE.y;
shared vec4 tileSamples[TILE_SAMPLES];

void loadTile() {
  ivec2 tileOrigin = ivec2(gl_WorkGroupID.xy * gl_WorkGroupSize.xy) - NEIGHBOURHOOD_RADIUS;
  uint groupInvocations = gl_WorkGroupSize.x * gl_WorkGroupSize.y;
  for (uint i = gl_LocalInvocationIndex; i < uint(TILE_SAMPLES); i += groupInvocations) {
    ivec2 at = tileOrigin + ivec2(int(i) % TILE_SIZE.x, int(i) / TILE_SIZE.x);
    tileSamples[i] = insideImage(at) ? rawSample(at) : vec4(OUTSIDE_IMAGE);
  }
}

vec4 neighbourSample(ivec2 offset) {
  ivec2 at = ivec2(gl_LocalInvocationID.xy) + NEIGHBOURHOOD_RADIUS + offset;
  return tileSamples[at.y * TILE_SIZE.x + at.x];
}
#else
// Whether the pixel's whole neighbourhood is inside the picture (most pixels): then its reads
// skip the test (on lavapipe the 25 neighbour reads are half of the denoiser's time).
bool neighbourhoodInside = false;

vec4 neighbourSample(ivec2 offset) {
  ivec2 at = ivec2(gl_GlobalInvocationID.xy) + offset;
  if (neighbourhoodInside) return rawSample(at);
  return insideImage(at) ? rawSample(at) : vec4(OUTSIDE_IMAGE);
}
#endif

void main() {
#if NEIGHBOURHOOD_TILE
  loadTile();
  barrier();  // every invocation reaches it: the ones past the image's edge return after
#endif
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (!insideImage(pixel)) return;
#if !NEIGHBOURHOOD_TILE
  neighbourhoodInside =
      all(greaterThanEqual(pixel, ivec2(NEIGHBOURHOOD_RADIUS))) &&
      all(lessThan(pixel + NEIGHBOURHOOD_RADIUS, ivec2(frame.sizeFrameLights.xy)));
#endif
  bool reset = frame.denoise.x != 0u;
  bool reference = frame.denoise.y != 0u;
  vec3 current = neighbourSample(ivec2(0)).rgb;
  vec4 surface = unpackSurface(imageLoad(surfaceImage, pixel).xy);
  uint instance = imageLoad(instanceImage, pixel).x;

  vec3 sum = vec3(0.0), sumSquares = vec3(0.0);
  vec3 low = vec3(1.0), high = vec3(0.0);
  float count = 0.0;
  // The penumbra's width here: the mean over the neighbourhood's samples that met a caster
  // (a sample that reached the light says nothing of it).
  float penumbraSum = 0.0, penumbraSamples = 0.0;
  for (int dy = -NEIGHBOURHOOD_RADIUS; dy <= NEIGHBOURHOOD_RADIUS; ++dy) {
    for (int dx = -NEIGHBOURHOOD_RADIUS; dx <= NEIGHBOURHOOD_RADIUS; ++dx) {
      vec4 sampled = neighbourSample(ivec2(dx, dy));
      if (sampled.x == OUTSIDE_IMAGE) continue;
      if (sampled.a >= 0.0) {
        penumbraSum += sampled.a;
        penumbraSamples += 1.0;
      }
      vec3 value = sampled.rgb;
      sum += value;
      sumSquares += value * value;
      low = min(low, value);
      high = max(high, value);
      count += 1.0;
    }
  }
  vec3 mean = sum / count;
  vec3 sigma = sqrt(max(sumSquares / count - mean * mean, vec3(0.0)));

  vec3 history = current;
  vec2 moments = vec2(luminance(current), luminance(current) * luminance(current));
  float historyLength = 0.0;
  float historyCap = MAX_HISTORY_LENGTH;
  vec3 motion = unpackMotion(imageLoad(motionImage, pixel).xy);
  if (!reset && surface.w >= 0.0 && motion.z >= 0.0) {
    // On a grid of 1/256 pixel: a still view's motion, rounding left over from projecting the
    // pixel's point back, becomes exactly 0, and the three taps of weight 0 are not read.
    vec2 previous =
        reference ? vec2(pixel) : vec2(pixel) + round(motion.xy * MOTION_GRID) / MOTION_GRID;
    float expectedDistance = reference ? surface.w : motion.z;
    ivec2 base = ivec2(floor(previous));
    vec2 f = previous - vec2(base);
    vec3 historySum = vec3(0.0);
    vec3 momentsSum = vec3(0.0);
    float weightSum = 0.0;
    for (int j = 0; j <= 1; ++j) {
      for (int i = 0; i <= 1; ++i) {
        ivec2 tap = base + ivec2(i, j);
        if (!insidePreviousImage(tap)) continue;
        float weight = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
        if (weight <= 0.0) continue;
        if (imageLoad(instancePreviousImage, tap).x != instance) continue;
        if (!historyMatches(imageLoad(surfacePreviousImage, tap).xy, expectedDistance,
                            surface.xyz))
          continue;
        vec4 tapHistory = imageLoad(historyImage, tap);  // the estimate and its length
        vec2 tapMoments = imageLoad(momentsImage, tap).xy;
        if (!isFinite(tapHistory.rgb) || !isFinite(vec3(tapMoments, tapHistory.a)))
          continue;  // never let NaN in
        historySum += weight * tapHistory.rgb;
        momentsSum += weight * vec3(tapMoments, tapHistory.a);
        weightSum += weight;
      }
    }
    // Each bilinear resampling blurs the history by a variance of f(1 - f) squared pixels per
    // axis, and a running average over L frames holds samples resampled up to about L times:
    // while the view moves, cap L so the blur's variance stays about a pixel squared (a sharp
    // shadow edge would otherwise soften frame after frame). A still view (f = 0) keeps 32.
    float blur = f.x * (1.0 - f.x) + f.y * (1.0 - f.y);
    if (frame.previousSize.xy != frame.sizeFrameLights.xy) {
      // The resampling's blur is in the previous picture's pixels: after a change of the render
      // scale it is counted in this picture's (a larger previous picture blurs less of it).
      vec2 toCurrent = vec2(frame.sizeFrameLights.xy) / vec2(frame.previousSize.xy);
      vec2 spread = f * (1.0 - f) * toCurrent * toCurrent;
      blur = spread.x + spread.y;
    }
    historyCap = clamp(1.0 / max(blur, 1e-6), MIN_MOVING_HISTORY, MAX_HISTORY_LENGTH);
    if (weightSum > 1e-3) {
      history = historySum / weightSum;
      moments = momentsSum.xy / weightSum;
      historyLength = momentsSum.z / weightSum;
    }
  }
  // Where ray-gen expected no history (a reset, or the motion it wrote says "nowhere") it
  // traced DENOISER_FRESH_HISTORY_FRAMES frames' worth of samples, which count as that many.
  bool fresh = !reference && surface.w >= 0.0 && (reset || motion.z < 0.0);
  float currentFrames = fresh ? float(DENOISER_FRESH_HISTORY_FRAMES) : 1.0;
  historyLength = min(historyLength + currentFrames, reference ? 1.0e9 : historyCap);
  if (!reference && historyLength > currentFrames) {
    history = clamp(history, low - CLAMP_MARGIN, high + CLAMP_MARGIN);
  }
  // history + a (current - history): exact when they agree, so fully lit stays exactly 1.
  float alpha = min(currentFrames / historyLength, 1.0);
  vec3 integrated = clamp(history + alpha * (current - history), 0.0, 1.0);
  float currentLuminance = luminance(current);
  // The moments are those of one frame's estimate. Fresh samples are the mean of several
  // frames' worth, whose spread is that many times smaller: the neighbourhood's spread (the
  // mean's) scaled up stands in for one frame's.
  float currentSquare = currentLuminance * currentLuminance;
  if (fresh) currentSquare += currentFrames * luminance(sigma) * luminance(sigma);
  moments += alpha * (vec2(currentLuminance, currentSquare) - moments);
  float variance = max(moments.y - moments.x * moments.x, 0.0);
  if (historyLength < 4.0) variance = max(variance, luminance(sigma) * luminance(sigma));
  // The spatial filter steers by the variance of the integrated estimate, which falls as the
  // history grows: a converged pixel is barely blurred, so the blur that feeds back into the
  // history through the first a-trous iteration cannot build up into bias.
  float filterVariance = variance / (historyLength * historyLength);
  vec4 filterInput = vec4(integrated, filterVariance);
  imageStore(filterAImage, pixel, filterInput);
  if (filterVariance < UNFILTERED_VARIANCE_BOUND) imageStore(filterBImage, pixel, filterInput);
  // NaN counts as variance: the a-trous iterations store such a pixel.
  if (subgroupAny(filterVariance != 0.0) && subgroupElect()) {
    uvec2 tile = gl_WorkGroupID.xy;
    if (imageAtomicExchange(filterTilesImage, ivec2(tile), pass.tileStamp) != pass.tileStamp) {
      uint entry = atomicAdd(listedTiles, 1u);
      filterTiles[entry] = tile.x | tile.y << 16;
      // Dispatched in rows as wide as the tile grid: a count of work-groups in one dimension
      // may be limited to 65535.
      uint rowLength = tileRowLength();
      atomicMax(dispatchGroups[0], min(entry + 1u, rowLength));
      atomicMax(dispatchGroups[1], entry / rowLength + 1u);
    }
  }
  float penumbra = penumbraSamples > 0.0 ? penumbraSum / penumbraSamples : -1.0;
  // The moments' length (half floats) serves the a-trous passes' test for a young history; the
  // next frame counts on the history's own, in full floats.
  imageStore(momentsNextImage, pixel,
             vec4(moments, min(historyLength, HALF_FLOAT_MAX), penumbra));
  imageStore(historyNextImage, pixel, vec4(integrated, historyLength));
}
