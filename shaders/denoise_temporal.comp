#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_vote : require
#include "shared_types.h"
#define DENOISER_BINDINGS
#include "frame_bindings.glsl"
#ifndef NEIGHBOURHOOD_TILE  // the renderer defines it: 1 on GPUs, 0 on CPU drivers
#define NEIGHBOURHOOD_TILE 0
#endif
// Without the tile (CPU drivers) an invocation handles this many pixels of a column (below).
#ifndef COLUMN_PIXELS
#define COLUMN_PIXELS 2
#endif
// 1 where the soft lights' visibility has no colour (the renderer defines it for a level
// without glass, whose shadow rays each report 0 or 1 in all three channels alike).
#ifndef GREY_VISIBILITY
#define GREY_VISIBILITY 0
#endif
// 1 for a still view: the renderer defines it when the camera, the picture's size and every
// instance are as they were in the last full frame (and for neither a reset nor a reference
// accumulation). Then every point is where it was, so a pixel's history is its own: one tap of
// weight 1, the one whose surface ray-gen compared already, and no resampling blur to cap. The
// same results as the general path (where a still view's motion rounds to exactly 0) with no
// loop over four taps: on lavapipe at 320x180 the denoiser took 0.16-0.25 ms less on 02, 06
// and 07 (docs/PERFORMANCE.md, session 24).
#ifndef STILL_VIEW
#define STILL_VIEW 0
#endif
#if NEIGHBOURHOOD_TILE
#define DENOISER_GROUP_ROWS DENOISER_GROUP_SIZE
#else
#define DENOISER_GROUP_ROWS (DENOISER_GROUP_SIZE / COLUMN_PIXELS)
#endif
#include "denoise_common.glsl"

// Temporal pass: reproject last frame's history, reject it where the surface changed (depth,
// normal, instance), clamp it to the range of this frame's 5x5 neighbourhood (below; not in a
// still view of a steady scene, whose history grows longer and whose penumbrae trace more
// samples: tracesPenumbraSamples), and blend in this frame's samples; also keeps luminance
// moments for the variance the spatial filter steers by. A pixel of sky is only passed through
// (keepWithoutSurface).
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
const float MOTION_GRID = 256.0;   // the reprojection rounds to 1/256 pixel

// The neighbourhood's statistics are kept per channel of visibility: one where it is grey, which
// gives the same bits as three alike and on lavapipe took 17-28 % off the denoiser's time on 02
// and 06 (docs/PERFORMANCE.md, session 23).
#if GREY_VISIBILITY
#define Visibility float
Visibility visibilityOf(vec4 sampled) { return sampled.r; }
#else
#define Visibility vec3
Visibility visibilityOf(vec4 sampled) { return sampled.rgb; }
#endif

// The statistics of a pixel's neighbourhood the clamp and the moments need. They are summed row
// by row, then the rows in order, the same way on both paths below, so both give the same bits.
struct Neighbourhood {
  Visibility sum, sumSquares, low, high;
  float count;
  // The penumbra's width here: the mean over the neighbourhood's samples that met a caster
  // (a sample that reached the light says nothing of it).
  float penumbraSum, penumbraSamples;
};

Neighbourhood emptyNeighbourhood() {
  return Neighbourhood(Visibility(0.0), Visibility(0.0), Visibility(1.0), Visibility(0.0), 0.0,
                       0.0, 0.0);
}

void addSample(inout Neighbourhood n, vec4 sampled) {
  if (sampled.x == OUTSIDE_IMAGE) return;
  if (sampled.a >= 0.0) {
    n.penumbraSum += sampled.a;
    n.penumbraSamples += 1.0;
  }
  Visibility visibility = visibilityOf(sampled);
  n.sum += visibility;
  n.sumSquares += visibility * visibility;
  n.low = min(n.low, visibility);
  n.high = max(n.high, visibility);
  n.count += 1.0;
}

Neighbourhood merged(Neighbourhood a, Neighbourhood b) {
  return Neighbourhood(a.sum + b.sum, a.sumSquares + b.sumSquares, min(a.low, b.low),
                       max(a.high, b.high), a.count + b.count, a.penumbraSum + b.penumbraSum,
                       a.penumbraSamples + b.penumbraSamples);
}

