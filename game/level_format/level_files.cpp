#include <algorithm>
#include <cctype>
#include <string>
#include <system_error>

#include "game/level_format/level_reader.hpp"
#include "game/texture_file.hpp"

// LevelReader's file handling: the path rules, and the textures and source files of a level.
namespace game::level_format {

namespace fs = std::filesystem;

namespace {

bool isInside(const fs::path& file, const fs::path& directory) {
  const fs::path relative = file.lexically_relative(directory);
  return !relative.empty() && *relative.begin() != ".." && relative != ".";
}

}  // namespace

// The asset root: the first existing directory of options_.assetRoots, or by default the
// "assets" directory beside the level's directory (levels/x.json -> assets/).
std::optional<fs::path> LevelReader::assetRoot() const {
  std::vector<fs::path> candidates = options_.assetRoots;
  if (candidates.empty()) candidates.push_back(levelDirectory_ / ".." / "assets");
  for (const fs::path& candidate : candidates) {
    std::error_code error;
    if (fs::is_directory(candidate, error)) return candidate.lexically_normal();
  }
  return std::nullopt;
}

// Applies the path rules of docs/LEVELS.md ("Paths") to the string at `pointer`: relative to
// the level file or starting with "assets/", and after following symbolic links still inside
// the level's directory or the asset root.
ResolvedFile LevelReader::resolveFile(const OrderedJson& value, const std::string& pointer,
                                      const std::string& kind,
                                      const std::vector<std::string>& extensions) const {
  const std::string& text = readString(value, pointer, 1, kMaxStringCharacters);
  const std::string quotedText = "\"" + text + "\"";
  if (text.find('%') != std::string::npos) {
    failValue(pointer, kind + " path " + quotedText +
                           " contains '%': percent-encoding is not supported; write the file "
                           "name as it is on disk");
  }
  if (text.find('\\') != std::string::npos) {
    failValue(pointer, kind + " path " + quotedText +
                           " contains a backslash; separate directories with '/'");
  }
  const bool driveLetter =
      text.size() >= 2 && std::isalpha(static_cast<unsigned char>(text[0])) && text[1] == ':';
  if (text.front() == '/' || driveLetter || fs::path(text).has_root_path()) {
    failValue(pointer, kind + " path " + quotedText +
                           " is absolute; write it relative to the level file or starting "
                           "with \"assets/\"");
  }
  const std::optional<fs::path> assets = assetRoot();
  const std::string assetPrefix = "assets/";
  fs::path base = levelDirectory_;
  std::string relative = text;
  if (text.rfind(assetPrefix, 0) == 0) {
    if (!assets) {
      failValue(pointer, kind + " path " + quotedText +
                             " names the asset directory, but there is none (looked for " +
                             describeAssetRootCandidates() + ")");
    }
    base = *assets;
    relative = text.substr(assetPrefix.size());
  }
  const fs::path lexical = (base / relative).lexically_normal();

  // Canonical forms follow symbolic links; a file is allowed in either directory tree. Both
  // sides are made absolute first: weakly_canonical keeps a path relative when no prefix of
  // it exists, while the roots always exist.
  std::error_code error;
  const fs::path canonicalFile = fs::weakly_canonical(fs::absolute(lexical), error);
  std::vector<fs::path> allowedRoots;
  if (!error) {
    for (const auto& directory : {std::optional<fs::path>(levelDirectory_), assets}) {
      if (!directory) continue;
      std::error_code rootError;
      const fs::path canonicalRoot = fs::weakly_canonical(fs::absolute(*directory), rootError);
      if (!rootError) allowedRoots.push_back(canonicalRoot);
    }
  }
  const auto root = std::find_if(allowedRoots.begin(), allowedRoots.end(),
                                 [&](const fs::path& r) { return isInside(canonicalFile, r); });
  if (error || root == allowedRoots.end()) {
    const bool lexicallyInside =
        isInside(lexical, base.lexically_normal()) ||
        (base.lexically_normal() == "." && !lexical.empty() && *lexical.begin() != "..");
    failValue(pointer, kind + " path " + quotedText +
                           (lexicallyInside ? " leads outside the level's directory and the "
                                              "asset directory through a symbolic link"
                                            : " leaves the level's directory and the asset "
                                              "directory"));
  }
  const std::string extension = toLower(fs::path(text).extension().string());
  if (std::find(extensions.begin(), extensions.end(), extension) == extensions.end()) {
    std::string list;
    for (std::size_t i = 0; i < extensions.size(); ++i) {
      list += (i == 0 ? "" : i + 1 == extensions.size() ? " or " : ", ") + extensions[i];
    }
    expected(value, pointer, "a path to a " + list + " file");
  }

  std::error_code existsError;
  if (!fs::is_regular_file(canonicalFile, existsError)) {
    failValue(pointer,
              kind + " file " + quotedText + " not found (looked for " + lexical.string() + ")");
  }
  return {lexical, *root};
}

std::string LevelReader::describeAssetRootCandidates() const {
  std::vector<std::string> names;
  if (options_.assetRoots.empty()) {
    names.push_back((levelDirectory_ / ".." / "assets").lexically_normal().string());
  }
  for (const fs::path& candidate : options_.assetRoots) names.push_back(candidate.string());
  return joinQuoted(names);
}

void LevelReader::addSourceFile(Level& level, const fs::path& file) const {
  if (std::find(level.sourceFiles.begin(), level.sourceFiles.end(), file) ==
      level.sourceFiles.end()) {
    level.sourceFiles.push_back(file);
  }
}

// The index in level.textures of the texture at `pointer`, loading each file once.
int32_t LevelReader::readTexture(const OrderedJson& value, const std::string& pointer, bool srgb,
                                 Level& level) {
  const ResolvedFile file = resolveFile(value, pointer, "texture", {".png", ".jpg", ".jpeg"});
  std::error_code error;
  const std::pair<fs::path, bool> key{fs::weakly_canonical(file.path, error), srgb};
  if (const auto found = textureIndices_.find(key); found != textureIndices_.end()) {
    return found->second;
  }
  if (level.textures.size() >= kMaxTextures) {
    failValue(pointer,
              "more than " + std::to_string(kMaxTextures) + " textures, the limit per level");
  }
  try {
    level.textures.push_back(loadTextureFile(file.path, srgb));
  } catch (const LevelError& problem) {
    failValue(pointer, problem.what());
  }
  addSourceFile(level, file.path);
  const auto index = static_cast<int32_t>(level.textures.size() - 1);
  textureIndices_.emplace(key, index);
  return index;
}

// A texture a glTF model brought, shared with an identical one already in the level (the
// same image file named by a material, or by another model).
int32_t LevelReader::addModelTexture(scene::TextureDesc texture, const std::string& pointer,
                                     Level& level) {
  for (std::size_t i = 0; i < level.textures.size(); ++i) {
    const scene::TextureDesc& existing = level.textures[i];
    if (existing.srgb == texture.srgb && existing.width == texture.width &&
        existing.height == texture.height && existing.rgba == texture.rgba) {
      return static_cast<int32_t>(i);
    }
  }
  if (level.textures.size() >= kMaxTextures) {
    failValue(pointer, "the model's texture \"" + texture.name + "\" makes more than " +
                           std::to_string(kMaxTextures) + " textures, the limit per level");
  }
  level.textures.push_back(std::move(texture));
  return static_cast<int32_t>(level.textures.size() - 1);
}

}  // namespace game::level_format
