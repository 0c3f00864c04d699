#pragma once
// The world as the game plays it: the streamed, saved world with its props, the player's body in it,
// the world's clock and the edits the player made (for --report). Opens a save or makes a new world,
// streams it round the player each frame and saves it. GL thread only (props and meshes go to the GPU).

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "controls.h"
#include "game_props.h"
#include "pipeline/streamed_world.h"
#include "player.h"
#include "scene/block_atlas.h"
#include "time_controls.h"
#include "world/block_shapes.h"

namespace terrasol {

class GameRenderer;

// The blocks the game knows and their collision shapes (from the default pack's models: resource
// packs do not change collision).
struct BlockContent {
  explicit BlockContent(BlockRegistry registry);
  BlockRegistry blocks;
  // The default pack's models baked, for the shapes and the first atlas; released once that is made.
  std::optional<BlockModelBake> defaultBake;
  BlockShapes shapes;
};

struct Edit {
  BlockPos pos;
  std::string block;  // its state's name
};

// A cell the player changed (not the neighbours that joined it), for what is heard.
struct StateChange {
  BlockPos pos;
  BlockId before = kAir, after = kAir;
};

class PlayWorld {
 public:
  // Opens `dir`, or creates it with `seed`; a saved player stands where they were, a new world's
  // drops onto its surface once the ground there is loaded. A `scratch` world's folder is deleted
  // with it. `content` must outlive this.
  // `minecraft`: the Minecraft save a new `dir` overlays (world_choice.h); a new overlay's player starts
  // where the save's player stands (else at its spawn, else over the middle of its chunks).
  PlayWorld(const std::filesystem::path& dir, bool scratch, std::uint64_t seed,
            std::optional<std::uint64_t> requestedSeed, const BlockContent& content, GameRenderer& renderer,
            int viewDistance, const std::filesystem::path& minecraft = {});

  // Said once when the world opens, for the HUD (empty for Terrasol's own worlds).
  const std::string& notice() const { return notice_; }

  StreamedWorld& streamed() { return world_; }
  const StreamedWorld& streamed() const { return world_; }
  const World& world() const { return world_.world(); }
  const LightEngine& light() const { return world_.light(); }
  Level& level() { return world_.level(); }
  const Level& level() const { return world_.level(); }
  Player& player() { return player_; }
  const Player& player() const { return player_; }
  GameProps& props() { return props_; }
  const GameProps& props() const { return props_; }
  TimeControls& time() { return time_; }
  const TimeControls& time() const { return time_; }
  const std::vector<Edit>& edits() const { return edits_; }
  // The player's changes since the last call.
  std::vector<StateChange> takeStateChanges() { return std::exchange(changes_, {}); }

  // `ticks` game ticks of the player moving by `input` (nothing held while a screen is open) and of
  // the world's clock; `afterTick` runs after each.
  void tick(const FrameInput& input, bool screenOpen, int ticks, const std::function<void()>& afterTick = {});
  // A jump press at game time `now`: two in quick succession toggle flight.
  void jumpPressed(double now);
  // Streams the world round the player until `deadline` and uploads the finished meshes; relights
  // props near them. Returns the number of sections uploaded.
  int stream(std::chrono::steady_clock::time_point deadline);
  // Sets a block as the player does: recorded among the edits, and stairs beside it turned into
  // corners (world/connected_states.h). False when nothing changed.
  bool editBlock(const BlockPos& pos, BlockId state);
  // Places a prop (Error when its model cannot be read) or removes one; the renderer learns the
  // props' new needs.
  void placeProp(const LevelProp& prop);
  void removeProp(int index);
  // The world's props/ folder: the models a player can place.
  std::vector<std::string> propFiles() const;
  // The player is in place and everything round them is loaded and meshed.
  bool ready() const;
  // Saves the world with the player and props; a failure is logged (the game goes on).
  void save();

 private:
  struct Scratch {
    std::filesystem::path dir;  // empty: a world to keep
    ~Scratch();
  } scratch_;  // first: removed once the world below has closed its files
  const BlockContent& content_;
  GameRenderer& renderer_;
  StreamedWorld world_;
  GameProps props_;  // after the world: props light from it
  Player player_;
  TimeControls time_;
  DoubleTap flightTap_;
  bool spawnPending_ = false;  // the player waits for the ground to drop onto
  std::string notice_;
  std::vector<Edit> edits_;
  std::vector<StateChange> changes_;
};

}  // namespace terrasol
