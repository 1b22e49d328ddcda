#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"
#include "temporal_upscale.glsl"

// The resolve on CPU drivers (temporal_upscale.glsl): a fragment shader over one triangle that
// covers the output (fullscreen.vert), writing the picture and the history as colour
// attachments.
layout(location = UPSCALE_ATTACHMENT_DISPLAY) out vec4 display;
layout(location = UPSCALE_ATTACHMENT_HISTORY) out uvec4 historyNext;

void main() { resolvePixel(ivec2(gl_FragCoord.xy), display, historyNext); }
