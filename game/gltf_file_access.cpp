#include "game/gltf_file_access.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>

namespace game::gltf {

namespace {

namespace fs = std::filesystem;

// Guards against memory exhaustion from a hostile or broken asset.
constexpr std::uintmax_t kMaxModelFileBytes = 256u << 20;

bool guardedFileExists(const std::string& path, void* userData) {
  auto& guard = *static_cast<FileAccessGuard*>(userData);
  std::error_code error;
  const bool exists = fs::is_regular_file(path, error);
  if (!guard.allows(path)) {
    // tinygltf also probes the working directory for missing files; only a file that really
    // exists out there means the model tried to reach outside.
    if (exists) guard.refuse(path);
    return false;
  }
  return exists;
}

// tinygltf's default would run wordexp on paths taken from the model; keep them literal.
std::string literalPath(const std::string& path, void*) {
  return path;
}

bool guardedReadFile(std::vector<unsigned char>* contents, std::string* error,
                     const std::string& path, void* userData) {
  auto& guard = *static_cast<FileAccessGuard*>(userData);
  if (!guard.allows(path)) {
    guard.refuse(path);
    if (error) *error = "outside the allowed directory";
    return false;
  }
  std::error_code sizeError;
  const std::uintmax_t size = fs::file_size(path, sizeError);
  if (sizeError || size > kMaxModelFileBytes) {
    if (error) *error = sizeError ? sizeError.message() : "file is larger than 256 MiB";
    return false;
  }
  std::ifstream stream(path, std::ios::binary);
  contents->resize(static_cast<std::size_t>(size));
  if (!stream ||
      !stream.read(reinterpret_cast<char*>(contents->data()), static_cast<std::streamsize>(size))) {
    if (error) *error = "cannot read file";
    return false;
  }
  const fs::path readPath = fs::path(path).lexically_normal();
  if (std::find(guard.read.begin(), guard.read.end(), readPath) == guard.read.end()) {
    guard.read.push_back(readPath);
  }
  return true;
}

bool refuseWrite(std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
  if (error) *error = "writing files is disabled";
  return false;
}

}  // namespace

bool FileAccessGuard::allows(const std::string& path) const {
  std::error_code error;
  const fs::path resolved = fs::weakly_canonical(fs::path(path), error);
  if (error) return false;
  const fs::path relative = resolved.lexically_relative(root);
  return !relative.empty() && *relative.begin() != "..";
}

void FileAccessGuard::refuse(const std::string& path) {
  if (std::find(refused.begin(), refused.end(), path) == refused.end()) refused.push_back(path);
}

tinygltf::FsCallbacks guardedFsCallbacks(FileAccessGuard& guard) {
  return {&guardedFileExists, &literalPath, &guardedReadFile, &refuseWrite, &guard};
}

bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  if (image->bufferView >= 0) return true;
  image->image.assign(bytes, bytes + std::max(size, 0));
  image->as_is = true;
  return true;
}

}  // namespace game::gltf
