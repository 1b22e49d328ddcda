// Where a point of this frame's render space was seen from the previous frame's camera: ray-gen
// gives every surface's motion with it, and the upscaler's resolve a mirror's outline
// (temporal_upscale.glsl). Include it after `frame` is declared.
#ifndef PREVIOUS_VIEW_GLSL
#define PREVIOUS_VIEW_GLSL

// `point` (already moved back by its instance's motion, if any) in the previous frame's picture,
// in pixels, and its distance from the previous camera; vec3(-1.0) behind that camera.
vec3 projectToPreviousView(vec3 point) {
  vec3 offset = point - frame.previousCameraPosition.xyz;
  float along = dot(offset, frame.previousCameraForward.xyz);
  if (along <= 1e-6) return vec3(-1.0);
  vec3 right = frame.previousCameraRight.xyz;
  vec3 up = frame.previousCameraUp.xyz;
  vec2 ndc = vec2(dot(offset, right) / (along * dot(right, right)),
                  dot(offset, up) / (along * dot(up, up)));
  vec2 size = vec2(frame.sizeFrameLights.xy);
  return vec3((ndc.x + 1.0) * 0.5 * size.x - 0.5, (1.0 - ndc.y) * 0.5 * size.y - 0.5,
              length(offset));
}

#endif
