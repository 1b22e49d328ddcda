// Structs that cross between C++ and GLSL: defined once here. The C++ side checks sizes and
// offsets with static_assert (render/gpu_types.hpp). std430/std140-compatible: vec4-sized rows.
#ifndef SIGHTLINE_SHARED_TYPES_H
#define SIGHTLINE_SHARED_TYPES_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace render::gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using uint = uint32_t;
#endif

// Binding numbers of descriptor set 0, shared by the ray tracing and compute pipelines.
#define BINDING_TLAS 0
#define BINDING_RADIANCE 1  // vec4 a render pixel, row after row: ray-gen's linear radiance
#define BINDING_OUTPUT_IMAGE 2
#define BINDING_FRAME 3
#define BINDING_INSTANCES 4
#define BINDING_MATERIALS 5
#define BINDING_LIGHTS 6
#define BINDING_VERTICES 7
#define BINDING_INDICES 8
#define BINDING_COUNTERS 9
#define BINDING_TEXTURES 10
#define BINDING_PATHS 11
// Soft shadows: what ray-gen writes for the denoiser, and the denoiser's own images.
// A storage buffer of vec4 (frame_bindings.glsl's pixelIndex): unshadowed light of the sampled
// (soft) lights
#define BINDING_SOFT_LIGHT 12
#define BINDING_VISIBILITY_RAW 13  // rgba16f: this frame's visibility estimate
// Ray-gen writes the raw visibility (four half floats) and the surface (uvec4) to storage buffers,
// which the renderer copies into the images at BINDING_VISIBILITY_RAW and BINDING_SURFACE.
#define BINDING_VISIBILITY_WRITTEN 38
#define BINDING_SURFACE_WRITTEN 39
// The same for the temporal pass's moments (four half floats) and history (vec4), copied into
// the images at BINDING_MOMENTS_NEXT and BINDING_HISTORY_NEXT.
#define BINDING_MOMENTS_WRITTEN 40
#define BINDING_HISTORY_WRITTEN 41
// rgba32ui: packed world normal, distance from the camera (< 0: sky), instance + 1 (0: sky)
#define BINDING_SURFACE 14
#define BINDING_SURFACE_PREVIOUS 15
// A storage buffer of uvec2 (packMotion): previous pixel position xy, expected distance z
#define BINDING_MOTION 18
#define BINDING_HISTORY 19       // rgba32f: rgb visibility history (previous frame)
#define BINDING_MOMENTS 20       // rgba32f: luminance moments x, y; history length z (prev.)
#define BINDING_MOMENTS_NEXT 21  // this frame's moments
#define BINDING_FILTER_A 22      // rgba16f: rgb visibility, a variance (ping)
#define BINDING_FILTER_B 23      // (pong)
// The most frames the temporal filter averages: the oldest weight stays >= 1/32, a bounded lag;
// a static view has settled after this many frames.
#define DENOISER_MAX_HISTORY 32
// A pixel whose history starts afresh (the first frame, a disocclusion, the view's edge while
// turning) traces this many frames' worth of soft shadow samples, and the temporal filter
// counts them as that many frames.
#define DENOISER_FRESH_HISTORY_FRAMES 8
// While the view is still and the scene steady (FrameUniforms::previousSize.z), a pixel in a
// penumbra traces DENOISER_PENUMBRA_FRAMES frames' worth of soft shadow samples until its
// history holds DENOISER_PENUMBRA_HISTORY frames' worth, and a history may hold up to
// DENOISER_STEADY_MAX_HISTORY.
#define DENOISER_PENUMBRA_FRAMES 3
#define DENOISER_PENUMBRA_HISTORY 64
#define DENOISER_STEADY_MAX_HISTORY 128
#define BINDING_HISTORY_NEXT 24  // this frame's history (the first filter iteration)
#define BINDING_PROBE_SETUP 25   // what the probes measure: focus regions, exposure points
#define BINDING_LIGHT_ROUTES 26  // lights seen via mirrors (levels with flat mirrors and lights)
#define BINDING_TRIANGLE_MATERIALS 27  // per-triangle materials of meshes with several
// Temporal upscaling (a renderer with an output size): ray-gen's motion at the render size, and
// the history and picture at the output size.
// A storage buffer of vec4, a row of render pixels after another: previous pixel xy, distance z,
// first instance + 1 w; in a mirror that held still the reflection's previous pixel, the
// mirror's distance and minus (the mirror + 1) (ray-gen's writeUpscaleMotion)
#define BINDING_UPSCALE_MOTION 28
// rgba32ui: accumulated display rgb and its weight as four half floats (xy), the instance + 1
// the history shows (z; 0: none); the previous frame's
#define BINDING_UPSCALE_HISTORY 29
// This frame's history and the upscaled picture (rgba8, sRGB-encoded): storage images where the
// resolve is a compute shader (GPUs), colour attachments where it is a fragment shader (CPU
// drivers).
#define BINDING_UPSCALE_HISTORY_NEXT 30
#define BINDING_DISPLAY_IMAGE 33
#define UPSCALE_ATTACHMENT_DISPLAY 0
#define UPSCALE_ATTACHMENT_HISTORY 1
// r32ui, one texel per denoiser work-group: the stamp of the last frame whose temporal pass left
// a pixel there with variance for the a-trous iterations to filter.
#define BINDING_FILTER_TILES 34
// A storage buffer: the a-trous iterations' indirect dispatch (x, y, z work-groups), the count
// of listed work-groups, then one entry per work-group the temporal pass left something to
// filter (x | y << 16).
#define BINDING_FILTER_TILE_LIST 35
// The glass instances alone, for the glass rays (glassTransmittance): a CPU driver's traversal
// of the whole scene's structure to reject every opaque instance by its mask cost a quarter of
// a glass level's frame.
#define BINDING_GLASS_TLAS 36
// A storage buffer: the soft shadows' per-pixel starts of their sample numbers, one word a texel
// of a SAMPLE_NOISE_SIZE-square tile (render/blue_noise.hpp says how three blue-noise maps are
// packed in it; shaders/sample_noise.glsl, blueNoiseStart, reads it).
#define BINDING_SAMPLE_NOISE 37
#define SAMPLE_NOISE_SIZE 64u
// The upscaler's history cap in frames without upscaling (plain TAA); upscaled by k a side the
// cap comes to this times k^4 frames, so a still view keeps averaging (temporal_upscale.glsl).
#define UPSCALE_MAX_HISTORY_FRAMES 32.0
// A still view's history goes unclamped once the scene has held this many full frames
// (Renderer::steadyFrames(); the resolve is then compiled with STEADY_VIEW, temporal_upscale.glsl).
#define UPSCALE_STEADY_FRAMES_UNCLAMPED 8u

