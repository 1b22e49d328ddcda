// Images and per-frame uniforms, used by the ray tracing stages and the compute passes.
layout(set = 0, binding = BINDING_HDR_IMAGE, rgba32f) uniform image2D hdrImage;
layout(set = 0, binding = BINDING_OUTPUT_IMAGE, rgba8) uniform writeonly image2D outputImage;
layout(set = 0, binding = BINDING_FRAME, std140) uniform FrameBlock { FrameUniforms frame; };
