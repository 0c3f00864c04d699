#include "assets/texture_meta.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/error.h"

namespace terrasol {
namespace {

using nlohmann::json;

int positiveInt(const json& object, const char* key, int fallback, const std::string& where) {
  if (!object.contains(key)) return fallback;
  const json& v = object[key];
  if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 1'000'000) {
    throw Error(where + "." + key + " must be a positive integer");
  }
  return v.get<int>();
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
    out.blend = std::clamp((static_cast<float>(t) + std::clamp(partialTick, 0.0f, 1.0f)) / static_cast<float>(seq[i].ticks),
                           0.0f, 1.0f);
  }
  return out;
}

std::optional<Animation> parseAnimation(const std::string& text, int width, int height, const std::string& file) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    throw Error(file + ": invalid JSON: " + e.what());
  }
  if (!root.is_object()) throw Error(file + ": expected a JSON object");
  if (!root.contains("animation")) return std::nullopt;
  const json& a = root["animation"];
  if (!a.is_object()) throw Error(file + ": \"animation\" must be an object");
  const std::string where = file + ": animation";

  Animation anim;
  anim.frameWidth = positiveInt(a, "width", width, where);
  anim.frameHeight = positiveInt(a, "height", anim.frameWidth, where);
  if (anim.frameWidth != width || height % anim.frameHeight != 0) {
    throw Error(where + ": the strip is " + std::to_string(width) + "x" + std::to_string(height) +
                ", not a stack of " + std::to_string(anim.frameWidth) + "x" + std::to_string(anim.frameHeight) +
                " frames");
  }
  anim.stripFrames = height / anim.frameHeight;
  const int frametime = positiveInt(a, "frametime", 1, where);
  if (a.contains("interpolate")) {
    if (!a["interpolate"].is_boolean()) throw Error(where + ".interpolate must be true or false");
    anim.interpolate = a["interpolate"].get<bool>();
  }
  if (a.contains("frames")) {
    if (!a["frames"].is_array() || a["frames"].empty()) throw Error(where + ".frames must be a non-empty array");
    for (std::size_t i = 0; i < a["frames"].size(); ++i) {
      const json& f = a["frames"][i];
      const std::string at = where + ".frames[" + std::to_string(i) + "]";
      AnimationFrame frame{0, frametime};
      if (f.is_number_integer()) {
        frame.index = f.get<int>();
      } else if (f.is_object() && f.contains("index") && f["index"].is_number_integer()) {
        frame.index = f["index"].get<int>();
        frame.ticks = positiveInt(f, "time", frametime, at);
      } else {
        throw Error(at + " must be a frame index or {\"index\": N, \"time\": T}");
      }
      if (frame.index < 0 || frame.index >= anim.stripFrames) {
        throw Error(at + " is frame " + std::to_string(frame.index) + ", but the strip has " +
                    std::to_string(anim.stripFrames));
      }
      anim.sequence.push_back(frame);
    }
  } else {
    if (anim.stripFrames > 65536) throw Error(where + ": more than 65536 frames");
    for (int i = 0; i < anim.stripFrames; ++i) anim.sequence.push_back({i, frametime});
  }
  if (anim.sequence.size() > 65536) throw Error(where + ".frames has more than 65536 entries");
  return anim;
}

}  // namespace terrasol