#define LIGHT_POINT 0u
#define LIGHT_DIRECTIONAL 1u
#define LIGHT_SPHERE 2u
#define LIGHT_RECTANGLE 3u
#define LIGHT_DISK 4u

#define MATERIAL_DIFFUSE 0u
#define MATERIAL_MIRROR 1u
#define MATERIAL_GLASS 2u

#define SHADING_BLINN_PHONG 0u         // Lambert plus an energy-normalised Blinn-Phong lobe
#define SHADING_METALLIC_ROUGHNESS 1u  // glTF 2.0's BRDF (appendix B)

// Instance mask bits. Surface rays see opaque instances, shadow rays opaque shadow casters;
// glass is only seen by the glass rays that collect its tint.
#define MASK_VISIBLE 0x01u
#define MASK_SHADOW_CASTER 0x02u
#define MASK_GLASS 0x04u
#define MASK_GLASS_SHADOW 0x08u
// The player's body: seen by shadow rays and by rays that left a mirror, not by camera rays from
// the eye, nor by the probe rays that measure the player's own exposure.
#define MASK_BODY 0x10u
// Casters of shadows from directional lights only ("casts_shadow": "directional"), opaque and
// glass: only the shadow rays towards a directional light test them.
#define MASK_SHADOW_DIRECTIONAL 0x20u
#define MASK_GLASS_SHADOW_DIRECTIONAL 0x40u

// Hit groups (the instance's SBT record offset).
#define HIT_GROUP_SURFACE 0u
#define HIT_GROUP_GLASS 1u

// What a pixel's final path reached, written by ray-gen for tests and probes.
#define PATH_REACHED_NOTHING 0xFFFFFFFFu

// The upscaler's name for what a pixel shows (its motion's w, its history's z): the instance + 1
// (0: none), or for an area light seen, SEEN_LIGHT_BASE + the light's index (below 2^24, so
// exact as a float).
#define SEEN_LIGHT_BASE 0x800000u

#define TONEMAP_IDENTITY 0u
#define TONEMAP_ACES 1u

// Floats per vertex in the vertex buffer: position xyz, normal xyz, uv, colour rgba, uv1.
#define VERTEX_FLOATS 14

