// Temporal upscaling (TAAU): this frame's jittered picture at the render size is accumulated
// into a history at the output size, which follows the motion ray-gen wrote (camera, moving
// instances and lights; in a mirror, the reflection's; between the samples on one surface,
// interpolated, and past them towards a silhouette, continued), is clamped to the range of this
// frame's samples around it (no ghosts where the view changed) and, while the camera moves,
// counts for less the further the clamp moved it, where it moves counts for at most 16 frames'
// worth at 4x, 8 at 2x (each frame's resampling blurs it), and is dropped where a moving
// instance (or light) was seen before (no trail behind it).
// Colours stay the tonemap's sRGB-encoded values, which is where the eye judges differences.
// This file resolves one output pixel for the two entry points:
// temporal_upscale.comp (GPUs: a compute shader storing to images) and temporal_upscale.frag
// (CPU drivers: a fragment shader writing colour attachments; lavapipe writes those in whole
// vectors, where a compute shader's image stores go one lane at a time, 1.4 of the pass's 3.8 ms
// at 640x360; on the H100, whose raster units are few, the same fragment pass took 5.8 ms at
// 3840x2160 against the compute shader's 0.22).

layout(set = 0, binding = BINDING_FRAME, std140) uniform FrameBlock { FrameUniforms frame; };
#include "pixel_index.glsl"
layout(set = 0, binding = BINDING_INSTANCES, std430) readonly buffer InstanceBlock {
  GpuInstance instances[];
};
layout(set = 0, binding = BINDING_LIGHTS, std430) readonly buffer LightBlock { GpuLight lights[]; };
// The tonemap's output at the render size.
layout(set = 0, binding = BINDING_OUTPUT_IMAGE, rgba8) uniform readonly image2D currentImage;
// Ray-gen's motion: where each sample's point was in the previous frame (ray-gen's
// writeUpscaleMotion says what it holds for a reflection), a value per render pixel (loadMotion).
layout(set = 0, binding = BINDING_UPSCALE_MOTION, std430) readonly buffer UpscaleMotionBlock {
  vec4 upscaleMotion[];
};
// The history: its rgb and weight as four half floats (packHalf2x16 of rg and of b and the
// weight) and the instance + 1 it shows (0: none), one read and one store a pixel.
layout(set = 0, binding = BINDING_UPSCALE_HISTORY, rgba32ui) uniform readonly uimage2D historyImage;

// Where the camera holds still and what the pixel shows does not move, the clamp's range takes
// in the 3x3 samples around the pixel instead of its 2x2: a detail thinner than the samples'
// spacing (a rail, a plate seen edge-on) falls between the four nearest samples of most
// frames' jitter, and clamping to them erased what the history had gathered of it
// (bench-upscale on 13 Colour Lock, static after 16 frames: RMSE 0.0212 with the 2x2 range,
// 0.0162 with 3x3, 0.0138 with no clamp at all). Moving, the range stays 2x2: a wider one let
// more of what the history showed elsewhere through (13 moving after 32 frames: 0.0312 with
// 2x2, 0.0374 with 3x3, 0.0394 with 3x3 wherever a pixel moved under one output pixel).
// The still range is widened by this share of its width on each side (03 Glass and Mirrors,
// static after 16 frames: 0.02195 without, 0.02166 with).
const float kStillRangeMargin = 0.25;
// STEADY_VIEW 1: the pipeline for a steady view, which the renderer takes once the scene has
// held UPSCALE_STEADY_FRAMES_UNCLAMPED full frames (Renderer::steadyFrames(): the camera still,
// no instance or light changed). Its history is not clamped at all: nothing it holds can be
// stale, and any range of this frame's samples erases details thinner than their spacing that
// the history has gathered. Nor is the motion read: every point is where it was. Until then
// the clamp removes what a change made stale, and the soft-shadow denoiser's history (its own
// temporal pass) settles. A pipeline of its own, not a branch on a uniform: on lavapipe at
// 640x360, an if/else on the count cost a moving view's resolve up to 0.4 ms more, and the count
// tested inside each of the general path's branches left a steady view's 0.4 ms slower than
// this (docs/PERFORMANCE.md, session 24).
#ifndef STEADY_VIEW
#define STEADY_VIEW 0
#endif
// HAS_MIRRORS 1: the scene has mirrors, so a sample's motion may be a reflection's (ray-gen's
// writeUpscaleMotion); without, the resolve is compiled without that test.
#ifndef HAS_MIRRORS
#define HAS_MIRRORS 0
#endif
// HELD_POINT_RESOLVE 1: the pipeline for a camera held still (render::ResolveView::HeldCamera),
// where a pixel whose four samples show nothing that moved takes heldPointHistory (the same
// history as the general path's, for less). A pipeline of its own: the test in the moving
// view's pipeline cost a strafing view's resolve 0.6 ms on 01 at 640x360 (docs/PERFORMANCE.md,
// session 36).
#ifndef HELD_POINT_RESOLVE
#define HELD_POINT_RESOLVE 0
#endif

