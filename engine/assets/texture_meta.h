#pragma once
// A texture's ".png.mcmeta": animation strips (Minecraft Java format).
//   {"animation": {"frametime": 2, "interpolate": true, "frames": [0, 1, {"index": 2, "time": 5}],
//                  "width": 16, "height": 16}}
// Frames are stacked vertically; each is `width` wide and `height` tall (both default to the image
// width, i.e. square frames).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace terrasol {

struct AnimationFrame {
  int index = 0;  // frame in the strip, top = 0
  int ticks = 1;  // game ticks it is shown (20 per second)
};

struct Animation {
  int frameWidth = 0, frameHeight = 0;
  int stripFrames = 0;  // frames in the strip
  bool interpolate = false;
  std::vector<AnimationFrame> sequence;  // the order they play in
  std::int64_t totalTicks() const;
};

// The frame to show after `ticks` game ticks (20 a second): `frame` blends towards `next` by `blend`
// (0..1) when the animation interpolates, otherwise blend is 0. Exact for any tick count, 10^12 too.
struct FrameBlend {
  int frame = 0, next = 0;
  float blend = 0.0f;
};
FrameBlend frameAt(const Animation& animation, std::int64_t ticks, float partialTick = 0.0f);

// Parses `json` (the .mcmeta text) for an image of `width` x `height`. Returns nothing when it has no
// "animation" section. Throws Error naming `file` and the key for malformed JSON, a strip height that
// is not a multiple of the frame height, frame indices out of range or times below 1.
std::optional<Animation> parseAnimation(const std::string& json, int width, int height,
                                        const std::string& file);

}  // namespace terrasol
