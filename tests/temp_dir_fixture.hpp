#pragma once
// Test helpers for files: a fresh directory per test under the system's temporary directory,
// removed afterwards.
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "scene/scene_desc.hpp"

namespace test {

class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = std::filesystem::temp_directory_path() /
            ("sightline-" + std::string(info->test_suite_name()) + "-" + info->name() + "-" +
             std::to_string(std::random_device{}()));
    std::filesystem::create_directories(root_);
  }
  void TearDown() override {
    std::error_code ignored;
    std::filesystem::remove_all(root_, ignored);
  }
  std::filesystem::path root_;
};

inline void writeFile(const std::filesystem::path& path, const std::string& contents) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << contents;
}

// One RGBA texel of a decoded texture.
inline std::array<uint8_t, 4> texel(const scene::TextureDesc& texture, uint32_t x, uint32_t y) {
  const std::size_t at = (std::size_t{y} * texture.width + x) * 4;
  return {texture.rgba.at(at), texture.rgba.at(at + 1), texture.rgba.at(at + 2),
          texture.rgba.at(at + 3)};
}

}  // namespace test