// A sample counts for an output pixel by its distance d (output pixels) as (1 - d^2/r^2)^2, a
// smooth bump about a pixel wide, like the box filter of a supersampled reference.
const float kSampleRadius = 1.0;
// The bump's integral (pi r^2 / 3 output pixels): a sample's whole weight over the pixels.
const float kSampleBumpIntegral = 1.0471976 * kSampleRadius * kSampleRadius;
// Accumulated weight worth one sample at the pixel centre: below it the picture blends towards
// the bilinear upscale of this frame, so the first frames look like a plain upscale.
const float kEnoughWeight = 1.0;
const float kMotionGrid = 256.0;  // the reprojection rounds to 1/256 output pixel
// While the camera moves, a history that the clamp had to move far showed something this
// frame's samples do not (what the view uncovered, a highlight that moved on, a detail thinner
// than the samples' spacing that they miss now): it keeps less of its weight the further it was
// moved, down to kClampedHistoryFloor of it at kClampedHistoryDistance (in the encoded colour's
// units, the largest channel's move), so this frame's samples take over sooner. Measured with
// bench-upscale on every level (docs/QUALITY.md, session 27): moving after 32 frames lower on 14
// of 19 (07 Crossing, 13 Colour Lock and 06 Night Watch by 15-18 %), within 1.5x of the same
// view held still on 9 instead of 5 (the walk's first 8 frames from an empty history 2.6 %
// higher); a still view is unchanged.
const float kClampedHistoryDistance = 0.25;
const float kClampedHistoryFloor = 0.1;
// While the camera moves, or the instance a pixel shows, each frame resamples the history
// bilinearly, which blurs it, so the older a sample the blurrier: a moving history keeps at most
// so many frames' worth of the weight its pixel gets a frame, as many as it takes the jitter to
// put a sample within every output pixel (1 / (render pixels per output pixel)^2: 16 at 4x, 4
// at 2x) and at least kMovingHistoryFramesAtLeast. (A still view's cap, in resolvePixel, lets it
// average on.) Measured with bench-upscale (docs/QUALITY.md, session 28): at 4x, 16 frames
// against none lowered moving after 32 frames on 17 of 19 levels (by up to 5 %) and after 96
// frames of walking back and forth on 17 (by up to 10 %), the first 8 frames within 0.1 %; 12
// frames gained more on 02 Penumbra and 06 Night Watch and lost on 16 The Lift and 10 Relay. At
// 2x, 8 frames against 16 lowered moving after 32 frames on the six levels measured (by 2-6 %).
// A panel of bars one sample wide sliding past a still camera for 64 frames at 4x: 2.26x the
// error of the panel held still without the cap, 1.94x with it.
const float kMovingHistoryFramesAtLeast = 8.0;
// Samples of one instance whose distances from the previous camera differ by at most this share
// show one surface: their motions are interpolated between them, and continued past them towards
// a silhouette. 0.3 rather than 0.1: a side face seen at a slant, a few samples wide, changes
// its depth by more than a tenth from one sample to the next (the strafing box test: 1.48x the
// still view's error with 0.1, 1.33x with 0.3, the same with 0.5; bench-upscale at 4x, moving
// after 32 frames within 0.00005 of 0.3's with 0.1 and with 0.5 on four levels).
const float kSameSurfaceDepth = 0.3;

