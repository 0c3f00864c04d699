#include "assets/texture_meta.h"

#include <algorithm>

#include "core/error.h"
#include "core/json_check.h"

namespace terrasol {
namespace {

using namespace json_check;

int positiveInt(const json& object, const char* name, int fallback, const std::string& key) {
  const json* v = field(object, name);
  return v ? static_cast<int>(wholeNumber(*v, member(key, name), 1, 1'000'000)) : fallback;
}

// One entry of "frames": a frame index, or {"index": N, "time": T}.
AnimationFrame parseFrame(const json& f, int frametime, int stripFrames, const std::string& key) {
  AnimationFrame frame{0, frametime};
  const json* index = f.is_object() ? field(f, "index") : &f;
  if (!index || !index->is_number_integer()) expected(key, "a frame index or {\"index\": N, \"time\": T}", f);
  const std::int64_t i = index->get<std::int64_t>();
  if (i < 0 || i >= stripFrames) {
    fail(key, join({"is frame ", std::to_string(i), ", but the strip has ", std::to_string(stripFrames)}));
  }
  frame.index = static_cast<int>(i);
  if (f.is_object()) frame.ticks = positiveInt(f, "time", frametime, key);
  return frame;
}

// The "animation" section. The file is Minecraft's: keys it does not read (and the "texture",
// "villager" or "gui" sections beside it) are other readers' and pass unremarked.
Animation parseSection(const json& a, int width, int height) {
  if (!a.is_object()) expected("animation", "an object", a);
  Animation anim;
  anim.frameWidth = positiveInt(a, "width", width, "animation");
  anim.frameHeight = positiveInt(a, "height", anim.frameWidth, "animation");
  if (anim.frameWidth != width || height % anim.frameHeight != 0) {
    fail("animation",
         join({"the strip is ", std::to_string(width), "x", std::to_string(height), ", not a stack of ",
               std::to_string(anim.frameWidth), "x", std::to_string(anim.frameHeight), " frames"}));
  }
  anim.stripFrames = height / anim.frameHeight;
  const int frametime = positiveInt(a, "frametime", 1, "animation");
  if (const json* v = field(a, "interpolate")) anim.interpolate = boolean(*v, "animation.interpolate");
  if (const json* frames = field(a, "frames")) {
    if (!frames->is_array() || frames->empty()) expected("animation.frames", "a non-empty array", *frames);
    if (frames->size() > 65536) fail("animation.frames", "has more than 65536 entries");
    for (std::size_t i = 0; i < frames->size(); ++i) {
      const std::string key = element("animation.frames", i);
      anim.sequence.push_back(parseFrame((*frames)[i], frametime, anim.stripFrames, key));
    }
  } else {
    if (anim.stripFrames > 65536) fail("animation", "more than 65536 frames");
    for (int i = 0; i < anim.stripFrames; ++i) anim.sequence.push_back({i, frametime});
  }
  return anim;
}

}  // namespace

std::int64_t Animation::totalTicks() const {
  std::int64_t total = 0;
  for (const auto& f : sequence) total += f.ticks;
  return total;
}

FrameBlend frameAt(const Animation& animation, std::int64_t ticks, float partialTick) {
  const auto& seq = animation.sequence;
  if (seq.empty()) return {};
  const std::int64_t period = animation.totalTicks();
  std::int64_t t = ((ticks % period) + period) % period;  // integer arithmetic: no drift however long
  std::size_t i = 0;
  while (t >= seq[i].ticks) t -= seq[i++].ticks;
  FrameBlend out{seq[i].index, seq[(i + 1) % seq.size()].index, 0.0f};
  if (animation.interpolate) {
    out.blend = std::clamp(
        (static_cast<float>(t) + std::clamp(partialTick, 0.0f, 1.0f)) / static_cast<float>(seq[i].ticks),
        0.0f, 1.0f);
  }
  return out;
}

std::optional<Animation> parseAnimation(const std::string& text, int width, int height,
                                        const std::string& file) {
  const json root = parseJson(text, file);
  try {
    if (!root.is_object()) expected("", "an object", root);
    const json* a = field(root, "animation");
    if (!a) return std::nullopt;
    return parseSection(*a, width, height);
  } catch (const Error& e) {
    throw Error(withFile(file, e.what()));
  }
}

}  // namespace terrasol
