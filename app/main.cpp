// `sightline`: the program entry. Composes the game (levels) and the renderer (Vulkan).
#include <cstdio>
#include <exception>

#include "app/commands.hpp"
#include "app/options.hpp"
#include "game/level_loader.hpp"
#include "game/replay.hpp"
#include "render/shader_compiler.hpp"

int main(int argc, char** argv) {
  try {
    const app::Options options = app::parseOptions(argc, argv);
    if (options.help) {
      std::fputs(app::commandUsage(options.command).c_str(), stdout);
      return 0;
    }
    if (options.command == "version") return app::commandVersion();
    if (options.command == "render") return app::commandRender(options);
    if (options.command == "play") return app::commandPlay(options);
    if (options.command == "bench") return app::commandBench(options);
    if (options.command == "validate") return app::commandValidate(options);
    if (options.command == "devices") return app::commandDevices();
    if (options.command == "preview") return app::commandPreview(options);
    if (options.command == "info") return app::commandInfo(options);
    if (options.command == "bench-quality") return app::commandBenchQuality(options);
    if (options.command == "bench-upscale") return app::commandBenchUpscale(options);
    if (options.command == "replay") return app::commandReplay(options);
    if (options.command == "campaign") return app::commandCampaign(options);
    if (options.command == "soak") return app::commandSoak(options);
    if (options.command == "bench-input") return app::commandBenchInput(options);
    if (options.command == "help") {
      std::fputs(app::usage().c_str(), stdout);
      return 0;
    }
    throw app::UsageError("unknown command '" + options.command + "'");
  } catch (const app::UsageError& error) {
    // After the mistake, what the command takes (or which commands there are).
    const std::string command = argc > 1 ? argv[1] : "";
    std::fprintf(stderr, "sightline: %s\n\n%s", error.what(), app::commandUsage(command).c_str());
    return 2;
  } catch (const game::ReplayError& error) {
    std::fprintf(stderr, "%s\n", error.what());
    return 1;
  } catch (const game::LevelError& error) {
    std::fprintf(stderr, "%s\n", error.what());
    return 1;
  } catch (const render::ShaderCompileError& error) {
    std::fprintf(stderr, "sightline: %s\n", error.what());
    return 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "sightline: %s\n", error.what());
    return 1;
  }
}
