#include "shaderpack/pack_draw_state.h"

#include <charconv>
#include <sstream>
#include <vector>

#include "core/error.h"

namespace terrasol {
namespace {

constexpr std::string_view kBlendFactors[] = {
    "ZERO",
    "ONE",
    "SRC_COLOR",
    "ONE_MINUS_SRC_COLOR",
    "DST_COLOR",
    "ONE_MINUS_DST_COLOR",
    "SRC_ALPHA",
    "ONE_MINUS_SRC_ALPHA",
    "DST_ALPHA",
    "ONE_MINUS_DST_ALPHA",
    "SRC_ALPHA_SATURATE",
};

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

[[noreturn]] void fail(const ShaderProperties::Entry& e, const std::string& what) {
  throw Error(e.where + ": " + e.key + ": '" + e.value + "': " + what);
}

}  // namespace

bool isBlendFactor(std::string_view name) {
  for (std::string_view f : kBlendFactors)
    if (f == name) return true;
  return false;
}

PackDrawState packDrawState(const ShaderProperties& properties, std::string_view program) {
  PackDrawState state;
  if (const auto* e = properties.find("alphaTest." + std::string(program))) {
    const std::vector<std::string> w = words(e->value);
    if (w.size() == 1 && w[0] == "off") {
      state.alphaTestRef = 0.0f;
    } else {
      if (w.size() != 2 || (w[0] != "GREATER" && w[0] != "GEQUAL"))
        fail(*e, "expected off, or GREATER or GEQUAL and a reference");
      float ref = 0.0f;
      const auto [end, ec] = std::from_chars(w[1].data(), w[1].data() + w[1].size(), ref);
      if (ec != std::errc() || end != w[1].data() + w[1].size() || !(ref >= 0.0f && ref <= 1.0f))
        fail(*e, "the reference is not a number 0..1");
      state.alphaTestRef = ref;
    }
  }
  if (const auto* e = properties.find("blend." + std::string(program))) {
    const std::vector<std::string> w = words(e->value);
    PackBlend blend;
    if (w.size() == 1 && w[0] == "off") {
      blend.enabled = false;
    } else {
      if (w.size() != 2 && w.size() != 4) fail(*e, "expected off, or two or four blend factors");
      for (const std::string& f : w)
        if (!isBlendFactor(f)) fail(*e, "'" + f + "' is not a blend factor");
      blend.factors = {w[0], w[1], w.size() == 4 ? w[2] : w[0], w.size() == 4 ? w[3] : w[1]};
    }
    state.blend = blend;
  }
  return state;
}

bool packSwitch(const ShaderProperties& properties, std::string_view key, bool otherwise) {
  const auto* e = properties.find(key);
  if (!e) return otherwise;
  if (e->value != "true" && e->value != "false") fail(*e, "expected true or false");
  return e->value == "true";
}

}  // namespace terrasol
