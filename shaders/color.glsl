// The exact sRGB OETF (IEC 61966-2-1), applied once, in the final pass.
vec3 linearToSrgb(vec3 linearColor) {
  vec3 low = linearColor * 12.92;
  vec3 high = 1.055 * pow(linearColor, vec3(1.0 / 2.4)) - 0.055;
  return mix(high, low, lessThan(linearColor, vec3(0.0031308)));
}

// Narkowicz 2015 fit of the ACES filmic curve; maps [0, inf) to [0, 1).
vec3 acesFilmic(vec3 x) {
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
