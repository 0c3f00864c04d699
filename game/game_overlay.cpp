#include "core/error.h"
#include "game_session.h"

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "platform/glfw/glfw_window.h"

// The F3 overlay's lines, and the --report written at exit.

namespace terrasol::session {
namespace {

std::size_t residentBytes() {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

const char* facingName(float yaw) {
  const float y = std::fmod(std::fmod(yaw, 360.0f) + 360.0f, 360.0f);
  if (y < 45.0f || y >= 315.0f) return "south (towards +Z)";
  if (y < 135.0f) return "west (towards -X)";
  if (y < 225.0f) return "north (towards -Z)";
  return "east (towards +X)";
}

}  // namespace

std::vector<std::string> Game::overlayLeft() const {
  double total = 0.0;
  for (double t : frameTimes_) total += t;
  const double frameMs = frameTimes_.empty() ? 0.0 : 1000.0 * total / static_cast<double>(frameTimes_.size());
  std::vector<std::string> out;
  out.push_back(format("Terrasol  %.0f fps (%.1f ms a frame)", frameMs > 0.0 ? 1000.0 / frameMs : 0.0, frameMs));
  std::string passes = "ms per pass:";
  for (const PassTiming& t : timings_) passes += format(" %s %.2f", t.pass.c_str(), t.ms);
  out.push_back(passes);
  const glm::dvec3 p = player_.position();
  const BlockPos b{static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)), static_cast<int>(std::floor(p.z))};
  out.push_back(format("XYZ: %.3f / %.5f / %.3f", p.x, p.y, p.z));
  out.push_back(format("Block: %d %d %d  [%d %d %d in chunk %d %d, section %d]", b.x, b.y, b.z, localOf(b.x),
                       localOf(b.y), localOf(b.z), chunkOf(b.x), chunkOf(b.z), inWorldHeight(b.y) ? sectionOf(b.y) : -1));
  out.push_back(format("Facing: %s (%.1f / %.1f)", facingName(player_.yaw), player_.yaw, player_.pitch));
  const BlockPos eye{b.x, static_cast<int>(std::floor(player_.eye().y)), b.z};
  out.push_back(format("Light at the eye: %d block, %d sky", world_.light().lightAt(eye, LightChannel::Block),
                       world_.light().lightAt(eye, LightChannel::Sky)));
  out.push_back(format("%s%s%s", player_.flying ? "flying" : player_.onGround() ? "on ground" : "in the air",
                       player_.inWater() ? ", in water" : "", player_.sprinting() ? ", sprinting" : ""));
  const std::int64_t t = world_.level().time;
  out.push_back(format("Time: day %lld, %02lld:%02lld (tick %lld), x%d%s", static_cast<long long>(t / 24000),
                       static_cast<long long>((t % 24000 / 1000 + 6) % 24), static_cast<long long>(t % 1000 * 60 / 1000),
                       static_cast<long long>(t), kTimeSpeeds[timeSpeed_], timeStopped_ ? ", stopped" : ""));
  const WorldCounts c = world_.counts();
  const FrameStats& f = renderer_.lastFrame();
  out.push_back(format("Chunks: %zu loaded, %zu pending, %zu meshable", c.loaded, c.pending, c.meshable));
  out.push_back(format("Sections: %zu dirty, %zu meshing, %zu on GPU, %d drawn, %d culled, %d shadow casters",
                       c.meshDirty, c.meshInFlight, renderer_.sectionsOnGpu(), f.sectionsDrawn, f.sectionsCulled,
                       f.shadowCasters));
  return out;
}

