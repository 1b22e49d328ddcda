#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require
#include "ray_payloads.glsl"

// A shadow ray that reaches its light unblocked.
layout(location = PAYLOAD_SHADOW) rayPayloadInEXT float visibility;

void main() { visibility = 1.0; }
