#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require
#include "ray_payloads.glsl"

// A glass ray only collects tints in its any-hit calls; reaching nothing changes nothing.
layout(location = PAYLOAD_GLASS) rayPayloadInEXT GlassPath glass;

void main() {}
