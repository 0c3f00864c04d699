#pragma once
// --report FILE: what a run did, as JSON written at exit for tests and tools: the world and its time,
// frames drawn and minimised, the player, the open screen, the hotbar, every edit, the props with
// their light, and the probed blocks with theirs (their chunks are loaded first, at most 30 s each).

#include <filesystem>
#include <string>
#include <vector>

#include "hotbar.h"
#include "input_router.h"
#include "play_world.h"

namespace terrasol {

struct FrameCounts {
  int drawn = 0, minimised = 0;
};

// Which pipeline drew: the shader pack's name (empty: Terrasol's), and a chosen pack's error.
struct PipelineReport {
  std::string shaderPack, shaderPackError;
};

void writeReport(const std::filesystem::path& file, PlayWorld& world, const std::vector<BlockPos>& probes,
                 FrameCounts frames, Screen screen, const Hotbar& hotbar, const PipelineReport& pipeline);

}  // namespace terrasol
