#include "scene/render_settings_json.h"

#include <nlohmann/json.hpp>

#include "core/json_check.h"
#include "core/render_scale.h"

namespace terrasol {
namespace {

using nlohmann::json;
using namespace json_check;

void parsePcf(const json& pcf, const std::string& key, ShadowSettings& shadow) {
  checkObject(pcf, key, {"samples", "radius", "radius_unit", "pattern"});
  if (const json* v = field(pcf, "samples"))
    shadow.pcfSamples = static_cast<int>(wholeNumber(*v, member(key, "samples"), 0, 8));
  if (const json* v = field(pcf, "radius"))
    shadow.pcfRadius = numberIn(*v, member(key, "radius"), 0.0, 32.0, false);
  if (const json* v = field(pcf, "pattern"))
    shadow.pcfPattern = enumOf(*v, member(key, "pattern"), kPcfPatterns);
  if (const json* v = field(pcf, "radius_unit")) {
    shadow.pcfRadiusInBlocks = enumOf(*v, member(key, "radius_unit"), kPcfRadiusUnits);
  }
}

}  // namespace

void parseShadow(const nlohmann::json& value, const std::string& key, ShadowSettings& shadow) {
  checkObject(value, key,
              {"enabled", "mode", "cascades", "resolution", "distance", "warp", "warp_strength", "pcf",
               "shift_ahead", "update_frames"});
  if (const json* v = field(value, "enabled")) shadow.enabled = boolean(*v, member(key, "enabled"));
  if (const json* v = field(value, "mode")) shadow.mode = enumOf(*v, member(key, "mode"), kShadowModes);
  if (const json* v = field(value, "cascades")) {
    shadow.cascades = static_cast<int>(wholeNumber(*v, member(key, "cascades"), 2, 4));
  }
  if (const json* v = field(value, "resolution")) {
    shadow.resolution = static_cast<int>(wholeNumber(*v, member(key, "resolution"), 16, 16384));
  }
  if (const json* v = field(value, "distance"))
    shadow.distance = numberIn(*v, member(key, "distance"), 1.0, 4096.0, false);
  if (const json* v = field(value, "warp")) shadow.warp = enumOf(*v, member(key, "warp"), kShadowWarps);
  if (const json* v = field(value, "warp_strength")) {
    const double a = finiteNumber(*v, member(key, "warp_strength"));
    if (a < 0.0 || a >= 1.0)
      expected(member(key, "warp_strength"), "a number from 0 up to (not including) 1", *v);
    shadow.warpStrength = static_cast<float>(a);
  }
  if (const json* v = field(value, "pcf")) parsePcf(*v, member(key, "pcf"), shadow);
  if (const json* v = field(value, "shift_ahead"))
    shadow.shiftAhead = numberIn(*v, member(key, "shift_ahead"), 0.0, 0.9, false);
  if (const json* v = field(value, "update_frames")) {
    shadow.updateFrames = static_cast<int>(wholeNumber(*v, member(key, "update_frames"), 1, 16));
  }
}

void parseReflections(const nlohmann::json& value, const std::string& key, ReflectionSettings& r) {
  checkObject(value, key,
              {"enabled", "max_steps", "thickness", "resolution_scale", "min_smoothness", "max_distance"});
  if (const json* v = field(value, "enabled")) r.enabled = boolean(*v, member(key, "enabled"));
  if (const json* v = field(value, "max_steps"))
    r.maxSteps = static_cast<int>(wholeNumber(*v, member(key, "max_steps"), 1, 256));
  if (const json* v = field(value, "thickness"))
    r.thickness = numberIn(*v, member(key, "thickness"), 0.01, 16.0, false);
  if (const json* v = field(value, "resolution_scale")) {
    r.resolutionScale =
        numberIn(*v, member(key, "resolution_scale"), kMinRenderScale, kMaxRenderScale, false);
  }
  if (const json* v = field(value, "min_smoothness")) {
    r.minSmoothness = numberIn(*v, member(key, "min_smoothness"), 0.0, 1.0, false);
  }
  if (const json* v = field(value, "max_distance"))
    r.maxDistance = numberIn(*v, member(key, "max_distance"), 1.0, 1024.0, false);
}

void parseBloom(const json& value, const std::string& key, BloomSettings& bloom) {
  checkObject(value, key, {"enabled", "strength"});
  if (const json* v = field(value, "enabled")) bloom.enabled = boolean(*v, member(key, "enabled"));
  if (const json* v = field(value, "strength"))
    bloom.strength = numberIn(*v, member(key, "strength"), 0.0, 1.0, false);
}

nlohmann::json bloomJson(const BloomSettings& bloom) {
  return {{"enabled", bloom.enabled}, {"strength", bloom.strength}};
}

nlohmann::json reflectionsJson(const ReflectionSettings& r) {
  return {{"enabled", r.enabled},
          {"max_steps", r.maxSteps},
          {"thickness", r.thickness},
          {"resolution_scale", r.resolutionScale},
          {"min_smoothness", r.minSmoothness},
          {"max_distance", r.maxDistance}};
}

nlohmann::json shadowJson(const ShadowSettings& s) {
  return {{"enabled", s.enabled},
          {"mode", nameOf(s.mode, kShadowModes)},
          {"cascades", s.cascades},
          {"resolution", s.resolution},
          {"distance", s.distance},
          {"warp", nameOf(s.warp, kShadowWarps)},
          {"warp_strength", s.warpStrength},
          {"shift_ahead", s.shiftAhead},
          {"update_frames", s.updateFrames},
          {"pcf",
           {{"samples", s.pcfSamples},
            {"radius", s.pcfRadius},
            {"radius_unit", kPcfRadiusUnits.nameOf(s.pcfRadiusInBlocks)},
            {"pattern", nameOf(s.pcfPattern, kPcfPatterns)}}}};
}

void parseClouds(const json& value, const std::string& key, CloudSettings& clouds) {
  checkObject(value, key, {"mode", "shadows"});
  if (const json* v = field(value, "mode")) clouds.mode = enumOf(*v, member(key, "mode"), kCloudModes);
  if (const json* v = field(value, "shadows")) clouds.shadows = boolean(*v, member(key, "shadows"));
}

nlohmann::json cloudsJson(const CloudSettings& clouds) {
  return {{"mode", nameOf(clouds.mode, kCloudModes)}, {"shadows", clouds.shadows}};
}

void parseFog(const json& value, const std::string& key, FogSettings& fog) {
  checkObject(value, key, {"density", "base", "falloff"});
  if (const json* v = field(value, "density"))
    fog.density = numberIn(*v, member(key, "density"), 0.0, 1.0, false);
  if (const json* v = field(value, "base"))
    fog.base = numberIn(*v, member(key, "base"), -4096.0, 4096.0, false);
  if (const json* v = field(value, "falloff"))
    fog.falloff = numberIn(*v, member(key, "falloff"), 1.0, 1024.0, false);
}

nlohmann::json fogJson(const FogSettings& fog) {
  return {{"density", fog.density}, {"base", fog.base}, {"falloff", fog.falloff}};
}

void parseShafts(const json& value, const std::string& key, ShaftSettings& shafts) {
  checkObject(value, key, {"enabled", "samples", "scale"});
  if (const json* v = field(value, "enabled")) shafts.enabled = boolean(*v, member(key, "enabled"));
  if (const json* v = field(value, "samples"))
    shafts.samples = static_cast<int>(wholeNumber(*v, member(key, "samples"), 1, 64));
  if (const json* v = field(value, "scale"))
    shafts.scale = numberIn(*v, member(key, "scale"), 0.125, 1.0, false);
}

nlohmann::json shaftsJson(const ShaftSettings& shafts) {
  return {{"enabled", shafts.enabled}, {"samples", shafts.samples}, {"scale", shafts.scale}};
}

void parseLod(const json& value, const std::string& key, LodSettings& lod) {
  checkObject(value, key, {"distance", "detail", "min_level", "shadows"});
  if (const json* v = field(value, "distance"))
    lod.distance = static_cast<int>(wholeNumber(*v, member(key, "distance"), 0, 1024));
  if (const json* v = field(value, "detail"))
    lod.detail = numberIn(*v, member(key, "detail"), 0.5, 8.0, false);
  if (const json* v = field(value, "min_level"))
    lod.minLevel = static_cast<int>(wholeNumber(*v, member(key, "min_level"), 0, 4));
  if (const json* v = field(value, "shadows")) lod.shadows = boolean(*v, member(key, "shadows"));
}

nlohmann::json lodJson(const LodSettings& lod) {
  return {{"distance", lod.distance},
          {"detail", lod.detail},
          {"min_level", lod.minLevel},
          {"shadows", lod.shadows}};
}

}  // namespace terrasol
