// Images, buffers and per-frame uniforms, used by the ray tracing stages and the compute passes.
layout(set = 0, binding = BINDING_OUTPUT_IMAGE, rgba8) uniform writeonly image2D outputImage;
layout(set = 0, binding = BINDING_FRAME, std140) uniform FrameBlock { FrameUniforms frame; };

#include "pixel_index.glsl"

// Ray-gen's linear radiance (rgb; alpha 0 where the sample shows something that moved).
layout(set = 0, binding = BINDING_RADIANCE, std430) buffer RadianceBlock {
  vec4 tracedRadiance[];
};
#ifdef DENOISER_BINDINGS
// Soft-shadow inputs written by ray-gen and the denoiser's own images. On GPUs the denoiser's
// passes are limited by memory traffic, so what tolerates fewer bits has them (the formats are
// explained in render/denoiser.cpp).
const float HALF_FLOAT_MAX = 65504.0;
// Ray-gen's, a value per pixel (pixelIndex), each read once: the unshadowed light of the soft
// lights (rgb) and the motion (packMotion).
layout(set = 0, binding = BINDING_SOFT_LIGHT, std430) buffer SoftLightBlock { vec4 softLights[]; };
layout(set = 0, binding = BINDING_MOTION, std430) buffer MotionBlock { uvec2 motions[]; };
// BUFFERED_IMAGE_WRITES 1 (CPU drivers): ray-gen writes the raw visibility (rgb) and penumbra
// width (a) as four half floats (packHalf2x16), and the surface (packSurface) in xy with its
// instance + 1 (0: sky) in z, and the temporal pass writes the next moments (four half floats)
// and history, to these buffers, and the denoiser copies them into the images below. lavapipe
// stores to an image one lane at a time, but reads an image faster than a buffer, and their
// readers read them many times a pixel (02 Penumbra at 320x180: the denoiser 6.6 ms reading the
// images, 7.9 reading the buffers). Elsewhere the shaders store to the images (on the H200 at
// 3840x2160 ray-gen's two copies cost 2.1 ms).
#ifndef BUFFERED_IMAGE_WRITES
#define BUFFERED_IMAGE_WRITES 0
#endif
#if BUFFERED_IMAGE_WRITES
layout(set = 0, binding = BINDING_VISIBILITY_WRITTEN, std430) buffer VisibilityWrittenBlock {
  uvec2 writtenVisibilities[];
};
layout(set = 0, binding = BINDING_SURFACE_WRITTEN, std430) buffer SurfaceWrittenBlock {
  uvec4 writtenSurfaces[];
};
layout(set = 0, binding = BINDING_MOMENTS_WRITTEN, std430) buffer MomentsWrittenBlock {
  uvec2 writtenMoments[];
};
layout(set = 0, binding = BINDING_HISTORY_WRITTEN, std430) buffer HistoryWrittenBlock {
  vec4 writtenHistories[];
};
#endif
layout(set = 0, binding = BINDING_VISIBILITY_RAW, rgba16f) uniform image2D visibilityRawImage;
// The surface in xy and its instance + 1 (0: sky) in z: one read for both.
layout(set = 0, binding = BINDING_SURFACE, rgba32ui) uniform uimage2D surfaceImage;
layout(set = 0, binding = BINDING_SURFACE_PREVIOUS, rgba32ui) uniform uimage2D surfacePreviousImage;
layout(set = 0, binding = BINDING_HISTORY, rgba32f) uniform image2D historyImage;
layout(set = 0, binding = BINDING_HISTORY_NEXT, rgba32f) uniform image2D historyNextImage;
layout(set = 0, binding = BINDING_MOMENTS, rgba16f) uniform image2D momentsImage;
layout(set = 0, binding = BINDING_MOMENTS_NEXT, rgba16f) uniform image2D momentsNextImage;
layout(set = 0, binding = BINDING_FILTER_A, rgba16f) uniform image2D filterAImage;
layout(set = 0, binding = BINDING_FILTER_B, rgba16f) uniform image2D filterBImage;
layout(set = 0, binding = BINDING_FILTER_TILES, r32ui) uniform uimage2D filterTilesImage;
layout(set = 0, binding = BINDING_FILTER_TILE_LIST, std430) buffer FilterTileList {
  uint dispatchGroups[3];  // rows of up to the tile grid's width, as many rows as needed
  uint listedTiles;
  uint filterTiles[];
};

