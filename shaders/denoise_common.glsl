// Shared by the denoiser passes.
#ifndef DENOISER_GROUP_SIZE  // the renderer defines it (Denoiser::kGroupSize)
#define DENOISER_GROUP_SIZE 16
#endif
layout(local_size_x = DENOISER_GROUP_SIZE, local_size_y = DENOISER_GROUP_SIZE) in;

float luminance(vec3 rgb) { return dot(rgb, vec3(0.2126, 0.7152, 0.0722)); }

bool isFinite(vec3 v) { return !any(isnan(v)) && !any(isinf(v)); }

bool insideImage(ivec2 pixel) {
  return all(greaterThanEqual(pixel, ivec2(0))) &&
         all(lessThan(pixel, ivec2(frame.sizeFrameLights.xy)));
}

// The raw visibility estimate, with anything non-finite replaced so it never spreads.
vec3 rawVisibility(ivec2 pixel) {
  vec3 value = imageLoad(visibilityRawImage, pixel).rgb;
  return isFinite(value) ? clamp(value, 0.0, 1.0) : vec3(1.0);
}