struct FrameUniforms {
  vec4 cameraPosition;          // xyz: the camera in render space (world minus camera): 0
  vec4 cameraRight;             // xyz: right * tan(fov/2) * aspect
  vec4 cameraUp;                // xyz: up * tan(fov/2)
  vec4 cameraForward;           // xyz: unit forward
  vec4 skyZenith;               // linear radiance
  vec4 skyHorizon;              // linear radiance
  vec4 ambient;                 // linear radiance of a uniform, unshadowed environment
  uvec4 sizeFrameLights;        // width, height, frame index, light count
  vec4 exposureTonemap;         // x: exposure, y: tonemap mode (as float), z: row groups
  vec4 previousCameraPosition;  // the previous frame's camera in this frame's render space
  vec4 previousCameraRight;
  vec4 previousCameraUp;
  vec4 previousCameraForward;
  // x: reset history, y: reference accumulation, z: filter iterations, w: 1 if an instance or a
  // light may have moved since the last full frame (else every previousFromCurrent is the
  // identity and every light's previousPosition its position)
  uvec4 denoise;
  // A probe-only frame (z: 1) traces just the focus regions' box, whose top-left pixel is xy,
  // and finds what each path reaches without shading it or writing any image.
  uvec4 probeLaunch;
  // xy: the camera rays' offset from the pixel centres (pixels, in [-0.5, 0.5): the upscaler's
  // sequence, else the frame's own; 0 in probe frames); zw: the output size.
  vec4 upscale;
  // x: the most mirror bounces a camera path takes, the level's cap (a uniform, not a variant
  // define: levels that differ only in it share one pipeline and its compile)
  uvec4 mirrorBounces;
  // xy: the size of the previous full frame's picture, whose extent of the images the
  // denoiser's history holds (it differs from this frame's while the render scale changes);
  // z: 1 where penumbrae trace more samples and the denoiser's history may grow to
  // DENOISER_STEADY_MAX_HISTORY (a still view of a steady scene; RendererOptions::
  // steadyPenumbraSamples)
  uvec4 previousSize;
  // The device addresses of two top-level structures, each as low and high 32 bits: xy the whole
  // scene's, zw the one camera rays trace (every instance but the player's body; xy again when
  // there is no such structure: no body, or nothing but the body)
  uvec4 topLevels;
  // xy: the width and height of the storage buffers that hold a value per pixel (ray-gen's
  // outputs), the render size's: pixel (x, y) is element y * width + x whatever the picture's
  // size this frame (pixelIndex in frame_bindings.glsl)
  uvec4 pixelBuffers;
};

// GpuInstance.geometry.z with this bit: the rest is where the instance's triangles' materials
// start in the triangle-material buffer (a glTF model of several materials).
#define MATERIAL_PER_TRIANGLE 0x80000000u

struct GpuInstance {
  // x: first index, y: vertex offset, z: material (or MATERIAL_PER_TRIANGLE | first triangle
  // material), w: glow (float bits): light the game adds to the surface, times its albedo (an orb
  // in focus, a lit sensor)
  uvec4 geometry;
  // Rows of the previous frame's object-to-world times the current world-to-object, in render
  // space: where a point on this instance was one frame ago (identity when it did not move).
  vec4 previousFromCurrent[3];
};

// A material's textures, by role (scene::TextureRole): index into GpuMaterial's arrays.
#define TEXTURE_BASE_COLOR 0u
#define TEXTURE_NORMAL 1u
#define TEXTURE_METALLIC_ROUGHNESS 2u
#define TEXTURE_OCCLUSION 3u
#define TEXTURE_EMISSIVE 4u
#define TEXTURE_ROLES 5

// GpuMaterial.kindShading.w bits.
#define MATERIAL_FLAG_ALPHA_BLEND 1u  // glass whose tint comes from glTF BLEND colour and alpha

struct GpuMaterial {
  vec4 baseColorSpecular;  // rgb: linear albedo, a: specular weight
  vec4 emissiveRoughness;  // rgb: linear emitted radiance, a: roughness
  vec4 mirrorTint;         // rgb: reflectance times tint (MATERIAL_MIRROR); a: metallic
  // rgb: transmittance per front face (MATERIAL_GLASS); a: the alpha cutoff divided by the
  // base colour's alpha factor, compared with texture alpha x vertex alpha (0: opaque)
  vec4 glassTint;
  // x: MATERIAL_*, y: SHADING_*, z: bit r set when texture role r reads the second UV set,
  // w: MATERIAL_FLAG_* bits
  uvec4 kindShading;
  // Texture + 1 (0: none) of role r at [r / 4][r % 4].
  uvec4 textureSlots[2];
  vec4 textureFactors;  // x: base colour alpha, y: normal scale, z: occlusion strength
  // Role r's KHR_texture_transform as two rows: uv' = (dot([2r].xyz, (uv, 1)),
  // dot([2r + 1].xyz, (uv, 1))).
  vec4 textureTransforms[2 * TEXTURE_ROLES];
};

