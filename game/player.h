#pragma once
// The player's body: an axis-aligned box moved by Minecraft's movement rules at Minecraft's fixed 20
// ticks a second, so speeds, jump height and fall speed match what players know. Collisions clip the
// whole move of a tick against every block box in its path (no tunnelling at any speed), and the
// frame rate never changes the physics (ticks are fixed; only the drawn position is interpolated).
// Plain C++: tests drive it over a World with no window.

#include <glm/vec3.hpp>

#include "world/world.h"

namespace terrasol {

inline constexpr double kTicksPerSecond = 20.0;

// One tick's intent, from the controls.
struct MoveInput {
  float forward = 0.0f, strafe = 0.0f;  // -1..1; strafe + is to the right
  bool jump = false;                    // held (jumps again on landing, like holding space)
  bool sneak = false, sprint = false;
};

struct Box {
  glm::dvec3 min{0.0}, max{0.0};
};

class Player {
 public:
  static constexpr double kWidth = 0.6, kHeight = 1.8, kEyeHeight = 1.62, kSneakEyeHeight = 1.27;

  // Feet at `position` (the centre of the box's bottom face).
  explicit Player(glm::dvec3 position = {0.0, 0.0, 0.0});

  // One 1/20 s step. Does nothing while the player's chunk is not loaded (it holds still until the
  // ground is there); blocks in unloaded chunks are solid.
  void tick(const World& world, const MoveInput& input);
  // Ticks to run for `seconds` of real time carried over from earlier frames; at most 10 (a long
  // stall slows the game down instead of moving the player through the world in one jump).
  static int ticksFor(double& accumulator, double seconds);

  // Position drawn at `alpha` (0..1) of the way from the previous tick to the current one.
  glm::dvec3 eyeAt(double alpha) const;
  glm::dvec3 eye() const { return eyeAt(1.0); }
  glm::dvec3 forward() const;  // from yaw and pitch
  Box box() const { return boxAt(position_); }
  static Box boxAt(glm::dvec3 feet);

  glm::dvec3 position() const { return position_; }
  glm::dvec3 velocity() const { return velocity_ * kTicksPerSecond; }  // blocks per second
  void teleport(glm::dvec3 feet);
  // Adds velocity (blocks per second), as a knock-back would.
  void push(glm::dvec3 blocksPerSecond) { velocity_ += blocksPerSecond / kTicksPerSecond; }
  // Degrees. Yaw 0 looks south (+z), 90 west (-x), as in Minecraft; pitch + looks down, within ±90.
  float yaw = 0.0f, pitch = 0.0f;
  void look(float dYaw, float dPitch);

  bool flying = false;
  bool onGround() const { return onGround_; }
  bool inWater() const { return inWater_; }
  bool sneaking() const { return sneaking_; }
  bool sprinting() const { return sprinting_; }

 private:
  glm::dvec3 move(const World& world, glm::dvec3 delta);
  glm::dvec3 backOffFromEdge(const World& world, glm::dvec3 delta) const;

  glm::dvec3 position_, previous_;
  glm::dvec3 velocity_{0.0};  // blocks per tick, as Minecraft keeps it
  bool onGround_ = false, inWater_ = false, sneaking_ = false, sprinting_ = false;
};

// True when `id` stops the player (full cubes of any layer: stone, leaves, glass).
bool isSolid(const World& world, const BlockPos& pos);
// Whether the box touches any solid cell (cells of unloaded chunks count as solid).
bool collides(const World& world, const Box& box);
// A state's collision boxes (BlockShapes::collision) as world boxes, were it in cell `at`.
std::vector<Box> collisionBoxes(const BlockShapes& shapes, BlockId state, const BlockPos& at);
// Whether two boxes overlap by more than a hair.
bool overlaps(const Box& a, const Box& b);

}  // namespace terrasol
