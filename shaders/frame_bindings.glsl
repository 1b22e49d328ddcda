// Images and per-frame uniforms, used by the ray tracing stages and the compute passes.
layout(set = 0, binding = BINDING_HDR_IMAGE, rgba32f) uniform image2D hdrImage;
layout(set = 0, binding = BINDING_OUTPUT_IMAGE, rgba8) uniform writeonly image2D outputImage;
layout(set = 0, binding = BINDING_FRAME, std140) uniform FrameBlock { FrameUniforms frame; };
#ifdef DENOISER_BINDINGS
// Soft-shadow inputs written by ray-gen and the denoiser's own images.
layout(set = 0, binding = BINDING_SOFT_LIGHT, rgba32f) uniform image2D softLightImage;
layout(set = 0, binding = BINDING_VISIBILITY_RAW, rgba16f) uniform image2D visibilityRawImage;
layout(set = 0, binding = BINDING_SURFACE, rgba32f) uniform image2D surfaceImage;
layout(set = 0, binding = BINDING_SURFACE_PREVIOUS, rgba32f) uniform image2D surfacePreviousImage;
layout(set = 0, binding = BINDING_INSTANCE, r32ui) uniform uimage2D instanceImage;
layout(set = 0, binding = BINDING_INSTANCE_PREVIOUS, r32ui) uniform uimage2D instancePreviousImage;
layout(set = 0, binding = BINDING_MOTION, rgba32f) uniform image2D motionImage;
layout(set = 0, binding = BINDING_HISTORY, rgba32f) uniform image2D historyImage;
layout(set = 0, binding = BINDING_HISTORY_NEXT, rgba32f) uniform image2D historyNextImage;
layout(set = 0, binding = BINDING_MOMENTS, rgba32f) uniform image2D momentsImage;
layout(set = 0, binding = BINDING_MOMENTS_NEXT, rgba32f) uniform image2D momentsNextImage;
layout(set = 0, binding = BINDING_FILTER_A, rgba16f) uniform image2D filterAImage;
layout(set = 0, binding = BINDING_FILTER_B, rgba16f) uniform image2D filterBImage;
#endif