#include "view_motion.glsl"

// Ray-gen's motion for the sample at render pixel `at` (on the picture).
vec4 loadMotion(ivec2 at) { return upscaleMotion[pixelIndex(at)]; }

#if HAS_MIRRORS
// Where the point at `distance` along the camera ray of render pixel `renderPixel` was in the
// previous frame: ray-gen's motion of a surface that held still, found again from its distance.
vec3 previousOfCameraRayPoint(ivec2 renderPixel, vec2 jitter, float distance) {
  return projectToPreviousView(frame.cameraPosition.xyz +
                               cameraRayDirection(vec2(renderPixel), jitter) * distance);
}
#endif

// The render pixel of sample `corner` (0-3: x, then y) of the four around a point, `base` the
// top-left one's, kept on the picture.
ivec2 cornerSample(vec2 base, int corner, ivec2 renderSize) {
  return clamp(ivec2(base) + ivec2(corner & 1, corner >> 1), ivec2(0), renderSize - 1);
}

// Which of the four samples around a point (0-3: x, then y) is nearest it, `fraction` (0-1 in x
// and y) its place past the first.
int nearestCornerTo(vec2 fraction) {
  return int(fraction.x >= 0.5) + 2 * int(fraction.y >= 0.5);
}

// Whether a sample at `candidate` from the previous camera is nearer in depth than one at
// `chosen` (0 or below: in front of no camera, never nearer, and beaten by any that is).
bool nearerInDepth(float candidate, float chosen) {
  return candidate > 0.0 && (chosen <= 0.0 || candidate < chosen);
}

// The motion ray-gen wrote for the sample at render pixel `at`, xy made how far its point moved
// (render pixels; the sample lies at `at` + `jitter`).
vec4 sampleMotion(ivec2 at, vec2 jitter) {
  vec4 motion = loadMotion(at);
  motion.xy -= vec2(at) + jitter;
  return motion;
}

// The bilinear weight of corner `corner` (0-3: x, then y) of four around a point `f` (0-1 in x
// and y) past the first.
float bilinearWeight(vec2 f, int corner) {
  return ((corner & 1) != 0 ? f.x : 1.0 - f.x) * ((corner >> 1) != 0 ? f.y : 1.0 - f.y);
}

// Whether `candidate` (a sample's motion, xy made its move) shows the surface that `chosen` does:
// the same instance (or light, or the sky), within kSameSurfaceDepth of its depth.
bool sameSurface(vec4 candidate, vec4 chosen) {
  return candidate.w == chosen.w && candidate.z > 0.0 &&
         abs(candidate.z - chosen.z) <= kSameSurfaceDepth * chosen.z;
}

// The share of its weight a moving view's history keeps after the clamp moved it by `moved`.
float clampedHistoryShare(vec3 moved) {
  vec3 distance = abs(moved);
  float largest = max(distance.r, max(distance.g, distance.b));
  return clamp(1.0 - largest / kClampedHistoryDistance, kClampedHistoryFloor, 1.0);
}

vec4 historyColourAndWeight(uvec4 texel) {
  return vec4(unpackHalf2x16(texel.x), unpackHalf2x16(texel.y));
}

float sampleWeight(vec2 offset) {
  float t = max(1.0 - dot(offset, offset) / (kSampleRadius * kSampleRadius), 0.0);
  return t * t;
}

