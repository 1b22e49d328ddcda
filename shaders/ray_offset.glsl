// Secondary ray origins leave the surface by a step proportional to `magnitude`, the largest
// quantity the hit position was computed from (the ray's origin coordinates and the distance
// it travelled): the hit's rounding error grows with it, so the step holds at every scale and
// distance, with no fixed epsilon that is metres long far from the camera or larger than the
// level itself at small scales. 2^-16 of it is 128 float ULPs.
float rayOffsetMagnitude(vec3 origin, float distance) {
  vec3 size = abs(origin);
  return max(max(size.x, size.y), max(size.z, distance));
}

// The step goes along the geometric normal (facing the arriving ray) and back along the
// arriving ray, whose last stretch is known to be empty: at a concave edge, where another
// surface lies within rounding distance of the hit, it moves away from that surface too.
vec3 offsetRayOrigin(vec3 position, vec3 geometricNormal, vec3 arriving, float magnitude) {
  const float relativeStep = 1.0 / 65536.0;
  // Below the smallest normal float the step would vanish; there everything is at the origin.
  return position + (geometricNormal - arriving) * max(magnitude * relativeStep, 1.0e-30);
}
