#include <gtest/gtest.h>

#include "render/shader_binding_table.hpp"

// Groups as the pipeline has them: one raygen, two misses (surface, shadow), one hit group.
TEST(ShaderBindingTable, lavapipe_properties_handle32_align16_base32) {
  const render::SbtLayout layout = render::computeSbtLayout({32, 16, 32}, 2, 1);
  EXPECT_EQ(layout.raygen.offset, 0u);
  EXPECT_EQ(layout.raygen.stride, 32u);
  EXPECT_EQ(layout.raygen.size, 32u);
  EXPECT_EQ(layout.miss.offset, 32u);
  EXPECT_EQ(layout.miss.stride, 32u);
  EXPECT_EQ(layout.miss.size, 64u);
  EXPECT_EQ(layout.hit.offset, 96u);
  EXPECT_EQ(layout.hit.stride, 32u);
  EXPECT_EQ(layout.hit.size, 32u);
  EXPECT_EQ(layout.totalSize, 128u);
}

TEST(ShaderBindingTable, nvidia_properties_handle32_align32_base64) {
  const render::SbtLayout layout = render::computeSbtLayout({32, 32, 64}, 2, 1);
  EXPECT_EQ(layout.raygen.stride, 64u);
  EXPECT_EQ(layout.raygen.size, 64u);  // raygen size must equal its stride
  EXPECT_EQ(layout.miss.offset, 64u);
  EXPECT_EQ(layout.miss.stride, 32u);
  EXPECT_EQ(layout.miss.size, 64u);
  EXPECT_EQ(layout.hit.offset, 128u);
  EXPECT_EQ(layout.hit.stride, 32u);
  EXPECT_EQ(layout.hit.size, 64u);
  EXPECT_EQ(layout.totalSize, 192u);
}

TEST(ShaderBindingTable, every_region_starts_on_the_base_alignment) {
  for (uint32_t base : {32u, 64u, 128u}) {
    for (uint32_t misses = 1; misses < 5; ++misses) {
      const render::SbtLayout layout = render::computeSbtLayout({32, 16, base}, misses, 3);
      EXPECT_EQ(layout.miss.offset % base, 0u);
      EXPECT_EQ(layout.hit.offset % base, 0u);
      EXPECT_GE(layout.miss.size, layout.miss.stride * misses);
      EXPECT_GE(layout.hit.size, layout.hit.stride * 3);
    }
  }
}

TEST(ShaderBindingTable, rejects_zero_properties) {
  EXPECT_THROW(render::computeSbtLayout({0, 16, 32}, 1, 1), std::invalid_argument);
}
