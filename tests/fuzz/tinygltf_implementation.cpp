// tinygltf's implementation, compiled into the fuzzing build of the game library instead of
// linking Debian's libtinygltf, so that its parser is instrumented too: libFuzzer sees its
// branches and the sanitizers check its memory accesses. stb_image comes from libstb.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