struct GpuLight {
  vec4 positionType;      // xyz: position, w: LIGHT_* as float
  vec4 directionEnabled;  // xyz: unit direction (light travel / emitting side), w: 1 if on
  vec4 radianceRadius;    // rgb: colour * intensity (unit by type), w: radius
  vec4 extent;            // xy: rectangle size, z: angular diameter in radians
  // xyz: where the light was at the previous full frame (render space), for the upscaler's
  // motion of a light seen (the same as positionType.xyz unless it moved; zero in a light
  // route's image).
  vec4 previousPosition;
};

// Counters the ray-gen shader adds into; integers so sums do not depend on order. Pixels
// spread their atomics over COUNTER_SLOTS copies (summed on the host) so a GPU's threads do
// not all queue on one address.
#define COUNTER_SLOTS 64
struct FrameCounters {
  uint surfaceRays;    // camera rays and their mirror bounces
  uint secondaryRays;  // shadow rays and glass rays
  uint reserved0;
  uint reserved1;
};

// Probes: what the game's rules read back each probe frame (see game/probes.hpp).
#define MAX_FOCUS_PROBES 16
#define MAX_EXPOSURE_PROBES 16
#define EXPOSURE_SAMPLES 64  // sample points per exposure probe (one shadow ray each)
#define EXPOSURE_ONE 1024u   // fixed point: what one fully lit sample adds
// What an exposure sample counts: the luminance of the transmittance (glass and mirror tints),
// or (a colour sensor) how far the light's colour times the tints is of one colour: that
// channel less the larger of the other two (see probe.rgen).
#define EXPOSURE_CHANNEL_LUMINANCE 0u
#define EXPOSURE_CHANNEL_RED 1u
#define EXPOSURE_CHANNEL_GREEN 2u
#define EXPOSURE_CHANNEL_BLUE 3u

struct ProbeSetup {
  uvec4 counts;  // x: focus probes, y: exposure probes
  // x: instance, y: region's first pixel (x | y << 16), z: one past its last (same packing)
  uvec4 focus[MAX_FOCUS_PROBES];
  // x: light, y: sample points used (<= EXPOSURE_SAMPLES), z: EXPOSURE_CHANNEL_* | 0x100 when
  // the points are on the player's body (its rays pass through the body), w: the light's colour
  // as the level made it (no feedback tint), largest channel 1, packUnorm4x8; points at
  // [probe * SAMPLES]
  uvec4 exposure[MAX_EXPOSURE_PROBES];
};

struct ProbePoint {
  vec4 position;  // xyz: render-space position, already offset off the surface
  vec4 normal;    // xyz: outward normal; w: 1 = the light must be on the normal's side
};

// Added into by the ray-gen shaders; integers, so sums do not depend on order.
struct ProbeResults {
  uint focusPixels[MAX_FOCUS_PROBES];  // region pixels whose path ended on the probe's instance
  uint exposure[MAX_EXPOSURE_PROBES];  // sum over samples of visibility * EXPOSURE_ONE
};

// Light routed by flat mirrors: for each light and each sequence of mirror faces its light can
// take (at most MAX_ROUTE_MIRRORS), the light's mirror image. A point lit via the route sees the
// image; the ray towards the image must cross each face's rectangle from its reflecting side.
#define MAX_LIGHT_ROUTES 8
#define MAX_ROUTE_MIRRORS 3

struct GpuRouteMirror {
  vec4 plane;   // xyz: unit normal on the reflecting side, w: dot(normal, a point on the face)
  vec4 centre;  // xyz: the face rectangle's centre
  vec4 halfU;   // xyz: half the rectangle along one side; w: its length
  vec4 halfV;   // xyz: half along the other side; w: its length
};

struct GpuLightRoute {
  GpuLight image;      // the light mirrored by each face in turn; radiance times the tints
  uvec4 lightMirrors;  // x: the light it comes from, y: faces on the route
  vec4 tint;           // rgb: product of the faces' reflectance times tint
  vec4 imageTangent;   // xyz: a rectangle image's first side (mirrored, so not basisAround's)
  GpuRouteMirror mirrors[MAX_ROUTE_MIRRORS];  // from the lit point towards the light
};

struct LightRoutesHeader {
  uvec4 count;  // x: routes in use
};

struct PixelPath {
  uint finalInstance;  // instance the path ended on (after glass and mirrors), or NOTHING
  uint bounces;        // mirror reflections taken
};

#ifdef __cplusplus
}  // namespace render::gpu
#endif

#endif