#if NEIGHBOURHOOD_TILE
// The work-group's raw samples and the margin its neighbourhoods reach, loaded once into
// shared memory: each sample is read by 25 pixels (on the H100 at 3840x2160 the 5x5 image
// reads were a third of the denoiser's time). On lavapipe the work-group barrier costs more
// than the reads it saves, so the CPU build slides each neighbourhood down a column instead.
const ivec2 TILE_SIZE = ivec2(gl_WorkGroupSize.xy) + 2 * NEIGHBOURHOOD_RADIUS;
const int TILE_SAMPLES = TILE_SIZE.x * TILE_SIZE.y;
// A grey sample keeps its visibility and penumbra width only.
#if GREY_VISIBILITY
shared vec2 tileSamples[TILE_SAMPLES];
vec2 tileSample(vec4 sampled) { return sampled.ra; }
vec4 fromTile(vec2 kept) { return kept.xxxy; }
#else
shared vec4 tileSamples[TILE_SAMPLES];
vec4 tileSample(vec4 sampled) { return sampled; }
vec4 fromTile(vec4 kept) { return kept; }
#endif

void loadTile() {
  ivec2 tileOrigin = ivec2(gl_WorkGroupID.xy * gl_WorkGroupSize.xy) - NEIGHBOURHOOD_RADIUS;
  uint groupInvocations = gl_WorkGroupSize.x * gl_WorkGroupSize.y;
  for (uint i = gl_LocalInvocationIndex; i < uint(TILE_SAMPLES); i += groupInvocations) {
    ivec2 at = tileOrigin + ivec2(int(i) % TILE_SIZE.x, int(i) / TILE_SIZE.x);
    tileSamples[i] = tileSample(insideImage(at) ? rawSample(at) : vec4(OUTSIDE_IMAGE));
  }
}

vec4 neighbourSample(ivec2 offset) {
  ivec2 at = ivec2(gl_LocalInvocationID.xy) + NEIGHBOURHOOD_RADIUS + offset;
  return fromTile(tileSamples[at.y * TILE_SIZE.x + at.x]);
}

Neighbourhood pixelNeighbourhood() {
  Neighbourhood n = emptyNeighbourhood();
  for (int dy = -NEIGHBOURHOOD_RADIUS; dy <= NEIGHBOURHOOD_RADIUS; ++dy) {
    Neighbourhood row = emptyNeighbourhood();
    for (int dx = -NEIGHBOURHOOD_RADIUS; dx <= NEIGHBOURHOOD_RADIUS; ++dx)
      addSample(row, neighbourSample(ivec2(dx, dy)));
    n = merged(n, row);
  }
  return n;
}
#else
// One invocation handles COLUMN_PIXELS pixels one above the other: each row of samples their
// neighbourhoods share is read and summed once (on lavapipe the neighbourhoods' image reads
// were half of the denoiser's time, 25 a pixel; here 6 rows of 5 for 2 pixels). With 4 pixels
// a column lavapipe was slower again (docs/PERFORMANCE.md, session 19).
const int ROWS = COLUMN_PIXELS + 2 * NEIGHBOURHOOD_RADIUS;

// `inside`: the whole column's neighbourhood is inside the picture (most columns).
Neighbourhood rowNeighbourhood(ivec2 centre, bool inside) {
  Neighbourhood row = emptyNeighbourhood();
  for (int dx = -NEIGHBOURHOOD_RADIUS; dx <= NEIGHBOURHOOD_RADIUS; ++dx) {
    ivec2 at = centre + ivec2(dx, 0);
    // Read from a position clamped into the picture and dropped outside it: on lavapipe a read
    // without a condition costs less than one under it.
    vec4 sampled = rawSample(clamp(at, ivec2(0), ivec2(frame.sizeFrameLights.xy) - 1));
    addSample(row, inside || insideImage(at) ? sampled : vec4(OUTSIDE_IMAGE));
  }
  return row;
}
#endif

// The next frame's moments and history at `pixel` (BUFFERED_IMAGE_WRITES: to the buffers the
// denoiser copies into their images, frame_bindings.glsl).
void storeNext(ivec2 pixel, vec4 moments, vec4 history) {
#if BUFFERED_IMAGE_WRITES
  int index = pixelIndex(pixel);
  writtenMoments[index] = uvec2(packHalf2x16(moments.xy), packHalf2x16(moments.zw));
  writtenHistories[index] = history;
#else
  imageStore(momentsNextImage, pixel, moments);
  imageStore(historyNextImage, pixel, history);
#endif
}

// A pixel whose path met no surface (the sky, seen directly or in a mirror) has nothing to
// denoise: it keeps this frame's sample, without variance, and its neighbourhood is not read
// (on lavapipe a pixel's image reads are most of this pass; 06 Night Watch is half sky). The
// a-trous iterations filter no such pixel and leave it out of their surface pixels' taps (its
// instance is 0), and no later frame's history matches it, so only its variance differs from
// integrating it as a surface: the picture is the same.
void keepWithoutSurface(ivec2 pixel, vec3 current) {
  vec4 filterInput = vec4(current, 0.0);
  imageStore(filterAImage, pixel, filterInput);
  imageStore(filterBImage, pixel, filterInput);
  float currentLuminance = luminance(current);
  storeNext(pixel, vec4(currentLuminance, currentLuminance * currentLuminance, 1.0, -1.0),
            vec4(current, 1.0));
}