// The range of the 3x3 samples around a point that did not move, widened by kStillRangeMargin
// of its width on each side: `low` and `high` hold the four samples around the pixel (`base` the
// top-left one's render pixel, `nearest` the one nearest the pixel) and get the other five. The
// 3x3 is centred on the nearest of the four, so its other five lie in the column and the row
// just past the four on the nearest one's side. (Loaded by position: a loop over the nine that
// skipped the four cost lavapipe more than the loads themselves.)
void widenToStillRange(vec2 base, ivec2 nearest, inout vec3 low, inout vec3 high) {
  ivec2 renderSize = ivec2(frame.sizeFrameLights.xy);
  ivec2 beyond = ivec2(base) + mix(ivec2(-1), ivec2(2), greaterThan(nearest, ivec2(base)));
  ivec2 first = ivec2(base), second = ivec2(base) + 1;
  ivec2 extra[5] = ivec2[5](ivec2(beyond.x, first.y), ivec2(beyond.x, second.y),
                            ivec2(first.x, beyond.y), ivec2(second.x, beyond.y), beyond);
  for (int i = 0; i < 5; ++i) {
    vec3 colour = imageLoad(currentImage, clamp(extra[i], ivec2(0), renderSize - 1)).rgb;
    low = min(low, colour);
    high = max(high, colour);
  }
  vec3 spread = high - low;
  low -= kStillRangeMargin * spread;
  high += kStillRangeMargin * spread;
}

