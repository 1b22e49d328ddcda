// Where a camera pixel's soft-shadow sample numbers start (sampling.glsl's sequenceFrom): the
// lattice while the camera holds still, blue noise while it moves. Include it after
// view_motion.glsl.

layout(set = 0, binding = BINDING_SAMPLE_NOISE, std430) readonly buffer SampleNoiseBlock {
  uint sampleNoise[];
};

// Three blue-noise tiles' values at the pixel (render/blue_noise.hpp): any neighbourhood's
// starts are spread evenly over [0, 1) in each dimension, but unlike the lattice's they are not
// linear in the pixel.
uvec3 blueNoiseStart(uvec2 pixel) {
  uint packed =
      sampleNoise[(pixel.y % SAMPLE_NOISE_SIZE) * SAMPLE_NOISE_SIZE + pixel.x % SAMPLE_NOISE_SIZE];
  // Each rank to the middle of its share of [0, 1) in fixed point.
  return uvec3((packed & 0xFFFu) << 20 | 0x80000u, (packed >> 12 & 0xFFFu) << 20 | 0x80000u,
               (packed >> 24) << 24 | 0x800000u);
}

// A still view keeps the lattice: the errors of neighbouring pixels cancel best there. While the
// camera moves, a point it sees crosses k pixels in k frames and so meets the lattice's start k
// steps back with the sequence k steps on; at a speed where the two steps all but cancel (one
// pixel a frame across, for one) it met the same point of the light frame after frame, and a
// strafing view's soft shadows broke into stripes (02 Penumbra, docs/QUALITY.md, session 29).
// Blue noise has no such speed. A cut (the history reset) starts afresh like a first frame, so
// it takes the lattice as a first frame does.
uvec3 cameraSampleStart(uvec2 pixel) {
  bool resetHistory = frame.denoise.x != 0u;
  return cameraHeldStill() || resetHistory ? latticeStart(pixel) : blueNoiseStart(pixel);
}