// A unit vector as a point of the octahedron |x| + |y| + |z| = 1 unfolded onto the square
// [-1, 1]^2: two numbers instead of three, evenly precise in every direction.
vec2 octahedralFromUnit(vec3 direction) {
  vec3 onOctahedron = direction / max(dot(abs(direction), vec3(1.0)), 1e-30);
  vec2 signs = vec2(onOctahedron.x >= 0.0 ? 1.0 : -1.0, onOctahedron.y >= 0.0 ? 1.0 : -1.0);
  return onOctahedron.z >= 0.0 ? onOctahedron.xy : (1.0 - abs(onOctahedron.yx)) * signs;
}

vec3 unitFromOctahedral(vec2 square) {
  vec3 direction = vec3(square, 1.0 - abs(square.x) - abs(square.y));
  float fold = max(-direction.z, 0.0);
  direction.xy -= fold * vec2(direction.x >= 0.0 ? 1.0 : -1.0, direction.y >= 0.0 ? 1.0 : -1.0);
  return normalize(direction);
}

// The surface image: the normal (octahedral, 16-bit signed normalized) and the distance along
// the path (a full float: the depth tests are relative, at every scale a level may have); a
// distance below 0 is the sky.
uvec2 packSurface(vec3 normal, float pathLength) {
  return uvec2(packSnorm2x16(octahedralFromUnit(normal)), floatBitsToUint(pathLength));
}

vec4 unpackSurface(uvec2 packed) {
  return vec4(unitFromOctahedral(unpackSnorm2x16(packed.x)), uintBitsToFloat(packed.y));
}

// The motion image: where the point was in the previous frame as an offset from this pixel
// (half floats: an offset of 64 pixels to 1/32 of one) and its distance then (a full float);
// a distance below 0: nowhere.
uvec2 packMotion(vec2 offset, float previousDistance) {
  // Clamped: an offset past half float's range is off the image either way.
  vec2 representable = clamp(offset, vec2(-HALF_FLOAT_MAX), vec2(HALF_FLOAT_MAX));
  return uvec2(packHalf2x16(representable), floatBitsToUint(previousDistance));
}

vec3 unpackMotion(uvec2 packed) {
  return vec3(unpackHalf2x16(packed.x), uintBitsToFloat(packed.y));
}

// The temporal pass keeps a pixel of history only where the surface there last frame matches
// the point's: the same instance, a distance within 5 % of the expected one, a similar normal.
const float RELATIVE_DEPTH_TOLERANCE = 0.05;
const float NORMAL_COSINE_TOLERANCE = 0.9;

bool historyMatches(uvec2 previousSurfacePacked, float expectedDistance, vec3 normal) {
  vec4 previousSurface = unpackSurface(previousSurfacePacked);
  return abs(previousSurface.w - expectedDistance) <= RELATIVE_DEPTH_TOLERANCE * expectedDistance &&
         dot(previousSurface.xyz, normal) >= NORMAL_COSINE_TOLERANCE;
}

// A still view of a steady scene with nothing stale in the denoiser's history (the renderer
// decides: FrameUniforms::previousSize.z): penumbrae trace more samples, and the history grows
// longer and is not clamped.
bool steadyDenoiserView() { return frame.previousSize.z != 0u; }

// Whether a pixel of a still view of a steady scene traces DENOISER_PENUMBRA_FRAMES frames' worth
// of soft shadow samples, from its history (the estimate and its length): where its samples so
// far were neither all lit nor all shadowed (a penumbra) and the history holds fewer than
// DENOISER_PENUMBRA_HISTORY frames' worth. Ray-gen decides by it and the temporal pass counts
// the frames by it, from the same texel.
bool tracesPenumbraSamples(vec4 history) {
  return steadyDenoiserView() && history.a < float(DENOISER_PENUMBRA_HISTORY) &&
         any(greaterThan(history.rgb, vec3(0.0))) && any(lessThan(history.rgb, vec3(1.0)));
}

#endif
