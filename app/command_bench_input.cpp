// bench-input: how long each reader of strangers' files (level, replay, settings, progress,
// glTF) takes on worst-shaped inputs at 1x, 4x and 16x size. The ratios show whether reading
// grows linearly (4 and 16) or worse; docs/ROBUSTNESS.md keeps the figures.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "game/gltf_mesh.hpp"
#include "game/json_document.hpp"
#include "game/level_loader.hpp"
#include "game/progress.hpp"
#include "game/replay.hpp"
#include "game/settings.hpp"

namespace app {
namespace fs = std::filesystem;

namespace {

// One reader: reads `text` (as its file would hold it) and returns; what it decides about the
// text (loaded, refused with a message) does not matter here, only how long it took.
using Reader = std::function<void(const std::string& text)>;

// Writes `text` to `file` for the readers that read files.
void writeText(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
}

Reader levelReader() {
  return [](const std::string& text) {
    try {
      game::parseLevel(text, "bench/level.json");
    } catch (const game::LevelError&) {
    }
  };
}

Reader replayReader() {
  return [](const std::string& text) {
    try {
      game::parseReplay(text, "bench/replay.json");
    } catch (const game::ReplayError&) {
    }
  };
}

Reader settingsReader(const fs::path& directory) {
  return [directory](const std::string& text) {
    writeText(directory / "settings.json", text);
    game::loadSettings(directory / "settings.json");
  };
}

Reader progressReader(const fs::path& directory) {
  return [directory](const std::string& text) {
    writeText(directory / "progress.json", text);
    game::loadProgress(directory / "progress.json");
  };
}

Reader gltfReader(const fs::path& directory) {
  return [directory](const std::string& text) {
    writeText(directory / "model.gltf", text);
    try {
      game::loadGltfModel(directory / "model.gltf", directory);
    } catch (const game::LevelError&) {
    }
  };
}

// The worst shapes, `count` units each, as JSON values.
std::string deepBlocks(std::size_t count) {
  // Blocks nested as deep as a file may (kMaxJsonNesting, less the file's own two levels).
  const std::size_t depth = game::kMaxJsonNesting - 2;
  std::string block = std::string(depth, '[') + std::string(depth, ']');
  std::string text = "[";
  for (std::size_t i = 0; i < count / 16; ++i) text += (i ? "," : "") + block;
  return text + "]";
}

std::string manyKeys(std::size_t count) {
  std::string text = "{";
  for (std::size_t i = 0; i < count; ++i) text += (i ? ",\"k" : "\"k") + std::to_string(i) + "\":0";
  return text + "}";
}

std::string longString(std::size_t count) {
  return "\"" + std::string(count * 8, 'x') + "\"";
}

std::string manyNumbers(std::size_t count) {
  std::string text = "[";
  for (std::size_t i = 0; i < count; ++i) text += (i ? "," : "") + std::to_string(i) + ".5";
  return text + "]";
}

// Long keys over deep nesting, then many values: what a position index of full JSON pointers
// could not hold.
std::string longKeysDeep(std::size_t count) {
  const std::string key = "\"" + std::string(200, 'k') + "\":";
  std::string text;
  for (int i = 0; i < 40; ++i) text += "{" + key;
  text += manyNumbers(count);
  return text + std::string(40, '}');
}

struct Shape {
  std::string name;
  std::function<std::string(std::size_t count)> text;
};

// The generic shapes placed in a file at `before` ... `after` (where the reader looks).
std::vector<Shape> genericShapes(const std::string& before, const std::string& after) {
  std::vector<Shape> shapes;
  const std::vector<Shape> values = {{"deep nesting", deepBlocks},
                                     {"many keys", manyKeys},
                                     {"long string", longString},
                                     {"long array of numbers", manyNumbers},
                                     {"long keys over deep nesting", longKeysDeep}};
  for (const Shape& value : values) {
    const std::function<std::string(std::size_t)> text = value.text;
    shapes.push_back({value.name, [before, after, text](std::size_t count) {
                        return before + text(count) + after;
                      }});
  }
  return shapes;
}

const char* const kLevelStart =
    "{\"format\": 1, \"name\": \"Bench\", \"camera\": {\"position\": [0, 1, 5]}, "
    "\"meshes\": {\"cube\": {\"box\": {\"size\": [1, 1, 1]}}}, \"lights\": {}, "
    "\"materials\": {\"grey\": {\"color\": [0.5, 0.5, 0.5]}}, ";

std::string manyEntities(std::size_t count) {
  std::string text = std::string(kLevelStart) + "\"entities\": {";
  for (std::size_t i = 0; i < count; ++i) {
    text += (i ? ",\"e" : "\"e") + std::to_string(i) +
            "\": {\"mesh\": \"cube\", \"material\": \"grey\", \"position\": [" +
            std::to_string(i % 100) + ", 0, " + std::to_string(i / 100) + "]}";
  }
  return text + "}}";
}

std::string manyInputEvents(std::size_t count) {
  std::string text =
      "{\"replay\": 1, \"level\": \"level.json\", \"ticks\": " + std::to_string(count + 1) +
      ", \"input\": [";
  for (std::size_t i = 0; i < count; ++i) {
    text += (i ? "," : "") + std::string("{\"tick\": ") + std::to_string(i) +
            ", \"move\": [0, 1], \"look\": [0.5, 0]}";
  }
  return text + "], \"expect\": {\"outcome\": \"playing\"}}";
}

std::string manyBindings(std::size_t count) {
  std::string text = "{\"settings\": 1, \"key_bindings\": {";
  for (std::size_t i = 0; i < count; ++i)
    text += (i ? ",\"action" : "\"action") + std::to_string(i) + "\": \"W\"";
  return text + "}}";
}

std::string manyCompleted(std::size_t count) {
  std::string text = "{\"progress\": 1, \"completed\": [";
  for (std::size_t i = 0; i < count; ++i)
    text += (i ? ",\"level_" : "\"level_") + std::to_string(i) + ".json\"";
  return text + "]}";
}

// The best of three readings of `text`, in milliseconds.
double bestMilliseconds(const Reader& reader, const std::string& text) {
  double best = 1e30;
  for (int run = 0; run < 3; ++run) {
    const auto start = std::chrono::steady_clock::now();
    reader(text);
    const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
    best = std::min(best, took.count());
  }
  return best;
}

}  // namespace

int commandBenchInput(const Options&) {
  const fs::path directory =
      fs::temp_directory_path() / ("sightline-bench-input-" + std::to_string(getpid()));
  fs::create_directories(directory);
  struct Row {
    std::string reader;
    Reader read;
    std::vector<Shape> shapes;
    std::size_t baseCount;
  };
  std::vector<Row> rows = {
      {"level", levelReader(),
       genericShapes(std::string(kLevelStart) + "\"entities\": {}, \"x\": ", "}"), 16384},
      {"level", levelReader(), {{"many entities", manyEntities}}, 256},
      {"replay", replayReader(), genericShapes("{\"replay\": 1, \"input\": ", "}"), 16384},
      {"replay", replayReader(), {{"many input events", manyInputEvents}}, 4096},
      {"settings", settingsReader(directory),
       genericShapes("{\"settings\": 1, \"key_bindings\": ", "}"), 4096},
      {"settings", settingsReader(directory), {{"many unknown actions", manyBindings}}, 2048},
      {"progress", progressReader(directory),
       genericShapes("{\"progress\": 1, \"completed\": ", "}"), 4096},
      {"progress", progressReader(directory), {{"many completed levels", manyCompleted}}, 2048},
      {"glTF", gltfReader(directory),
       genericShapes("{\"asset\": {\"version\": \"2.0\"}, \"extras\": ", "}"), 16384},
  };
  std::printf("Each reader on worst-shaped input at 1x, 4x and 16x the size; best of 3 runs.\n");
  std::printf("Linear growth gives ratios near 4 and 16. Sizes stay under each format's limit\n");
  std::printf("(levels, replays 16 MiB; settings, progress 1 MiB; glTF 256 MiB).\n");
  std::printf("%-9s %-28s %10s %9s %9s %9s %6s %6s\n", "reader", "shape", "1x bytes", "1x ms",
              "4x ms", "16x ms", "4x/1x", "16x/1x");
  for (const Row& row : rows) {
    for (const Shape& shape : row.shapes) {
      double milliseconds[3] = {};
      std::size_t baseBytes = 0;
      for (int scale = 0; scale < 3; ++scale) {
        const std::string text = shape.text(row.baseCount << (2 * scale));
        if (scale == 0) baseBytes = text.size();
        milliseconds[scale] = bestMilliseconds(row.read, text);
      }
      std::printf("%-9s %-28s %10zu %9.2f %9.2f %9.2f %6.1f %6.1f\n", row.reader.c_str(),
                  shape.name.c_str(), baseBytes, milliseconds[0], milliseconds[1], milliseconds[2],
                  milliseconds[1] / milliseconds[0], milliseconds[2] / milliseconds[0]);
      std::fflush(stdout);
    }
  }
  std::error_code ignored;
  fs::remove_all(directory, ignored);
  return 0;
}

}  // namespace app
