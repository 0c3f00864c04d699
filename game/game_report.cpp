#include "game_report.h"

#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>

#include "core/error.h"

namespace terrasol {
namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kProbeBudget = std::chrono::milliseconds(4);  // light work between checks

}  // namespace

void writeReport(const std::filesystem::path& file, PlayWorld& world, const std::vector<BlockPos>& probes,
                 FrameCounts frames, Screen screen, const Hotbar& hotbar, const PipelineReport& pipeline) {
  const BlockRegistry& blocks = world.world().blocks();
  StreamedWorld& streamed = world.streamed();
  // Probes need their chunks: stream around each until it is loaded and lit (at most 30 s).
  nlohmann::json probed = nlohmann::json::array();
  for (const BlockPos& p : probes) {
    const auto deadline = Clock::now() + std::chrono::seconds(30);
    const ChunkPos chunk = ChunkPos::of(p);
    while (Clock::now() < deadline && !(world.world().isLoaded(chunk) && streamed.counts().pending == 0)) {
      streamed.update(chunk, Clock::now() + kProbeBudget);
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    const bool loaded = world.world().isLoaded(chunk);
    probed.push_back({{"pos", {p.x, p.y, p.z}},
                      {"loaded", loaded},
                      {"block", blocks.stateName(world.world().getBlock(p))},
                      {"block_light", world.light().lightAt(p, LightChannel::Block)},
                      {"sky_light", world.light().lightAt(p, LightChannel::Sky)}});
  }
  nlohmann::json props = nlohmann::json::array();
  for (int i = 0; i < static_cast<int>(world.props().placed().size()); ++i) {
    const LevelProp& prop = world.props().prop(i);
    const glm::vec2 light = world.props().placed().meanLight(i);
    props.push_back({{"model", prop.model},
                     {"position", {prop.position.x, prop.position.y, prop.position.z}},
                     {"light", {light.x, light.y}}});
  }
  nlohmann::json edits = nlohmann::json::array();
  for (const Edit& e : world.edits())
    edits.push_back({{"pos", {e.pos.x, e.pos.y, e.pos.z}}, {"block", e.block}});
  const Player& player = world.player();
  const glm::dvec3 p = player.position();
  nlohmann::json slots = nlohmann::json::array();
  for (const BlockId state : hotbar.slots()) slots.push_back(blocks.stateName(state));
  const nlohmann::json report = {{"world", streamed.dir().string()},
                                 {"time", world.level().time},
                                 {"frames", {{"drawn", frames.drawn}, {"minimised", frames.minimised}}},
                                 {"player",
                                  {{"position", {p.x, p.y, p.z}},
                                   {"yaw", player.yaw},
                                   {"pitch", player.pitch},
                                   {"flying", player.flying}}},
                                 {"screen", screen == Screen::Menu        ? "menu"
                                            : screen == Screen::Inventory ? "inventory"
                                                                          : "none"},
                                 {"hotbar", slots},
                                 {"shader_pack", pipeline.shaderPack},
                                 {"shader_pack_error", pipeline.shaderPackError},
                                 {"edits", edits},
                                 {"props", props},
                                 {"probes", probed}};
  writeFileAtomically(file, report.dump(2) + "\n");
}

}  // namespace terrasol
