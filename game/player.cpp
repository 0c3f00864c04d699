#include "player.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>
#include <vector>

#include "world/liquid.h"

namespace terrasol {
namespace {

// Minecraft's movement constants, per tick (blocks, blocks per tick).
constexpr double kGravity = 0.08, kAirDrag = 0.98;
constexpr double kGroundFriction = 0.6 * 0.91, kAirFriction = 0.91, kWaterFriction = 0.8, kFlyDrag = 0.6;
constexpr double kWalkAccel = 0.1, kAirAccel = 0.02, kSprintBoost = 1.3;
constexpr double kFlyAccel = 0.05, kFlyVertical = 0.15;
constexpr double kJumpVelocity = 0.42, kSprintJumpBoost = 0.2;
constexpr double kWaterSink = 0.08 / 16.0, kSwimUp = 0.04;
constexpr double kSneakFactor = 0.3, kInputScale = 0.98;
constexpr double kEdgeProbe = 0.6, kEdgeStep = 0.05;  // sneaking: how far down ground must be; back-off step
constexpr double kStepHeight = 0.6;                   // walked up without jumping (a slab, a stair)
// A tick's move is capped on each axis so the block boxes gathered for it stay few; far above any
// speed the rules reach (falling tops out near 3.9 blocks a tick).
constexpr double kMaxMove = 32.0;
constexpr double kEpsilon = 1e-7;
constexpr int kMaxTicksPerFrame = 10;

// Calls f(pos) for every cell the box overlaps.
template <class F>
bool anyCell(const Box& box, F&& f) {
  const glm::ivec3 lo(glm::floor(box.min + kEpsilon)), hi(glm::floor(box.max - kEpsilon));
  for (int y = lo.y; y <= hi.y; ++y)
    for (int z = lo.z; z <= hi.z; ++z)
      for (int x = lo.x; x <= hi.x; ++x)
        if (f(BlockPos{x, y, z})) return true;
  return false;
}

Box shifted(const Box& b, glm::dvec3 d) {
  return {b.min + d, b.max + d};
}

// The box grown to cover its whole move.
Box swept(const Box& b, glm::dvec3 d) {
  return {glm::min(b.min, b.min + d) - kEpsilon, glm::max(b.max, b.max + d) + kEpsilon};
}

// The collision boxes near `region`: each cell's state's shape (World::shapes), else whole cells
// of solid blocks. Cells half a block below count too: a fence's or wall's box reaches up into the
// cell above.
std::vector<Box> solidBoxes(const World& world, const Box& region) {
  std::vector<Box> boxes;
  const BlockShapes* shapes = world.shapes();
  const Box reach{region.min - glm::dvec3(0.0, 0.5, 0.0), region.max};
  anyCell(reach, [&](const BlockPos& p) {
    const glm::dvec3 corner(p.x, p.y, p.z);
    if (!shapes || !world.isLoaded(ChunkPos::of(p)) || !inWorldHeight(p.y)) {
      if (isSolid(world, p)) boxes.push_back({corner, corner + glm::dvec3(1.0)});
      return false;
    }
    const std::vector<Box> cell = collisionBoxes(*shapes, world.getBlock(p), p);
    boxes.insert(boxes.end(), cell.begin(), cell.end());
    return false;
  });
  return boxes;
}

// How far `box` can go along `axis` (wanting `d`) before touching one of `boxes`. Boxes it already
// overlaps do not stop it, so a player inside a block can walk out.
double clip(const std::vector<Box>& boxes, const Box& box, int axis, double d) {
  const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  for (const Box& b : boxes) {
    if (b.max[a1] <= box.min[a1] + kEpsilon || b.min[a1] >= box.max[a1] - kEpsilon) continue;
    if (b.max[a2] <= box.min[a2] + kEpsilon || b.min[a2] >= box.max[a2] - kEpsilon) continue;
    if (d > 0.0 && b.min[axis] >= box.max[axis] - kEpsilon) d = std::min(d, b.min[axis] - box.max[axis]);
    if (d < 0.0 && b.max[axis] <= box.min[axis] + kEpsilon) d = std::max(d, b.max[axis] - box.min[axis]);
  }
  return d;
}

}  // namespace

bool overlaps(const Box& a, const Box& b) {
  for (int i = 0; i < 3; ++i) {
    if (a.max[i] <= b.min[i] + kEpsilon || a.min[i] >= b.max[i] - kEpsilon) return false;
  }
  return true;
}

std::vector<Box> collisionBoxes(const BlockShapes& shapes, BlockId state, const BlockPos& at) {
  std::vector<Box> boxes;
  const glm::dvec3 corner(at.x, at.y, at.z);
  for (const ShapeBox& b : shapes.collision(state)) {
    boxes.push_back({corner + glm::dvec3(b.from[0], b.from[1], b.from[2]) / 16.0,
                     corner + glm::dvec3(b.to[0], b.to[1], b.to[2]) / 16.0});
  }
  return boxes;
}

bool isSolid(const World& world, const BlockPos& pos) {
  if (!inWorldHeight(pos.y)) return false;
  if (!world.isLoaded(ChunkPos::of(pos))) return true;
  return world.blocks()[world.getBlock(pos)].shape == BlockShape::Cube;
}

bool collides(const World& world, const Box& box) {
  for (const Box& b : solidBoxes(world, box)) {
    if (overlaps(b, box)) return true;
  }
  return false;
}

Player::Player(glm::dvec3 position) : position_(position), previous_(position) {}

Box Player::boxAt(glm::dvec3 feet) {
  const glm::dvec3 half(kWidth / 2.0, 0.0, kWidth / 2.0);
  return {feet - half, feet + half + glm::dvec3(0.0, kHeight, 0.0)};
}

void Player::teleport(glm::dvec3 feet) {
  position_ = previous_ = feet;
  velocity_ = glm::dvec3(0.0);
}

void Player::look(float dYaw, float dPitch) {
  yaw = std::fmod(yaw + dYaw, 360.0f);
  pitch = std::clamp(pitch + dPitch, -90.0f, 90.0f);
}

glm::dvec3 Player::forward() const {
  const double y = glm::radians(double(yaw)), p = glm::radians(double(pitch));
  return {-std::sin(y) * std::cos(p), -std::sin(p), std::cos(y) * std::cos(p)};
}

glm::dvec3 Player::eyeAt(double alpha) const {
  const double eye = sneaking_ ? kSneakEyeHeight : kEyeHeight;
  return previous_ + (position_ - previous_) * std::clamp(alpha, 0.0, 1.0) + glm::dvec3(0.0, eye, 0.0);
}

int Player::ticksFor(double& accumulator, double seconds) {
  accumulator += std::max(seconds, 0.0);
  const int ticks = static_cast<int>(std::floor(accumulator * kTicksPerSecond));
  if (ticks > kMaxTicksPerFrame) {
    accumulator = 0.0;
    return kMaxTicksPerFrame;
  }
  accumulator -= ticks / kTicksPerSecond;
  return ticks;
}

void Player::tick(const World& world, const MoveInput& input) {
  previous_ = position_;
  if (!world.isLoaded(ChunkPos::of({int(std::floor(position_.x)), 0, int(std::floor(position_.z))}))) return;

  inWater_ = anyCell(box(), [&](const BlockPos& p) { return isLiquid(world, p); });
  sneaking_ = input.sneak && !flying;
  sprinting_ = input.sprint && input.forward > 0.0f && !sneaking_;

  // Input as Minecraft scales it: 0.98 per axis, sneaking 0.3, never longer than 1.
  glm::dvec2 in(input.strafe, input.forward);
  in *= kInputScale * (sneaking_ ? kSneakFactor : 1.0);
  if (glm::dot(in, in) > 1.0) in = glm::normalize(in);
  const double yawRad = glm::radians(double(yaw));
  const glm::dvec3 ahead(-std::sin(yawRad), 0.0, std::cos(yawRad)),
      right(-std::cos(yawRad), 0.0, -std::sin(yawRad));
  const auto accelerate = [&](double speed) { velocity_ += (ahead * in.y + right * in.x) * speed; };
  const double sprint = sprinting_ ? kSprintBoost : 1.0;

  if (flying) {
    if (input.jump) velocity_.y += kFlyVertical;
    if (input.sneak) velocity_.y -= kFlyVertical;
    accelerate(kFlyAccel * (sprinting_ ? 2.0 : 1.0));
    move(world, velocity_);
    velocity_ *= glm::dvec3(kAirFriction, kFlyDrag, kAirFriction);
    if (onGround_) flying = false;  // landing ends flight, as in Minecraft
  } else if (inWater_) {
    if (input.jump) velocity_.y += kSwimUp;
    accelerate(kAirAccel);
    move(world, velocity_);
    velocity_ *= glm::dvec3(kWaterFriction, kWaterFriction, kWaterFriction);
    velocity_.y -= kWaterSink;
  } else {
    if (input.jump && onGround_) {
      velocity_.y = kJumpVelocity;
      if (sprinting_) velocity_ += ahead * kSprintJumpBoost;
    }
    const bool ground = onGround_;
    accelerate((ground ? kWalkAccel : kAirAccel) * sprint);
    glm::dvec3 delta = velocity_;
    if (sneaking_ && ground) delta = backOffFromEdge(world, delta);
    move(world, delta);
    const double friction = ground ? kGroundFriction : kAirFriction;
    velocity_.x *= friction;
    velocity_.z *= friction;
    velocity_.y = (velocity_.y - kGravity) * kAirDrag;
  }
}

glm::dvec3 Player::move(const World& world, glm::dvec3 delta) {
  delta = glm::clamp(delta, -kMaxMove, kMaxMove);
  const Box start = box();
  const std::vector<Box> boxes = solidBoxes(world, swept(swept(start, delta), {0.0, kStepHeight, 0.0}));
  // Vertical first, then the larger horizontal axis last, as Minecraft does (sliding along walls).
  const auto slide = [&](Box b, glm::dvec3 d, glm::dvec3& done) {
    const int order[3] = {1, std::abs(d.x) < std::abs(d.z) ? 2 : 0, std::abs(d.x) < std::abs(d.z) ? 0 : 2};
    for (const int a : order) {
      done[a] = clip(boxes, b, a, d[a]);
      glm::dvec3 step(0.0);
      step[a] = done[a];
      b = shifted(b, step);
    }
    return b;
  };
  glm::dvec3 done(0.0);
  Box b = slide(start, delta, done);
  bool landed = delta.y < 0.0 && done.y != delta.y;
  // Minecraft's step: on the ground and stopped across, try again from up to 0.6 higher, then settle
  // back down onto what is there; kept when it gets further (up a slab or a stair, not a block).
  if ((onGround_ || landed) && !flying && (done.x != delta.x || done.z != delta.z)) {
    const double up = clip(boxes, start, 1, kStepHeight);
    glm::dvec3 across(0.0);
    Box stepped = slide(shifted(start, {0.0, up, 0.0}), {delta.x, 0.0, delta.z}, across);
    const double down = clip(boxes, stepped, 1, -up);
    if (across.x * across.x + across.z * across.z > done.x * done.x + done.z * done.z + 1e-9) {
      b = shifted(stepped, {0.0, down, 0.0});
      done = {across.x, up + down, across.z};
      delta.y = done.y;  // the climb is the move's vertical part, not a blocked one
      landed = true;     // it settled onto the step
    }
  }
  onGround_ = landed;
  for (int a = 0; a < 3; ++a)
    if (done[a] != delta[a]) velocity_[a] = 0.0;
  position_ = glm::dvec3((b.min.x + b.max.x) / 2.0, b.min.y, (b.min.z + b.max.z) / 2.0);
  return done;
}

// Sneaking on ground: shortens the move so the box keeps ground within 0.6 blocks below it.
glm::dvec3 Player::backOffFromEdge(const World& world, glm::dvec3 d) const {
  const Box b = box();
  const auto unsupported = [&](double dx, double dz) {
    return !collides(world, shifted(b, {dx, -kEdgeProbe, dz}));
  };
  const auto shrink = [](double& v) { v = std::abs(v) < kEdgeStep ? 0.0 : v - std::copysign(kEdgeStep, v); };
  while (d.x != 0.0 && unsupported(d.x, 0.0)) shrink(d.x);
  while (d.z != 0.0 && unsupported(0.0, d.z)) shrink(d.z);
  while (d.x != 0.0 && d.z != 0.0 && unsupported(d.x, d.z)) {
    shrink(d.x);
    shrink(d.z);
  }
  return d;
}

}  // namespace terrasol
