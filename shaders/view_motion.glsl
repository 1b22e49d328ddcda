// This frame's camera rays, and where points and instances were in the previous frame: ray-gen
// gives every surface's motion with these, and the upscaler's resolve finds a mirror's outline
// again (temporal_upscale.glsl). Include it after `frame`, `instances` and `lights` are declared.
#ifndef VIEW_MOTION_GLSL
#define VIEW_MOTION_GLSL

// The direction of this frame's camera ray through `pixel` (its corner; + 0.5 is its centre)
// offset by `jitter` pixels.
vec3 cameraRayDirection(vec2 pixel, vec2 jitter) {
  vec2 ndc = (pixel + 0.5 + jitter) / vec2(frame.sizeFrameLights.xy) * 2.0 - 1.0;
  return normalize(frame.cameraForward.xyz + ndc.x * frame.cameraRight.xyz -
                   ndc.y * frame.cameraUp.xyz);
}

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

// Whether the camera is where it was in the previous frame, turned the same way (the upscaler's
// jitter aside): the previous camera's position in this frame's render space is its origin.
bool cameraHeldStill() {
  return frame.previousCameraPosition.xyz == vec3(0.0) &&
         frame.previousCameraRight.xyz == frame.cameraRight.xyz &&
         frame.previousCameraUp.xyz == frame.cameraUp.xyz &&
         frame.previousCameraForward.xyz == frame.cameraForward.xyz;
}

// Whether the instance `instancePlusOne` - 1 (or the light SEEN_LIGHT_BASE names) moved since the
// previous frame (0: none, which did not). Most frames nothing moved: then the instances' motion
// is not read (in the upscaler's resolve on lavapipe these reads were a fifth of the pass).
bool instanceMoved(uint instancePlusOne) {
  if (frame.denoise.w == 0u || instancePlusOne == 0u) return false;
  if (instancePlusOne >= SEEN_LIGHT_BASE) {
    GpuLight light = lights[instancePlusOne - SEEN_LIGHT_BASE];
    return light.previousPosition.xyz != light.positionType.xyz;
  }
  vec4 rows[3] = instances[instancePlusOne - 1u].previousFromCurrent;
  return rows[0] != vec4(1.0, 0.0, 0.0, 0.0) || rows[1] != vec4(0.0, 1.0, 0.0, 0.0) ||
         rows[2] != vec4(0.0, 0.0, 1.0, 0.0);
}

#endif
