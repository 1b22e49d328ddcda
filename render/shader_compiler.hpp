#pragma once
// GLSL -> SPIR-V through the glslang library, with per-variant defines and an on-disk cache
// keyed by the source, every included file, the defines and the compiler version.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace render {

class ShaderCompileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using ShaderDefines = std::vector<std::pair<std::string, std::string>>;

struct CompiledShader {
  std::vector<uint32_t> spirv;
  uint64_t cacheKey = 0;
  bool fromCache = false;
};

class ShaderCompiler {
 public:
  // Includes resolve inside `shaderDirectory` only. No cache when `cacheDirectory` is empty.
  ShaderCompiler(std::filesystem::path shaderDirectory, std::filesystem::path cacheDirectory);

  // `file` is relative to the shader directory; its extension gives the stage
  // (.rgen .rmiss .rchit .rahit .comp).
  CompiledShader compile(const std::filesystem::path& file, const ShaderDefines& defines = {});

  const std::filesystem::path& shaderDirectory() const { return shaderDirectory_; }

  // $SIGHTLINE_SHADER_CACHE, else $XDG_CACHE_HOME/sightline/shaders, else ~/.cache/...
  static std::filesystem::path defaultCacheDirectory();

 private:
  std::filesystem::path shaderDirectory_;
  std::filesystem::path cacheDirectory_;
};

}  // namespace render
