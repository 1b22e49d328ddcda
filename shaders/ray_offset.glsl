// Secondary ray origins leave the surface by a few ULPs along the geometric normal, scaled to
// the coordinate's magnitude (integer steps in float bits), so there is no fixed epsilon that
// fails far from the origin or at small scales. Near zero, where ULPs vanish, a tiny fixed
// step takes over.
vec3 offsetRayOrigin(vec3 position, vec3 geometricNormal) {
  const float nearOrigin = 1.0 / 32.0;
  const float fixedStep = 1.0 / 65536.0;
  const float ulpsPerUnitNormal = 256.0;
  ivec3 ulps = ivec3(ulpsPerUnitNormal * geometricNormal);
  ivec3 signedUlps = ivec3(position.x < 0.0 ? -ulps.x : ulps.x, position.y < 0.0 ? -ulps.y : ulps.y,
                           position.z < 0.0 ? -ulps.z : ulps.z);
  vec3 stepped = intBitsToFloat(floatBitsToInt(position) + signedUlps);
  vec3 nearZero = position + fixedStep * geometricNormal;
  return vec3(abs(position.x) < nearOrigin ? nearZero.x : stepped.x,
              abs(position.y) < nearOrigin ? nearZero.y : stepped.y,
              abs(position.z) < nearOrigin ? nearZero.z : stepped.z);
}
