#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require
#include "ray_payloads.glsl"

layout(location = PAYLOAD_SURFACE) rayPayloadInEXT SurfaceHit hit;

void main() { hit.hitT = -1.0; }