// The history at where this pixel's point was in the previous frame, clamped to the range of
// this frame's samples around the pixel (`low`, `high`: the four's), as rgb and weight (0: none
// kept), and the instance the pixel shows (0: none).
vec4 reprojectedHistory(ivec2 pixel, vec2 samplePosition, vec2 base, vec3 low, vec3 high,
                        out uint seenInstance) {
  ivec2 outputSize = ivec2(frame.upscale.zw);
  ivec2 renderSize = ivec2(frame.sizeFrameLights.xy);
  vec2 scale = vec2(renderSize) / vec2(outputSize);
  vec2 jitter = frame.upscale.xy;
  // Where this pixel's point was in the previous frame, in output pixels: the motion (render
  // pixels, without this frame's jitter) of the surface that whichever of the four samples around
  // it is nearest in depth (its distance from the previous camera) shows, applied to this pixel.
  // Along a silhouette the foreground's motion so carries the pixels around its edge, which moves
  // as one piece instead of splitting into the samples' 4-pixel steps.
  vec2 fraction = samplePosition - base;
  int nearestCorner = nearestCornerTo(fraction);
  ivec2 nearest = cornerSample(base, nearestCorner, renderSize);
  // Each sample's motion, xy made how far its point moved (render pixels).
  vec4 cornerMotions[4];
  vec4 motion = vec4(0.0);
  for (int corner = 0; corner < 4; ++corner) {
    vec4 cornerMotion = sampleMotion(cornerSample(base, corner, renderSize), jitter);
    cornerMotions[corner] = cornerMotion;
    if (corner == nearestCorner) motion = cornerMotion;
  }
  int chosenCorner = nearestCorner;
#if HAS_MIRRORS
  float nearestShows = motion.w;
  // The four samples show the same instance, and the same way (a mirror's reflection or not).
  bool oneSurface = true;
#endif
  for (int corner = 0; corner < 4; ++corner) {
    vec4 candidate = cornerMotions[corner];
#if HAS_MIRRORS
    oneSurface = oneSurface && candidate.w == nearestShows;
#endif
    if (nearerInDepth(candidate.z, motion.z)) {
      motion = candidate;
      chosenCorner = corner;
    }
  }
  ivec2 chosenAt = cornerSample(base, chosenCorner, renderSize);  // the chosen sample's pixel
  // The pixel's point moves as the samples on that surface around it do, their moves
  // interpolated bilinearly at the pixel. On a surface seen at a slant (a floor, a wall along the
  // walk) the sample nearest in depth is the one nearest the camera, whose point moves further
  // than the pixel's: its move alone put the moving picture ahead of where it is (04 Stained
  // Glass's shadows on the floor by about 1.5 output pixels at 4x; docs/QUALITY.md, session 31).
  // On one surface: sameSurface. A reflection keeps its own sample's move: the samples in a
  // mirror show different things at different depths behind it, while their depths are the
  // mirror's.
  bool cameraStill = cameraHeldStill();
  vec2 displacement = motion.xy;
  if (motion.w >= 0.0) {
    vec2 interpolated = vec2(0.0);
    float weights = 0.0;
    int onSurface = 0;  // the corners on that surface, a bit each
    // The moves of the chosen sample's neighbours within the four, along x and along y (kept
    // here, where the corner is a constant once the loop is unrolled).
    vec2 neighbourMoves[2] = vec2[2](motion.xy, motion.xy);
    for (int corner = 0; corner < 4; ++corner) {
      vec4 candidate = cornerMotions[corner];
      if (!sameSurface(candidate, motion)) continue;
      onSurface |= 1 << corner;
      if (corner == (chosenCorner ^ 1)) neighbourMoves[0] = candidate.xy;
      if (corner == (chosenCorner ^ 2)) neighbourMoves[1] = candidate.xy;
      float w = bilinearWeight(fraction, corner);
      interpolated += w * candidate.xy;
      weights += w;
    }
    if (weights > 0.0) displacement = interpolated / weights;
    // Along a silhouette, where not all four show the surface, the pixel's point may lie past the
    // chosen sample's, nearer the outline, and the outline is where the surface turns away: a
    // box's side face seen at a slant, a pillar's curve. There the surface lies deeper than the
    // sample nearest in depth, and moves less; with that sample's move the outline ran ahead of
    // itself (the strafing box's far edge by 1.0-2.0 output pixels). So the move is continued
    // from the chosen sample towards the pixel, along each axis, as it changes to the next
    // sample on the surface (within the four, or else the one beyond the chosen sample on the
    // other side), and kept within the four samples' moves (docs/QUALITY.md, session 32).
    if (onSurface != 15 && (!cameraStill || instanceMoved(uint(motion.w)))) {
      ivec2 chosenOffset = ivec2(chosenCorner & 1, chosenCorner >> 1);
      vec2 reach = abs(fraction - vec2(chosenOffset));  // from the chosen sample to the pixel
      vec2 continued = motion.xy, lowest = motion.xy, highest = motion.xy;
      for (int corner = 0; corner < 4; ++corner) {
        vec4 candidate = cornerMotions[corner];
        if (candidate.z <= 0.0) continue;
        lowest = min(lowest, candidate.xy);
        highest = max(highest, candidate.xy);
      }
      for (int axis = 0; axis < 2; ++axis) {
        vec2 change = vec2(0.0);
        if ((onSurface & (1 << (chosenCorner ^ (1 << axis)))) != 0) {
          change = neighbourMoves[axis] - motion.xy;
        } else {
          ivec2 away = ivec2(0);
          away[axis] = 2 * chosenOffset[axis] - 1;  // the side away from the pixel
          vec4 beyond = sampleMotion(clamp(chosenAt + away, ivec2(0), renderSize - 1), jitter);
          // (At the picture's edge that is the chosen sample itself, and the change 0.)
          if (sameSurface(beyond, motion)) change = motion.xy - beyond.xy;
        }
        continued += change * reach[axis];
      }
      displacement = clamp(continued, lowest, highest);
    }
  }
#if HAS_MIRRORS
  // A reflection's sample (w < 0): inside the mirror the pixel follows the reflection, whose
  // motion ray-gen wrote. Along the mirror's outline, where the four samples do not all show
  // it, the outline moves with the mirror: its point on the sample's ray, z away. (With the
  // reflection's motion there the outline came out in the samples' steps: 19 Last Light moving,
  // docs/QUALITY.md, session 26.)
  if (motion.w < 0.0) {
    if (!oneSurface) {
      motion.xyz = previousOfCameraRayPoint(chosenAt, jitter, motion.z);
      displacement = motion.xy - (vec2(chosenAt) + jitter);
    }
    motion.w = -motion.w;
  }
#endif
  seenInstance = uint(motion.w);
  bool historyThere = motion.z > 0.0;  // the point was in front of the previous camera
  // On a grid of 1/256 output pixel: a still view's motion, rounding left over from projecting
  // the sample's point back, becomes exactly 0, and the three history taps of weight 0 are not
  // read.
  vec2 previous = vec2(pixel) + round(displacement / scale * kMotionGrid) / kMotionGrid;
  // What the pixel shows moves: the camera does, or the instance the pixel shows.
  bool pointMoves = !cameraStill || instanceMoved(seenInstance);
  if (!pointMoves) widenToStillRange(base, nearest, low, high);
  vec3 history = vec3(0.0);
  float historyWeight = 0.0;
  ivec2 previousPixel = ivec2(floor(previous + 0.5));
  bool onImage = all(greaterThanEqual(previousPixel, ivec2(0))) &&
                 all(lessThan(previousPixel, outputSize));
  // The history is dropped where it showed a moving instance other than the one seen now: what
  // the mover uncovered (no trail behind it).
  if (frame.denoise.x == 0u && historyThere && onImage) {
    uvec4 nearestHistory = imageLoad(historyImage, previousPixel);
    uint shown = nearestHistory.z;
    if (shown == seenInstance || !instanceMoved(shown)) {
      // Bilinear over the four history pixels around `previous` that are on the image.
      vec2 from = floor(previous);
      vec2 g = previous - from;
      vec4 sum = vec4(0.0);
      float taps = 0.0;
      for (int tap = 0; tap < 4; ++tap) {
        ivec2 at = ivec2(from) + ivec2(tap & 1, tap >> 1);
        float w = bilinearWeight(g, tap);
        if (w == 0.0 || any(lessThan(at, ivec2(0))) || any(greaterThanEqual(at, outputSize)))
          continue;
        // The nearest one was read already (a still view's only tap).
        sum += w * historyColourAndWeight(at == previousPixel ? nearestHistory
                                                               : imageLoad(historyImage, at));
        taps += w;
      }
      if (taps > 1.0e-3) {
        vec3 reprojected = sum.rgb / taps;
        history = clamp(reprojected, low, high);
        historyWeight = sum.a / taps;
        if (!cameraStill) historyWeight *= clampedHistoryShare(history - reprojected);
        if (pointMoves) {
          // The weight a pixel gets a frame: the sample bump's integral times the samples an
          // output pixel gets.
          float weightPerFrame = kSampleBumpIntegral * scale.x * scale.y;
          float frames = max(1.0 / (scale.x * scale.y), kMovingHistoryFramesAtLeast);
          historyWeight = min(historyWeight, frames * weightPerFrame);
        }
      }
    }
  }
  return vec4(history, historyWeight);
}

