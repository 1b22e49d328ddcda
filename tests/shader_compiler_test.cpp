#include <fstream>

#include <gtest/gtest.h>

#include "render/shader_compiler.hpp"
#include "vulkan_fixture.hpp"

namespace {
namespace fs = std::filesystem;

class ShaderCompilerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("sightline-shader-test-" +
             std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_ / "shaders");
    write("shaders/common.glsl", "const float SCALE = 2.0;\n");
    write("shaders/fill.comp",
          "#version 460\n"
          "#extension GL_GOOGLE_include_directive : require\n"
          "#include \"common.glsl\"\n"
          "layout(local_size_x = 1) in;\n"
          "layout(std430, binding = 0) buffer Out { float values[]; };\n"
          "void main() { values[0] = SCALE * VALUE; }\n");
  }
  void TearDown() override { fs::remove_all(root_); }
  void write(const std::string& relative, const std::string& text) {
    std::ofstream(root_ / relative) << text;
  }
  render::ShaderCompiler compiler() { return {root_ / "shaders", root_ / "cache"}; }

  fs::path root_;
};

TEST_F(ShaderCompilerTest, second_compile_of_same_variant_comes_from_disk_cache) {
  auto first = compiler().compile("fill.comp", {{"VALUE", "1.0"}});
  auto second = compiler().compile("fill.comp", {{"VALUE", "1.0"}});
  EXPECT_FALSE(first.fromCache);
  EXPECT_TRUE(second.fromCache);
  EXPECT_EQ(first.spirv, second.spirv);
  EXPECT_EQ(first.spirv.at(0), 0x07230203u);  // SPIR-V magic
  EXPECT_TRUE(fs::exists(root_ / "cache"));
}

TEST_F(ShaderCompilerTest, changing_a_define_is_a_new_variant) {
  auto one = compiler().compile("fill.comp", {{"VALUE", "1.0"}});
  auto two = compiler().compile("fill.comp", {{"VALUE", "3.0"}});
  EXPECT_NE(one.cacheKey, two.cacheKey);
  EXPECT_FALSE(two.fromCache);
  EXPECT_NE(one.spirv, two.spirv);
}

TEST_F(ShaderCompilerTest, editing_an_included_file_misses_the_cache) {
  auto before = compiler().compile("fill.comp", {{"VALUE", "1.0"}});
  write("shaders/common.glsl", "const float SCALE = 4.0;\n");
  auto after = compiler().compile("fill.comp", {{"VALUE", "1.0"}});
  EXPECT_NE(before.cacheKey, after.cacheKey);
  EXPECT_FALSE(after.fromCache);
}

TEST_F(ShaderCompilerTest, compile_error_names_the_file_and_line) {
  write("shaders/broken.comp",
        "#version 460\n"
        "layout(local_size_x = 1) in;\n"
        "void main() {\n"
        "  float x = undefinedThing;\n"
        "}\n");
  try {
    compiler().compile("broken.comp");
    FAIL() << "a broken shader compiled";
  } catch (const render::ShaderCompileError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("broken.comp:4:"), std::string::npos) << message;
    EXPECT_NE(message.find("undefinedThing"), std::string::npos) << message;
  }
}

TEST_F(ShaderCompilerTest, include_outside_the_shader_directory_is_refused) {
  write("secret.glsl", "const float LEAK = 1.0;\n");
  write("shaders/escape.comp",
        "#version 460\n"
        "#extension GL_GOOGLE_include_directive : require\n"
        "#include \"../secret.glsl\"\n"
        "layout(local_size_x = 1) in;\n"
        "void main() {}\n");
  EXPECT_THROW(compiler().compile("escape.comp"), render::ShaderCompileError);
}

TEST_F(ShaderCompilerTest, shipped_shaders_all_compile) {
  render::ShaderCompiler shipped(test::sourceDir() / "shaders", root_ / "cache");
  for (const char* file :
       {"raygen.rgen", "surface.rmiss", "shadow.rmiss", "surface.rchit", "tonemap.comp"}) {
    EXPECT_FALSE(shipped.compile(file).spirv.empty()) << file;
  }
}

// Whether a SPIR-V module declares a capability (OpCapability is opcode 17, two words long).
bool declaresCapability(const std::vector<uint32_t>& spirv, uint32_t capability) {
  for (size_t word = 5; word < spirv.size();) {
    const uint32_t opcode = spirv[word] & 0xFFFFu;
    const uint32_t length = spirv[word] >> 16;
    if (length == 0) break;
    if (opcode == 17 && word + 1 < spirv.size() && spirv[word + 1] == capability) return true;
    word += length;
  }
  return false;
}

TEST_F(ShaderCompilerTest, subgroup_counters_use_subgroup_arithmetic_only_when_asked) {
  constexpr uint32_t groupNonUniformArithmetic = 63;
  render::ShaderCompiler shipped(test::sourceDir() / "shaders", root_ / "cache");
  for (const char* soft : {"0", "1"}) {
    const auto with =
        shipped.compile("raygen.rgen", {{"SOFT_SHADOWS", soft}, {"SUBGROUP_COUNTERS", "1"}});
    const auto without =
        shipped.compile("raygen.rgen", {{"SOFT_SHADOWS", soft}, {"SUBGROUP_COUNTERS", "0"}});
    EXPECT_TRUE(declaresCapability(with.spirv, groupNonUniformArithmetic)) << soft;
    EXPECT_FALSE(declaresCapability(without.spirv, groupNonUniformArithmetic)) << soft;
  }
}

}  // namespace
