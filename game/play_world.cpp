#include "play_world.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <thread>

#include "core/error.h"
#include "core/log.h"
#include "core/paths.h"
#include "game_renderer.h"
#include "scene/block_atlas.h"
#include "world/connected_states.h"

namespace terrasol {
namespace {

// Threads in each world pool (chunk loading, meshing): 2, or 3 where there are cores to spare.
int workerThreads() {
  const int cores = static_cast<int>(std::thread::hardware_concurrency());
  return std::clamp(cores - 1, 2, 3);
}

}  // namespace

namespace {
PackStack defaultPack() {
  PackStack packs;
  packs.push(ResourcePack::open(resourcePackDir() / "default"));
  return packs;
}
}  // namespace

BlockContent::BlockContent(BlockRegistry registry)
    : blocks(std::move(registry)),
      defaultBake(bakeBlockModels(blocks, defaultPack())),
      shapes(blockShapesOf(blocks, *defaultBake)) {}

PlayWorld::Scratch::~Scratch() {
  std::error_code ec;
  if (!dir.empty()) std::filesystem::remove_all(dir, ec);
}

PlayWorld::PlayWorld(const std::filesystem::path& dir, bool scratch, std::uint64_t seed,
                     std::optional<std::uint64_t> requestedSeed, const BlockContent& content,
                     GameRenderer& renderer, int viewDistance, const std::filesystem::path& minecraft)
    : scratch_{scratch ? dir : std::filesystem::path()},
      content_(content),
      renderer_(renderer),
      world_(dir, seed, content.blocks, renderer.assets().table, viewDistance, workerThreads(),
             &content.shapes, minecraft),
      props_(world_.dir()) {
  const Level& level = world_.level();
  if (const MinecraftChunkSource* save = world_.minecraft()) {
    notice_ = "Minecraft save " + level.minecraft.string() + " (read-only); edits are kept in " +
              world_.dir().string();
    logInfo(notice_);
    for (const std::string& problem : save->problems()) logWarning(problem);
  }
  if (world_.isNew() && world_.minecraft()) {
    player_.teleport(world_.minecraft()->startPosition());
  } else if (world_.isNew()) {
    spawnPending_ = true;
    player_.teleport({0.5, 200.0, 0.5});
    logInfo("new world at " + world_.dir().string() + " (seed " + std::to_string(level.seed) + ")");
  } else {
    player_.teleport(level.playerPosition);
    player_.yaw = level.playerYaw;
    player_.pitch = level.playerPitch;
    player_.flying = level.playerFlying;  // a player saved in mid-air stays there
    logInfo("opened " + world_.dir().string());
    if (requestedSeed && *requestedSeed != level.seed) {
      logWarning("--seed " + std::to_string(*requestedSeed) + " ignored: the world has its own seed " +
                 std::to_string(level.seed));
    }
  }
  for (const LevelProp& prop : level.props) {
    try {
      props_.place(prop, world_.world(), world_.light(), true);  // dark until its chunks load
    } catch (const Error&) {
      // Kept in the level, undrawn; place() said why.
    }
  }
  renderer_.setPropNeeds(props_.placed().gpu().needs());
}

void PlayWorld::tick(const FrameInput& in, bool screenOpen, int ticks,
                     const std::function<void()>& afterTick) {
  MoveInput move;
  if (!screenOpen) {
    move.forward =
        static_cast<float>(in.isHeld(Action::Forward)) - static_cast<float>(in.isHeld(Action::Back));
    move.strafe = static_cast<float>(in.isHeld(Action::Right)) - static_cast<float>(in.isHeld(Action::Left));
    move.jump = in.isHeld(Action::Jump);
    move.sneak = in.isHeld(Action::Sneak);
    move.sprint = in.isHeld(Action::Sprint);
  }
  for (int i = 0; i < ticks; ++i) {
    player_.tick(world_.world(), move);
    if (player_.position().y < kMinY - 64)
      spawnPending_ = true;  // fell out of the world: back to the surface
    time_.tick(world_.level().time);
    if (afterTick) afterTick();
  }
}

void PlayWorld::jumpPressed(double now) {
  if (flightTap_.press(now)) player_.flying = !player_.flying;
}

int PlayWorld::stream(std::chrono::steady_clock::time_point deadline) {
  const glm::dvec3 p = player_.position();
  const ChunkPos centre = ChunkPos::of({static_cast<int>(std::floor(std::clamp(p.x, -3e7, 3e7))), 0,
                                        static_cast<int>(std::floor(std::clamp(p.z, -3e7, 3e7)))});
  std::vector<SectionPos> changed;
  for (const SectionMesh& mesh : world_.update(centre, deadline)) {
    renderer_.upload(mesh);
    changed.push_back(mesh.pos);
  }
  if (!changed.empty()) props_.placed().relightNear(changed, world_.world(), world_.light());
  if (spawnPending_) {
    const int x = static_cast<int>(std::floor(p.x)), z = static_cast<int>(std::floor(p.z));
    if (const auto y = world_.surfaceY(x, z)) {
      player_.teleport({x + 0.5, *y + 1.0, z + 0.5});
      spawnPending_ = false;
    }
  }
  return static_cast<int>(changed.size());
}

bool PlayWorld::editBlock(const BlockPos& pos, BlockId state) {
  const BlockId before = world_.world().getBlock(pos);
  if (!world_.setBlock(pos, state)) return false;
  changes_.push_back({pos, before, state});
  edits_.push_back({pos, content_.blocks.stateName(state)});
  for (const auto& [at, connected] : connectionUpdates(world_.world(), pos)) {
    if (world_.setBlock(at, connected)) edits_.push_back({at, content_.blocks.stateName(connected)});
  }
  return true;
}

void PlayWorld::placeProp(const LevelProp& prop) {
  props_.place(prop, world_.world(), world_.light());
  renderer_.setPropNeeds(props_.placed().gpu().needs());
}

void PlayWorld::removeProp(int index) {
  props_.remove(index);
  renderer_.setPropNeeds(props_.placed().gpu().needs());
}

std::vector<std::string> PlayWorld::propFiles() const {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(world_.dir() / "props", ec)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".gltf" || ext == ".glb")) {
      files.push_back((std::filesystem::path("props") / entry.path().filename()).string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

bool PlayWorld::ready() const {
  const WorldCounts c = world_.counts();
  return !spawnPending_ && c.loaded > 0 && c.pending == 0 && c.meshDirty == 0 && c.meshInFlight == 0;
}

void PlayWorld::save() {
  Level& level = world_.level();
  level.playerPosition = player_.position();
  level.playerYaw = player_.yaw;
  level.playerPitch = player_.pitch;
  level.playerFlying = player_.flying;
  level.props = props_.level();
  try {
    world_.save();
    logInfo("saved " + world_.dir().string());
  } catch (const std::exception& e) {
    logError(std::string("saving failed: ") + e.what());
  }
}

}  // namespace terrasol