std::vector<std::string> Game::overlayRight() const {
  std::vector<std::string> out;
  out.push_back(format("Memory: %.0f MB resident", static_cast<double>(residentBytes()) / (1024.0 * 1024.0)));
  out.push_back("GL: " + glRenderer_);
  const glm::ivec2 size = drawableSize();
  out.push_back(format("Display: %dx%d, view %d chunks, fov %.0f", size.x, size.y, settings_.viewDistance, settings_.fov));
  const float scale = settings_.targetFps > 0 ? resolution_.scale() : settings_.renderScale;
  const glm::ivec2 drawn = scaledRenderSize(size, scale);
  out.push_back(settings_.targetFps > 0
                    ? format("Render scale: %.2f (%dx%d), dynamic for %d fps", scale, drawn.x, drawn.y, settings_.targetFps)
                    : format("Render scale: %.2f (%dx%d)", scale, drawn.x, drawn.y));
  const ShadowSettings& s = settings_.shadow;
  out.push_back(s.enabled ? format("Shadows: %s %d^2, %.0f blocks, pcf %d", std::string(nameOf(s.mode, kShadowModes)).c_str(),
                                   s.resolution, s.distance, s.pcfSamples)
                          : std::string("Shadows: off"));
  out.push_back(format("Debug view (F4): %s", std::string(kDebugViews[static_cast<std::size_t>(debugView_)]).c_str()));
  if (target_) {
    const BlockPos b = target_->block;
    out.push_back(format("Targeted block: %d %d %d", b.x, b.y, b.z));
    out.push_back(blocks_[world_.world().getBlock(b)].name);
    out.push_back(format("Light at its face: %d block, %d sky", world_.light().lightAt(target_->place, LightChannel::Block),
                         world_.light().lightAt(target_->place, LightChannel::Sky)));
  }
  return out;
}

void Game::writeReport() {
  if (options_.report.empty()) return;
  // Probes need their chunks: stream around each until it is loaded and lit (at most 30 s).
  nlohmann::json probes = nlohmann::json::array();
  for (const BlockPos& p : options_.probes) {
    const auto deadline = Clock::now() + std::chrono::seconds(30);
    const ChunkPos chunk = ChunkPos::of(p);
    while (Clock::now() < deadline && !(world_.world().isLoaded(chunk) && world_.counts().pending == 0)) {
      world_.update(chunk, Clock::now() + kWorldBudget);
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    const bool loaded = world_.world().isLoaded(chunk);
    probes.push_back({{"pos", {p.x, p.y, p.z}},
                      {"loaded", loaded},
                      {"block", blocks_.stateName(world_.world().getBlock(p))},
                      {"block_light", world_.light().lightAt(p, LightChannel::Block)},
                      {"sky_light", world_.light().lightAt(p, LightChannel::Sky)}});
  }
  nlohmann::json props = nlohmann::json::array();
  for (int i = 0; i < static_cast<int>(props_->placed().size()); ++i) {
    const LevelProp& prop = props_->prop(i);
    const glm::vec2 light = props_->placed().meanLight(i);
    props.push_back({{"model", prop.model},
                     {"position", {prop.position.x, prop.position.y, prop.position.z}},
                     {"light", {light.x, light.y}}});
  }
  nlohmann::json edits = nlohmann::json::array();
  for (const Edit& e : edits_) edits.push_back({{"pos", {e.pos.x, e.pos.y, e.pos.z}}, {"block", e.block}});
  const glm::dvec3 p = player_.position();
  nlohmann::json hotbar = nlohmann::json::array();
  for (const BlockId state : hotbar_) hotbar.push_back(blocks_.stateName(state));
  const nlohmann::json report = {
      {"world", world_.dir().string()},
      {"time", world_.level().time},
      {"frames", {{"drawn", framesDrawn_}, {"minimised", framesHidden_}}},
      {"player", {{"position", {p.x, p.y, p.z}}, {"yaw", player_.yaw}, {"pitch", player_.pitch}, {"flying", player_.flying}}},
      {"screen", menuOpen_ ? "menu" : inventoryOpen_ ? "inventory" : "none"},
      {"hotbar", hotbar},
      {"edits", edits},
      {"props", props},
      {"probes", probes}};
  writeFileAtomically(options_.report, report.dump(2) + "\n");
}

}  // namespace terrasol::session
