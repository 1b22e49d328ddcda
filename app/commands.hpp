#pragma once
// The `sightline` subcommands; each returns the process exit status.
#include "app/options.hpp"

namespace app {

int commandPlay(const Options& options);
int commandRender(const Options& options);
int commandPreview(const Options& options);
int commandBench(const Options& options);
int commandBenchQuality(const Options& options);
int commandBenchUpscale(const Options& options);
int commandValidate(const Options& options);
int commandInfo(const Options& options);
int commandDevices();
int commandVersion();  // the version and the Vulkan device the game would use
int commandReplay(const Options& options);
int commandCampaign(const Options& options);
int commandSoak(const Options& options);
int commandBenchInput(const Options& options);

}  // namespace app