#if !STEADY_VIEW && HELD_POINT_RESOLVE
// reprojectedHistory for a pixel whose four samples show nothing that moved (the tonemap's
// alpha, from ray-gen) under a camera held still, after the first frame: every motion there is
// 0, so the point is where it was and its history is the pixel under it, clamped to the still
// range as a point that did not move is, and dropped where it showed something that moved (what
// a mover uncovered). The same history and picture as reprojectedHistory's for less: with the
// camera held still on a level whose movers never rest (06's lamp, 07's carts) every pixel took
// the general path (docs/PERFORMANCE.md, session 36). The instance recorded as shown is the
// history's own (a steady view's rule) where it is kept; where it is dropped, the one
// reprojectedHistory chooses (the sample's nearest in depth; a mirror's as the mirror), read from
// the motions only there. Choosing it everywhere cost the pass 0.5-0.6 ms, and it differs only
// along the outline of something at rest, whose pixels, once it moves, may keep or drop one
// frame's history otherwise than the general path's, as after a steady view.
vec4 heldPointHistory(ivec2 pixel, vec2 samplePosition, vec2 base, vec3 low, vec3 high,
                      out uint seenInstance) {
  ivec2 renderSize = ivec2(frame.sizeFrameLights.xy);
  vec2 fraction = samplePosition - base;
  ivec2 nearest = cornerSample(base, nearestCornerTo(fraction), renderSize);
  uvec4 texel = imageLoad(historyImage, pixel);
  if (instanceMoved(texel.z)) {
    vec2 chosen = loadMotion(nearest).zw;  // depth and instance
    for (int corner = 0; corner < 4; ++corner) {
      vec2 candidate = loadMotion(cornerSample(base, corner, renderSize)).zw;
      if (nearerInDepth(candidate.x, chosen.x)) chosen = candidate;
    }
    seenInstance = uint(abs(chosen.y));
    return vec4(0.0);
  }
  seenInstance = texel.z;
  widenToStillRange(base, nearest, low, high);
  vec4 history = historyColourAndWeight(texel);
  return vec4(clamp(history.rgb, low, high), history.a);
}
#endif

