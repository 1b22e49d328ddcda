#pragma once
#include <filesystem>
#include <vector>

namespace app {

// The directory holding shaders/, levels/ and assets/: $SIGHTLINE_DATA_DIR, else next to the
// installed binary (../share/sightline), else the source tree the binary was built from.
std::filesystem::path findDataRoot();

// The shipped levels in play order: levels/order.txt when it exists, else levels/*.json by
// file name (the schema is not a level).
std::vector<std::filesystem::path> shippedLevels(const std::filesystem::path& dataRoot);

}  // namespace app
