#include "shaderpack/pack_settings.h"

#include <charconv>

#include "core/error.h"
#include "shaderpack/pack_conditions.h"

namespace terrasol {
namespace {

using Kind = PackFormat::Kind;

constexpr PackFormat kFormats[] = {
    {"R8", 1, Kind::Unorm},          {"RG8", 2, Kind::Unorm},
    {"RGB8", 3, Kind::Unorm},        {"RGBA8", 4, Kind::Unorm},
    {"R8_SNORM", 1, Kind::Snorm},    {"RG8_SNORM", 2, Kind::Snorm},
    {"RGB8_SNORM", 3, Kind::Snorm},  {"RGBA8_SNORM", 4, Kind::Snorm},
    {"R16", 1, Kind::Unorm},         {"RG16", 2, Kind::Unorm},
    {"RGB16", 3, Kind::Unorm},       {"RGBA16", 4, Kind::Unorm},
    {"R16_SNORM", 1, Kind::Snorm},   {"RG16_SNORM", 2, Kind::Snorm},
    {"RGB16_SNORM", 3, Kind::Snorm}, {"RGBA16_SNORM", 4, Kind::Snorm},
    {"R16F", 1, Kind::Float},        {"RG16F", 2, Kind::Float},
    {"RGB16F", 3, Kind::Float},      {"RGBA16F", 4, Kind::Float},
    {"R32F", 1, Kind::Float},        {"RG32F", 2, Kind::Float},
    {"RGB32F", 3, Kind::Float},      {"RGBA32F", 4, Kind::Float},
    {"R8I", 1, Kind::Int},           {"RG8I", 2, Kind::Int},
    {"RGB8I", 3, Kind::Int},         {"RGBA8I", 4, Kind::Int},
    {"R8UI", 1, Kind::Uint},         {"RG8UI", 2, Kind::Uint},
    {"RGB8UI", 3, Kind::Uint},       {"RGBA8UI", 4, Kind::Uint},
    {"R16I", 1, Kind::Int},          {"RG16I", 2, Kind::Int},
    {"RGB16I", 3, Kind::Int},        {"RGBA16I", 4, Kind::Int},
    {"R16UI", 1, Kind::Uint},        {"RG16UI", 2, Kind::Uint},
    {"RGB16UI", 3, Kind::Uint},      {"RGBA16UI", 4, Kind::Uint},
    {"R32I", 1, Kind::Int},          {"RG32I", 2, Kind::Int},
    {"RGB32I", 3, Kind::Int},        {"RGBA32I", 4, Kind::Int},
    {"R32UI", 1, Kind::Uint},        {"RG32UI", 2, Kind::Uint},
    {"RGB32UI", 3, Kind::Uint},      {"RGBA32UI", 4, Kind::Uint},
    {"R3_G3_B2", 3, Kind::Packed},   {"RGB5_A1", 4, Kind::Packed},
    {"RGB10_A2", 4, Kind::Packed},   {"R11F_G11F_B10F", 3, Kind::Packed},
    {"RGB9_E5", 3, Kind::Packed},
};

// A buffer's directives are named colortexN... or, for 0..7, by the old names.
constexpr std::string_view kOldNames[] = {"gcolor", "gdepth", "gnormal", "composite",
                                          "gaux1",  "gaux2",  "gaux3",   "gaux4"};

std::vector<std::string> namesOf(int buffer) {
  std::vector<std::string> names{"colortex" + std::to_string(buffer)};
  if (buffer < 8) names.emplace_back(kOldNames[buffer]);
  return names;
}

glm::vec4 vec4Of(std::string_view text, const std::string& what) {
  text = trimmed(text);
  const auto fail = [&] { throw Error(what + ": '" + std::string(text) + "' is not a vec4 of numbers"); };
  if (!text.starts_with("vec4(") || !text.ends_with(")")) fail();
  text = text.substr(5, text.size() - 6);
  glm::vec4 v(0.0f);
  int n = 0;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    std::string_view item = trimmed(text.substr(start, comma - start));
    if (item.ends_with('f')) item.remove_suffix(1);
    float f = 0.0f;
    const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), f);
    if (item.empty() || ec != std::errc() || end != item.data() + item.size() || n >= 4) fail();
    v[n++] = f;
    start = comma + 1;
  }
  if (n == 1)
    v = glm::vec4(v.x);
  else if (n != 4)
    fail();
  return v;
}

}  // namespace

std::optional<PackFormat> packFormat(std::string_view name) {
  for (const PackFormat& f : kFormats)
    if (f.name == name) return f;
  return std::nullopt;
}

PackSettings packSettings(const std::vector<ProgramDirectives>& directives, const std::string& pack) {
  PackSettings s;
  for (const ProgramDirectives& d : directives) {
    for (int b = 0; b < kPackColorBuffers; ++b) {
      PackBuffer& buffer = s.buffers[static_cast<std::size_t>(b)];
      for (const std::string& name : namesOf(b)) {
        if (const auto found = d.constants.find(name + "Format"); found != d.constants.end()) {
          const auto format = packFormat(found->second);
          if (!format)
            throw Error(pack + ": " + name + "Format: '" + found->second + "' is no format OptiFine knows");
          buffer.format = *format;
        }
        if (const auto clear = d.flag(name + "Clear")) buffer.clear = *clear;
        if (const auto found = d.constants.find(name + "ClearColor"); found != d.constants.end())
          buffer.clearColor = vec4Of(found->second, pack + ": " + name + "ClearColor");
        if (d.flag(name + "MipmapEnabled").value_or(false)) buffer.mipmap = true;
      }
    }
    const auto number = [&](const char* name, auto& into) {
      if (const auto v = d.number(name)) into = static_cast<std::remove_reference_t<decltype(into)>>(*v);
    };
    number("shadowMapResolution", s.shadowMapResolution);
    number("shadowDistance", s.shadowDistance);
    number("shadowIntervalSize", s.shadowIntervalSize);
    if (const auto v = d.number("sunPathRotation")) s.sunPathRotation = static_cast<float>(*v);
    number("noiseTextureResolution", s.noiseTextureResolution);
    number("eyeBrightnessHalflife", s.eyeBrightnessHalflife);
    number("ambientOcclusionLevel", s.ambientOcclusionLevel);
    if (const auto f = d.flag("shadowHardwareFiltering")) s.shadowHardwareFiltering = *f;
    for (int i = 0; i < 2; ++i) {
      if (const auto f = d.flag("shadowtex" + std::to_string(i) + "Nearest"))
        s.shadowtexNearest[static_cast<std::size_t>(i)] = *f;
      if (const auto f = d.flag("shadowcolor" + std::to_string(i) + "Nearest"))
        s.shadowcolorNearest[static_cast<std::size_t>(i)] = *f;
    }
  }
  return s;
}

}  // namespace terrasol