// The pixel's picture (rgba8, sRGB-encoded) and its history for the next frame (as above).
void resolvePixel(ivec2 pixel, out vec4 display, out uvec4 historyNext) {
  ivec2 outputSize = ivec2(frame.upscale.zw);
  ivec2 renderSize = ivec2(frame.sizeFrameLights.xy);
  vec2 scale = vec2(renderSize) / vec2(outputSize);  // render pixels per output pixel
  vec2 jitter = frame.upscale.xy;
  // This pixel's centre in render pixels, where this frame's sample i lies at i + jitter.
  vec2 samplePosition = (vec2(pixel) + 0.5) * scale - 0.5 - jitter;

  // The four samples around this pixel: the bilinear upscale, their range (for the clamp) and
  // their weighted sum for this pixel.
  vec2 base = floor(samplePosition);
  vec2 f = samplePosition - base;
  vec3 corners[4];
  vec3 low = vec3(1.0), high = vec3(0.0), weighted = vec3(0.0);
  float weight = 0.0;
  float shownHeld = 1.0;  // 0 where one of the four shows something that moved (ray-gen's alpha)
  for (int corner = 0; corner < 4; ++corner) {
    ivec2 offset = ivec2(corner & 1, corner >> 1);
    vec4 texel = imageLoad(currentImage, cornerSample(base, corner, renderSize));
    vec3 colour = texel.rgb;
    shownHeld = min(shownHeld, texel.a);
    corners[corner] = colour;
    low = min(low, colour);
    high = max(high, colour);
    float w = sampleWeight((vec2(offset) - f) / scale);
    weighted += w * colour;
    weight += w;
  }
  vec3 bilinear = mix(mix(corners[0], corners[1], f.x), mix(corners[2], corners[3], f.x), f.y);

#if STEADY_VIEW
  // A steady view needs no motion: every point is where it was, its history is the one pixel
  // under it, unclamped, and the instance it shows is the one its history shows.
  uvec4 texel = imageLoad(historyImage, pixel);
  vec4 history = historyColourAndWeight(texel);
  uint seenInstance = texel.z;
#else
  uint seenInstance;
#if HELD_POINT_RESOLVE
  vec4 history =
      cameraHeldStill() && frame.denoise.x == 0u && shownHeld > 0.5
          ? heldPointHistory(pixel, samplePosition, base, low, high, seenInstance)
          : reprojectedHistory(pixel, samplePosition, base, low, high, seenInstance);
#else
  vec4 history = reprojectedHistory(pixel, samplePosition, base, low, high, seenInstance);
#endif
#endif
  float historyWeight = history.a;
  // The cap on the history's weight: UPSCALE_MAX_HISTORY_FRAMES times the bump's integral
  // (pi r^2 / 3 output pixels) over the samples an output pixel gets a frame. A pixel's weight
  // a frame is that integral times those samples, so while upscaling the cap is that many frames
  // over their square: 32 frames plainly, 512 at 2x, 8192 at 4x. A still view keeps averaging,
  // and that is what holds it steady. A pixel gets its weight in lumps, one when a sample lands
  // near its centre, and a history held to 32 frames' worth took a ninth (2x) to a third (4x)
  // of each such sample: 02 at 2x after 200 frames changed three times as much from one frame
  // to the next (RMSE 0.00069 against 0.00022; docs/QUALITY.md, session 20).
  float expectedWeight = kSampleBumpIntegral / (scale.x * scale.y);
  historyWeight = min(historyWeight, UPSCALE_MAX_HISTORY_FRAMES * expectedWeight);
  float total = historyWeight + weight;
  vec3 accumulated = (history.rgb * historyWeight + weighted) / max(total, 1.0e-6);
  vec3 shown = mix(bilinear, accumulated, min(total / kEnoughWeight, 1.0));
  historyNext = uvec4(packHalf2x16(accumulated.rg), packHalf2x16(vec2(accumulated.b, total)),
                      seenInstance, 0u);
  // Quantized with round-to-nearest, as the tonemap does, so the UNORM write is exact.
  display = vec4(round(clamp(shown, 0.0, 1.0) * 255.0) / 255.0, 1.0);
}
