#include "debug_overlay.h"

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <string>

#include "core/day_cycle.h"
#include "game_renderer.h"
#include "play_world.h"

namespace terrasol {
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

void DebugOverlay::frameTime(double seconds) {
  frameTimes_.push_back(seconds);
  double sum = 0.0;
  for (double t : frameTimes_) sum += t;
  while (sum > 1.0 && frameTimes_.size() > 1) {
    sum -= frameTimes_.front();
    frameTimes_.erase(frameTimes_.begin());
  }
}

void DebugOverlay::drawnFrameTime(double seconds) {
  constexpr std::size_t kGraphFrames = 240;
  graph_.push_back(static_cast<float>(seconds * 1000.0));
  if (graph_.size() > kGraphFrames) graph_.pop_front();
}

std::vector<std::string> DebugOverlay::left(const PlayWorld& world, const GameRenderer& renderer,
                                            const std::optional<LodTerrainStats>& far) const {
  double total = 0.0;
  for (double t : frameTimes_) total += t;
  const double frameMs = frameTimes_.empty() ? 0.0 : 1000.0 * total / static_cast<double>(frameTimes_.size());
  std::vector<std::string> out;
  out.push_back(
      format("Terrasol  %.0f fps (%.1f ms a frame)", frameMs > 0.0 ? 1000.0 / frameMs : 0.0, frameMs));
  std::string passes = "ms per pass:";
  for (const PassTiming& t : timings_) passes += format(" %s %.2f", t.pass.c_str(), t.ms);
  out.push_back(passes);
  const Player& player = world.player();
  const glm::dvec3 p = player.position();
  const BlockPos b = BlockPos::containing(p.x, p.y, p.z);
  out.push_back(format("XYZ: %.3f / %.5f / %.3f", p.x, p.y, p.z));
  out.push_back(format("Block: %d %d %d  [%d %d %d in chunk %d %d, section %d]", b.x, b.y, b.z, localOf(b.x),
                       localOf(b.y), localOf(b.z), chunkOf(b.x), chunkOf(b.z),
                       inWorldHeight(b.y) ? sectionOf(b.y) : -1));
  out.push_back(format("Facing: %s (%.1f / %.1f)", facingName(player.yaw), player.yaw, player.pitch));
  const BlockPos eye{b.x, static_cast<int>(std::floor(player.eye().y)), b.z};
  out.push_back(format("Light at the eye: %d block, %d sky", world.light().lightAt(eye, LightChannel::Block),
                       world.light().lightAt(eye, LightChannel::Sky)));
  out.push_back(format("%s%s%s",
                       player.flying       ? "flying"
                       : player.onGround() ? "on ground"
                                           : "in the air",
                       player.inWater() ? ", in water" : "", player.sprinting() ? ", sprinting" : ""));
  const std::int64_t t = world.level().time;
  out.push_back(format("Time: day %lld, %02lld:%02lld (tick %lld), x%d%s",
                       static_cast<long long>(t / kTicksPerDay),
                       static_cast<long long>((t % kTicksPerDay / 1000 + 6) % 24),
                       static_cast<long long>(t % 1000 * 60 / 1000), static_cast<long long>(t),
                       world.time().speed(), world.time().stopped() ? ", stopped" : ""));
  const WorldCounts c = world.streamed().counts();
  const FrameStats& f = renderer.lastFrame();
  out.push_back(format("Chunks: %zu loaded, %zu pending, %zu meshable", c.loaded, c.pending, c.meshable));
  out.push_back(format("Sections: %zu dirty, %zu meshing, %zu on GPU, %d drawn, %d culled, %d shadow casters",
                       c.meshDirty, c.meshInFlight, renderer.sectionsOnGpu(), f.sectionsDrawn,
                       f.sectionsCulled, f.shadowCasters));
  if (far) {
    out.push_back(format(
        "Far terrain: %d tiles in %d levels (%d to build), %d drawn, %lld triangles; %.1f MB CPU, "
        "%.1f MB GPU",
        far->tiles, far->levels, far->pending, f.lodTilesDrawn, static_cast<long long>(f.lodTrianglesDrawn),
        static_cast<double>(far->cachedBytes) / 1e6, static_cast<double>(renderer.lod().gpuBytes()) / 1e6));
  }
  return out;
}

std::vector<std::string> DebugOverlay::right(const PlayWorld& world, const GameSettings& settings,
                                             glm::ivec2 size, float scale,
                                             const std::optional<Target>& target) const {
  std::vector<std::string> out;
  out.push_back(format("Memory: %.0f MB resident", static_cast<double>(residentBytes()) / (1024.0 * 1024.0)));
  out.push_back("GL: " + glRenderer_);
  out.push_back(format("Display: %dx%d, view %d chunks, fov %.0f", size.x, size.y, settings.viewDistance,
                       settings.fov));
  const glm::ivec2 drawn = scaledRenderSize(size, scale);
  out.push_back(settings.targetFps > 0 ? format("Render scale: %.2f (%dx%d), dynamic for %d fps", scale,
                                                drawn.x, drawn.y, settings.targetFps)
                                       : format("Render scale: %.2f (%dx%d)", scale, drawn.x, drawn.y));
  const ShadowSettings& s = settings.shadow;
  out.push_back(s.enabled ? format("Shadows: %s %d^2, %.0f blocks, pcf %d",
                                   std::string(nameOf(s.mode, kShadowModes)).c_str(), s.resolution,
                                   s.distance, s.pcfSamples)
                          : std::string("Shadows: off"));
  out.push_back(format("Debug view (F4): %s", std::string(kDebugViews.nameOf(view_)).c_str()));
  if (target) {
    const BlockPos b = target->block;
    out.push_back(format("Targeted block: %d %d %d", b.x, b.y, b.z));
    out.push_back(world.world().blocks()[world.world().getBlock(b)].name);
    out.push_back(format("Light at its face: %d block, %d sky",
                         world.light().lightAt(target->place, LightChannel::Block),
                         world.light().lightAt(target->place, LightChannel::Sky)));
  }
  return out;
}

}  // namespace terrasol
