#include "render/shader_compiler.hpp"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <mutex>
#include <sstream>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <glslang/build_info.h>

namespace render {
namespace fs = std::filesystem;
namespace {

constexpr uint32_t kSpirvMagic = 0x07230203;

std::optional<std::string> readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// FNV-1a, 64 bit: a cache key, not a security boundary.
struct Fnv1a {
  uint64_t value = 0xcbf29ce484222325ull;
  void add(const std::string& text) {
    for (unsigned char c : text) {
      value ^= c;
      value *= 0x100000001b3ull;
    }
    value ^= 0xff;  // separator, so ("ab","c") and ("a","bc") differ
    value *= 0x100000001b3ull;
  }
};

EShLanguage stageFromExtension(const fs::path& file) {
  const std::string extension = file.extension().string();
  if (extension == ".rgen") return EShLangRayGen;
  if (extension == ".rmiss") return EShLangMiss;
  if (extension == ".rchit") return EShLangClosestHit;
  if (extension == ".rahit") return EShLangAnyHit;
  if (extension == ".rint") return EShLangIntersect;
  if (extension == ".comp") return EShLangCompute;
  if (extension == ".vert") return EShLangVertex;
  if (extension == ".frag") return EShLangFragment;
  throw ShaderCompileError(file.string() + ": unknown shader stage extension '" + extension +
                           "' (expected .rgen .rmiss .rchit .rahit .rint .comp .vert .frag)");
}

bool isInside(const fs::path& root, const fs::path& path) {
  const fs::path canonicalRoot = fs::weakly_canonical(root);
  const fs::path canonical = fs::weakly_canonical(path);
  auto rootIt = canonicalRoot.begin();
  auto it = canonical.begin();
  for (; rootIt != canonicalRoot.end(); ++rootIt, ++it) {
    if (it == canonical.end() || *it != *rootIt) return false;
  }
  return true;
}

// Resolves #include "x" next to the including file, never outside the shader directory, and
// remembers every file's text for the cache key.
class RecordingIncluder : public glslang::TShader::Includer {
 public:
  explicit RecordingIncluder(fs::path root) : root_(std::move(root)) {}

  IncludeResult* includeLocal(const char* headerName, const char* includerName, size_t) override {
    const fs::path candidate = fs::path(includerName).parent_path() / headerName;
    if (!isInside(root_, candidate)) return nullptr;
    auto text = readText(candidate);
    if (!text) return nullptr;
    auto owned = std::make_unique<std::string>(std::move(*text));
    included_.push_back(candidate.string() + "\n" + *owned);
    auto* result = new IncludeResult(candidate.string(), owned->data(), owned->size(), owned.get());
    owned.release();
    return result;
  }
  IncludeResult* includeSystem(const char* headerName, const char* includerName,
                               size_t depth) override {
    return includeLocal(headerName, includerName, depth);
  }
  void releaseInclude(IncludeResult* result) override {
    if (!result) return;
    delete static_cast<std::string*>(result->userData);
    delete result;
  }
  const std::vector<std::string>& included() const { return included_; }

 private:
  fs::path root_;
  std::vector<std::string> included_;
};

void initializeGlslangOnce() {
  static std::once_flag once;
  std::call_once(once, [] {
    glslang::InitializeProcess();
    std::atexit([] { glslang::FinalizeProcess(); });
  });
}

void configure(glslang::TShader& shader, EShLanguage stage) {
  shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_4);
}

}  // namespace

ShaderCompiler::ShaderCompiler(fs::path shaderDirectory, fs::path cacheDirectory)
    : shaderDirectory_(std::move(shaderDirectory)), cacheDirectory_(std::move(cacheDirectory)) {}

