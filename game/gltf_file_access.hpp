#pragma once
// tinygltf's file-system and image callbacks, confined to one directory tree.
#include <filesystem>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace game::gltf {

// Confines tinygltf's file access to one directory tree. tinygltf only reads through these
// callbacks, so a path that escapes (via "..", an absolute URI or a symlink) is never opened.
struct FileAccessGuard {
  std::filesystem::path root;               // weakly canonical
  std::vector<std::string> refused;         // paths outside `root` that tinygltf wanted
  std::vector<std::filesystem::path> read;  // every file read, in order, for reload watching

  bool allows(const std::string& path) const;
  void refuse(const std::string& path);
};

// Callbacks that read only files `guard` allows, record them in it and write nothing.
tinygltf::FsCallbacks guardedFsCallbacks(FileAccessGuard& guard);

// Keeps each image's encoded bytes so that only the images the material uses get decoded, and
// by decodeTexture with its size limits. Images in buffer views are left for later: tinygltf
// hands them over without checking that the view lies inside its buffer.
bool keepEncodedImage(tinygltf::Image* image, int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*);

}  // namespace game::gltf