#if !STILL_VIEW
// A moving view's history may be resampled with Catmull-Rom weights over 4x4 taps (where every
// tap shows the pixel's surface) instead of bilinear ones over 2x2. The cubic follows a ramp's
// curvature, so a penumbra's profile survives many resamplings, where each bilinear one blurs it
// by f(1 - f) squared pixels; but it averages less of the history's noise away. So it is used
// where 32 frames of the bilinear blur would take more than a quarter of what the cap allows
// (SHARP_BUDGET_SHARE): a penumbra a few pixels wide, or a sharp edge. Under a penumbra wider
// than two pixels what it still blurs (a ramp's finer detail) counts as a quarter of the
// bilinear blur (SHARP_BLUR_FRACTION), which lets the history grow four times as long; under a
// narrower one the cap stays, with less blur within it. Moving after 32 frames at 320x180: 02
// Penumbra 0.01029 -> 0.00945, 06 Night Watch 0.00642 -> 0.00502. Used wherever the view moved,
// it did as well at 320x180 but worse under 1920x1080's penumbrae tens of pixels wide (02
// 0.00486 -> 0.00625, 06 0.00381 -> 0.00484), which the bilinear blur barely touches while it
// smooths their noise (docs/QUALITY.md, session 37).
const float SHARP_BUDGET_SHARE = 0.25;
const float SHARP_BLUR_FRACTION = 0.25;

// The weights of the taps at -1, 0, 1 and 2 for a point at `t` in [0, 1) past tap 0.
vec4 catmullRomWeights(float t) {
  float t2 = t * t, t3 = t2 * t;
  return vec4(-0.5 * t3 + t2 - 0.5 * t, 1.5 * t3 - 2.5 * t2 + 1.0, -1.5 * t3 + 2.0 * t2 + 0.5 * t,
              0.5 * t3 - 0.5 * t2);
}

// The history at `base` + `f` with Catmull-Rom weights; false (and `history` untouched) where a
// tap of non-zero weight lies outside the previous picture, shows another surface or is not
// finite. The caller kept every bilinear tap of non-zero weight (base and the three past it), so
// they showed the surface and were finite already; a weight that is 0 there (f 0 on an axis) is
// 0 here too. The result is clamped to [0, 1], which the weights' negative lobes can overshoot.
bool sharpHistory(ivec2 base, vec2 f, uint instance, float expectedDistance, vec3 normal,
                  inout vec3 history) {
  vec4 weightsX = catmullRomWeights(f.x), weightsY = catmullRomWeights(f.y);
  vec3 sum = vec3(0.0);
  for (int j = 0; j < 4; ++j) {
    if (weightsY[j] == 0.0) continue;
    for (int i = 0; i < 4; ++i) {
      float weight = weightsX[i] * weightsY[j];
      if (weight == 0.0) continue;
      ivec2 tap = base + ivec2(i - 1, j - 1);
      bool bilinearTap = (i == 1 || i == 2) && (j == 1 || j == 2);
      vec3 tapHistory;
      if (bilinearTap) {
        tapHistory = imageLoad(historyImage, tap).rgb;
      } else {
        if (!insidePreviousImage(tap)) return false;
        uvec4 previousSurface = imageLoad(surfacePreviousImage, tap);
        if (previousSurface.z != instance ||
            !historyMatches(previousSurface.xy, expectedDistance, normal))
          return false;
        tapHistory = imageLoad(historyImage, tap).rgb;
        if (!isFinite(tapHistory)) return false;
      }
      sum += weight * tapHistory;
    }
  }
  history = clamp(sum, 0.0, 1.0);
  return true;
}
#endif