fs::path ShaderCompiler::defaultCacheDirectory() {
  if (const char* explicitDir = std::getenv("SIGHTLINE_SHADER_CACHE"); explicitDir && *explicitDir)
    return explicitDir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return fs::path(xdg) / "sightline" / "shaders";
  if (const char* home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".cache" / "sightline" / "shaders";
  return {};
}

CompiledShader ShaderCompiler::compile(const fs::path& file, const ShaderDefines& defines) {
  initializeGlslangOnce();
  const fs::path path = shaderDirectory_ / file;
  const EShLanguage stage = stageFromExtension(file);
  const auto source = readText(path);
  if (!source) throw ShaderCompileError(path.string() + ": cannot read shader file");

  std::string preamble;
  for (const auto& [name, value] : defines) preamble += "#define " + name + " " + value + "\n";
  const std::string pathName = path.string();
  const char* sourceText = source->c_str();
  const int sourceLength = static_cast<int>(source->size());
  const char* sourceName = pathName.c_str();
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  const TBuiltInResource* resources = GetDefaultResources();

  // Preprocessing finds every included file (cheap), so the key covers them all.
  RecordingIncluder includer(shaderDirectory_);
  glslang::TShader preprocessor(stage);
  preprocessor.setStringsWithLengthsAndNames(&sourceText, &sourceLength, &sourceName, 1);
  preprocessor.setPreamble(preamble.c_str());
  configure(preprocessor, stage);
  std::string preprocessed;
  if (!preprocessor.preprocess(resources, 460, ENoProfile, false, false, messages, &preprocessed,
                               includer)) {
    throw ShaderCompileError("shader preprocessing failed:\n" +
                             std::string(preprocessor.getInfoLog()));
  }
  Fnv1a key;
  key.add(std::to_string(static_cast<int>(stage)));
  key.add(*source);
  for (const std::string& included : includer.included()) key.add(included);
  key.add(preamble);
  key.add(std::to_string(GLSLANG_VERSION_MAJOR) + "." + std::to_string(GLSLANG_VERSION_MINOR) +
          "." + std::to_string(GLSLANG_VERSION_PATCH) + GLSLANG_VERSION_FLAVOR + " vk1.2 spv1.4");

  CompiledShader result;
  result.cacheKey = key.value;
  char keyText[17];
  std::snprintf(keyText, sizeof keyText, "%016llx", static_cast<unsigned long long>(key.value));
  const fs::path cachePath =
      cacheDirectory_.empty() ? fs::path() : cacheDirectory_ / (std::string(keyText) + ".spv");
  if (!cachePath.empty()) {
    if (auto cached = readText(cachePath);
        cached && cached->size() >= 20 && cached->size() % 4 == 0) {
      result.spirv.resize(cached->size() / 4);
      std::memcpy(result.spirv.data(), cached->data(), cached->size());
      if (result.spirv[0] == kSpirvMagic) {
        result.fromCache = true;
        return result;
      }
      result.spirv.clear();
    }
  }

  RecordingIncluder compileIncluder(shaderDirectory_);
  glslang::TShader shader(stage);
  shader.setStringsWithLengthsAndNames(&sourceText, &sourceLength, &sourceName, 1);
  shader.setPreamble(preamble.c_str());
  configure(shader, stage);
  if (!shader.parse(resources, 460, false, messages, compileIncluder)) {
    throw ShaderCompileError("shader compile failed:\n" + std::string(shader.getInfoLog()));
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) {
    throw ShaderCompileError(pathName + ": shader link failed:\n" + program.getInfoLog());
  }
  glslang::SpvOptions options;
  options.generateDebugInfo = false;
  options.disableOptimizer = false;
  options.validate = false;
  spv::SpvBuildLogger logger;
  glslang::GlslangToSpv(*program.getIntermediate(stage), result.spirv, &logger, &options);
  if (result.spirv.empty()) throw ShaderCompileError(pathName + ": SPIR-V generation failed");

  if (!cachePath.empty()) {
    // Write then rename, so a concurrent reader never sees half a file.
    std::error_code error;
    fs::create_directories(cacheDirectory_, error);
    const fs::path temporary = cachePath.string() + ".tmp" + std::to_string(::getpid());
    {
      std::ofstream out(temporary, std::ios::binary);
      out.write(reinterpret_cast<const char*>(result.spirv.data()),
                static_cast<std::streamsize>(result.spirv.size() * 4));
    }
    fs::rename(temporary, cachePath, error);
    if (error) fs::remove(temporary, error);
  }
  return result;
}

}  // namespace render
