// The scene as the ray tracing stages see it. (Camera rays trace a structure without the
// player's body, which ray-gen finds by its address: FrameUniforms::topLevels.)
layout(set = 0, binding = BINDING_TLAS) uniform accelerationStructureEXT sceneTlas;
layout(set = 0, binding = BINDING_GLASS_TLAS) uniform accelerationStructureEXT glassTlas;
layout(set = 0, binding = BINDING_INSTANCES, std430) readonly buffer InstanceBlock {
  GpuInstance instances[];
};
layout(set = 0, binding = BINDING_MATERIALS, std430) readonly buffer MaterialBlock {
  GpuMaterial materials[];
};
layout(set = 0, binding = BINDING_LIGHTS, std430) readonly buffer LightBlock { GpuLight lights[]; };
layout(set = 0, binding = BINDING_VERTICES, std430) readonly buffer VertexBlock {
  float vertexFloats[];
};
layout(set = 0, binding = BINDING_INDICES, std430) readonly buffer IndexBlock { uint indices[]; };
layout(set = 0, binding = BINDING_COUNTERS, std430) buffer CounterBlock {
  FrameCounters counterSlots[COUNTER_SLOTS];
  ProbeResults probeResults;
};
layout(set = 0, binding = BINDING_PROBE_SETUP, std430) readonly buffer ProbeSetupBlock {
  ProbeSetup probeSetup;
  ProbePoint probePoints[];
};
layout(set = 0, binding = BINDING_TRIANGLE_MATERIALS, std430) readonly buffer TriangleMaterialBlock {
  uint triangleMaterials[];
};
layout(set = 0, binding = BINDING_TEXTURES) uniform sampler2D textures[];
layout(set = 0, binding = BINDING_PATHS, std430) writeonly buffer PathBlock { PixelPath paths[]; };