// Integrates this frame's sample `current` at `pixel`, whose surface and instance are
// `packedSurface` (as surfaceImage holds them; never sky, which keepWithoutSurface takes), into
// the history, and writes the spatial filter's input and the next history. Returns whether the
// estimate has variance.
bool integrate(ivec2 pixel, vec3 current, uvec4 packedSurface, Neighbourhood n) {
  bool reset = frame.denoise.x != 0u;
  bool reference = frame.denoise.y != 0u;
  vec4 surface = unpackSurface(packedSurface.xy);
  uint instance = packedSurface.z;
  vec3 low = vec3(n.low), high = vec3(n.high);
  vec3 mean = vec3(n.sum / n.count);
  vec3 sigma = sqrt(max(vec3(n.sumSquares / n.count) - mean * mean, vec3(0.0)));

  float penumbra = n.penumbraSamples > 0.0 ? n.penumbraSum / n.penumbraSamples : -1.0;
  vec3 history = current;
  vec2 moments = vec2(luminance(current), luminance(current) * luminance(current));
  float historyLength = 0.0;
  float historyCap = MAX_HISTORY_LENGTH;
  float currentFrames = 1.0;
  vec3 motion = unpackMotion(motions[pixelIndex(pixel)]);
  if (!reset && motion.z >= 0.0) {
#if STILL_VIEW
    vec4 ownHistory = imageLoad(historyImage, pixel);  // the estimate and its length
    // Ray-gen traced more samples where this says so, and a steady scene's history may be
    // longer (the flag is only set for a still view, which this pipeline is).
    if (tracesPenumbraSamples(ownHistory)) currentFrames = float(DENOISER_PENUMBRA_FRAMES);
    if (steadyDenoiserView()) historyCap = float(DENOISER_STEADY_MAX_HISTORY);
    vec2 ownMoments = imageLoad(momentsImage, pixel).xy;
    if (isFinite(ownHistory.rgb) && isFinite(vec3(ownMoments, ownHistory.a))) {
      history = ownHistory.rgb;
      moments = ownMoments;
      historyLength = ownHistory.a;
    }
#else
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
    int weightedTaps = 0, keptTaps = 0;  // the taps of non-zero weight, and those kept
    for (int j = 0; j <= 1; ++j) {
      for (int i = 0; i <= 1; ++i) {
        ivec2 tap = base + ivec2(i, j);
        float weight = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
        if (weight <= 0.0) continue;
        ++weightedTaps;
        if (!insidePreviousImage(tap)) continue;
        // A tap of weight 1 is the nearest one, whose surface ray-gen has compared already
        // (chooseSoftSamples: the motion says "nowhere" where it did not match). A still view
        // has only such taps, and so reads no previous surface.
        if (weight < 1.0 || reference) {
          uvec4 previousSurface = imageLoad(surfacePreviousImage, tap);
          if (previousSurface.z != instance) continue;
          if (!historyMatches(previousSurface.xy, expectedDistance, surface.xyz)) continue;
        }
        vec4 tapHistory = imageLoad(historyImage, tap);  // the estimate and its length
        vec2 tapMoments = imageLoad(momentsImage, tap).xy;
        if (!isFinite(tapHistory.rgb) || !isFinite(vec3(tapMoments, tapHistory.a)))
          continue;  // never let NaN in
        historySum += weight * tapHistory.rgb;
        momentsSum += weight * vec3(tapMoments, tapHistory.a);
        weightSum += weight;
        ++keptTaps;
      }
    }
    // Each bilinear resampling blurs the history by a variance of f(1 - f) squared pixels per
    // axis, and a running average over L frames holds samples resampled up to about L times:
    // while the view moves, cap L so the blur's standard deviation stays within half the
    // penumbra's width, and within a pixel where the penumbra is narrower than two (a sharp
    // shadow edge would otherwise soften frame after frame, while a wide penumbra hardly
    // changes under a blur much narrower than itself and is better served by a longer average:
    // 06 Night Watch moving, after 32 frames 0.01041 -> 0.00679; docs/QUALITY.md, session 21).
    // A still view (f = 0) keeps 32.
    float blur = f.x * (1.0 - f.x) + f.y * (1.0 - f.y);
    if (frame.previousSize.xy != frame.sizeFrameLights.xy) {
      // The resampling's blur is in the previous picture's pixels: after a change of the render
      // scale it is counted in this picture's (a larger previous picture blurs less of it).
      vec2 toCurrent = vec2(frame.sizeFrameLights.xy) / vec2(frame.previousSize.xy);
      vec2 spread = f * (1.0 - f) * toCurrent * toCurrent;
      blur = spread.x + spread.y;
    }
    float blurAllowed = max(1.0, 0.25 * penumbra * penumbra);  // 1 where no width is known
    if (weightSum > 1e-3) {
      history = historySum / weightSum;
      // Where the bilinear blur costs (above), every bilinear tap showed this surface and the
      // history is neither fully lit nor fully shadowed (there any weights give the same),
      // resample with Catmull-Rom weights instead.
      if (MAX_HISTORY_LENGTH * blur > SHARP_BUDGET_SHARE * blurAllowed &&
          keptTaps == weightedTaps &&
          any(greaterThan(history, vec3(0.0))) && any(lessThan(history, vec3(1.0))) &&
          sharpHistory(base, f, instance, expectedDistance, surface.xyz, history)) {
        if (blurAllowed > 1.0) blur *= SHARP_BLUR_FRACTION;
      }
      moments = momentsSum.xy / weightSum;
      historyLength = momentsSum.z / weightSum;
    }
    historyCap = clamp(blurAllowed / max(blur, 1e-6), MIN_MOVING_HISTORY, MAX_HISTORY_LENGTH);
#endif
  }
  // Where ray-gen expected no history (a reset, or the motion it wrote says "nowhere") it
  // traced DENOISER_FRESH_HISTORY_FRAMES frames' worth of samples, which count as that many.
  bool fresh = !reference && (reset || motion.z < 0.0);
  if (fresh) currentFrames = float(DENOISER_FRESH_HISTORY_FRAMES);
  historyLength = min(historyLength + currentFrames, reference ? 1.0e9 : historyCap);
  // A steady scene's history holds nothing stale, and is not clamped: with its longer average,
  // what a rare clamp took (all 25 samples lit beside a penumbra) stayed taken, and the test
  // scene's error rose from 0.0056 after 16 still frames to 0.0087 after 64.
  if (!reference && historyLength > currentFrames && !steadyDenoiserView()) {
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
  // The moments' length (half floats) serves the a-trous passes' test for a young history; the
  // next frame counts on the history's own, in full floats.
  storeNext(pixel, vec4(moments, min(historyLength, HALF_FLOAT_MAX), penumbra),
            vec4(integrated, historyLength));
  // NaN counts as variance: the a-trous iterations store such a pixel.
  return filterVariance != 0.0;
}

// Lists this work-group for the a-trous iterations if a pixel of it has variance.
void listIfFiltered(bool hasVariance) {
  if (subgroupAny(hasVariance) && subgroupElect()) {
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
}

void main() {
#if NEIGHBOURHOOD_TILE
  loadTile();
  barrier();  // every invocation reaches it: the ones past the image's edge return after
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (!insideImage(pixel)) return;
  vec3 current = neighbourSample(ivec2(0)).rgb;
  uvec4 packedSurface = imageLoad(surfaceImage, pixel);
  bool hasVariance = false;
  if (packedSurface.z == 0u) {
    keepWithoutSurface(pixel, current);
  } else {
    hasVariance = integrate(pixel, current, packedSurface, pixelNeighbourhood());
  }
  listIfFiltered(hasVariance);
#else
  ivec2 top = ivec2(gl_GlobalInvocationID.x, gl_GlobalInvocationID.y * COLUMN_PIXELS);
  if (!insideImage(top)) return;
  bool inside = all(greaterThanEqual(top, ivec2(NEIGHBOURHOOD_RADIUS))) &&
                all(lessThan(top + ivec2(NEIGHBOURHOOD_RADIUS, ROWS - 1 - NEIGHBOURHOOD_RADIUS),
                             ivec2(frame.sizeFrameLights.xy)));
  // The column's surfaces (a pixel past the picture's bottom reads the last row's, unused).
  uvec4 surfaces[COLUMN_PIXELS];
  bool anySurface = false;
  for (int i = 0; i < COLUMN_PIXELS; ++i) {
    surfaces[i] =
        imageLoad(surfaceImage, min(top + ivec2(0, i), ivec2(frame.sizeFrameLights.xy) - 1));
    anySurface = anySurface || surfaces[i].z != 0u;
  }
  // A column of sky reads no neighbourhood (rows then stay unset and unused).
  Neighbourhood rows[ROWS];
  if (anySurface) {
    for (int row = 0; row < ROWS; ++row)
      rows[row] = rowNeighbourhood(top + ivec2(0, row - NEIGHBOURHOOD_RADIUS), inside);
  }
  bool hasVariance = false;
  for (int i = 0; i < COLUMN_PIXELS; ++i) {
    ivec2 pixel = top + ivec2(0, i);
    if (!insideImage(pixel)) break;
    vec3 current = rawSample(pixel).rgb;
    if (surfaces[i].z == 0u) {
      keepWithoutSurface(pixel, current);
      continue;
    }
    Neighbourhood n = emptyNeighbourhood();
    for (int row = i; row <= i + 2 * NEIGHBOURHOOD_RADIUS; ++row) n = merged(n, rows[row]);
    hasVariance = integrate(pixel, current, surfaces[i], n) || hasVariance;
  }
  listIfFiltered(hasVariance);
#endif
}
