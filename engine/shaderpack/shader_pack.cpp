#include "shaderpack/shader_pack.h"

#include <array>
#include <set>
#include <system_error>
#include <utility>

#include "core/error.h"

namespace terrasol {
namespace {

constexpr std::string_view kRoot = "shaders/";

constexpr std::array<std::pair<std::string_view, std::string_view>, 23> kFallbacks{{
    {"gbuffers_line", "gbuffers_basic"},
    {"gbuffers_textured", "gbuffers_basic"},
    {"gbuffers_textured_lit", "gbuffers_textured"},
    {"gbuffers_skybasic", "gbuffers_basic"},
    {"gbuffers_skytextured", "gbuffers_textured"},
    {"gbuffers_clouds", "gbuffers_textured"},
    {"gbuffers_terrain", "gbuffers_textured_lit"},
    {"gbuffers_damagedblock", "gbuffers_terrain"},
    {"gbuffers_block", "gbuffers_terrain"},
    {"gbuffers_beaconbeam", "gbuffers_textured"},
    {"gbuffers_item", "gbuffers_textured_lit"},
    {"gbuffers_entities", "gbuffers_textured_lit"},
    {"gbuffers_entities_glowing", "gbuffers_entities"},
    {"gbuffers_armor_glint", "gbuffers_textured"},
    {"gbuffers_spidereyes", "gbuffers_textured"},
    {"gbuffers_hand", "gbuffers_textured_lit"},
    {"gbuffers_weather", "gbuffers_textured_lit"},
    {"gbuffers_water", "gbuffers_terrain"},
    {"gbuffers_hand_water", "gbuffers_hand"},
    {"gbuffers_terrain_solid", "gbuffers_terrain"},
    {"gbuffers_terrain_cutout", "gbuffers_terrain"},
    {"gbuffers_terrain_cutout_mip", "gbuffers_terrain"},
    {"gbuffers_basic", ""},
}};

void addNumbered(std::vector<std::string>& names, const std::string& base) {
  names.push_back(base);
  for (int i = 1; i < 100; ++i) names.push_back(base + std::to_string(i));
}

}  // namespace

const std::vector<std::string>& packProgramNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all{"shadow"};
    addNumbered(all, "shadowcomp");
    addNumbered(all, "prepare");
    for (const std::string_view g : {"gbuffers_basic",
                                     "gbuffers_line",
                                     "gbuffers_textured",
                                     "gbuffers_textured_lit",
                                     "gbuffers_skybasic",
                                     "gbuffers_skytextured",
                                     "gbuffers_clouds",
                                     "gbuffers_terrain",
                                     "gbuffers_terrain_solid",
                                     "gbuffers_terrain_cutout",
                                     "gbuffers_terrain_cutout_mip",
                                     "gbuffers_damagedblock",
                                     "gbuffers_block",
                                     "gbuffers_beaconbeam",
                                     "gbuffers_item",
                                     "gbuffers_entities",
                                     "gbuffers_entities_glowing",
                                     "gbuffers_armor_glint",
                                     "gbuffers_spidereyes",
                                     "gbuffers_hand",
                                     "gbuffers_weather"})
      all.emplace_back(g);
    addNumbered(all, "deferred");
    all.emplace_back("gbuffers_water");
    all.emplace_back("gbuffers_hand_water");
    addNumbered(all, "composite");
    all.emplace_back("final");
    return all;
  }();
  return names;
}

std::string_view programFallback(std::string_view name) {
  for (const auto& [program, fallback] : kFallbacks)
    if (program == name) return fallback;
  return {};
}

ShaderPack::ShaderPack(std::unique_ptr<PackSource> files, std::string name)
    : files_(std::move(files)), name_(std::move(name)) {
  for (const std::string& file : files_->list("shaders")) programFiles_.insert(file);
  for (const std::string& file : files_->list(std::string(kRoot) + "world0")) {
    programFiles_.insert("world0/" + file);
    world0_ = true;
  }
}

ShaderPack ShaderPack::open(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw Error(path.string() + ": no such shader pack (expected a folder or a .zip file)");
  std::unique_ptr<PackSource> files = PackSource::open(path);
  if (files->list("shaders").empty())
    throw Error(path.string() + ": not a shader pack: no shaders/ folder with files in it");
  const std::string name = (path.has_filename() ? path : path.parent_path()).filename().string();
  return ShaderPack(std::move(files), name);
}

bool ShaderPack::has(const std::string& path) const {
  return programFiles_.contains(path);
}

std::optional<PackProgram> ShaderPack::program(std::string_view name) const {
  const std::string base = (world0_ ? "world0/" : "") + std::string(name);
  if (!has(base + ".vsh") || !has(base + ".fsh")) return std::nullopt;
  return PackProgram{std::string(name), base + ".vsh", base + ".fsh",
                     has(base + ".gsh") ? base + ".gsh" : ""};
}

std::optional<PackProgram> ShaderPack::resolve(std::string_view name) const {
  for (std::string_view at = name; !at.empty(); at = programFallback(at))
    if (auto found = program(at)) return found;
  return std::nullopt;
}

std::vector<std::string> ShaderPack::programs() const {
  std::vector<std::string> present;
  for (const std::string& name : packProgramNames())
    if (program(name)) present.push_back(name);
  return present;
}

std::optional<std::string> ShaderPack::text(const std::string& path) const {
  const auto bytes = files_->read(std::string(kRoot) + path);
  if (!bytes) return std::nullopt;
  return std::string(bytes->begin(), bytes->end());
}

PreprocessedShader ShaderPack::source(const std::string& path,
                                      const std::vector<ShaderDefine>& defines) const {
  const ShaderPreprocessor pre([this](const std::string& file) { return text(file); },
                               files_->displayName("shaders"), IncludeRules::shaderPack());
  return pre.process(path, defines);
}

std::string ShaderPack::displayName(const std::string& path) const {
  return files_->displayName(std::string(kRoot) + path);
}

}  // namespace terrasol
