#pragma once
// An OptiFine/Iris shader pack: a folder or .zip with a `shaders/` folder of programs (name.vsh,
// name.fsh, optionally name.gsh), `.properties` files and included GLSL. Terrasol's world is the
// overworld, so where `shaders/world0/` exists its programs replace the root's (only programs are read
// there, as OptiFine does). A program missing from the pack falls back along OptiFine's chain
// (gbuffers_water to gbuffers_terrain to gbuffers_textured_lit, ...). GL-free.

#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "assets/pack_source.h"
#include "assets/shader_source.h"

namespace terrasol {

// A program's files, by path inside `shaders/` ("world0/gbuffers_terrain.vsh").
struct PackProgram {
  std::string name;                        // as asked for, or the fallback that stands in for it
  std::string vertex, fragment, geometry;  // geometry: empty when the pack has none
};

class ShaderPack {
 public:
  // Throws Error naming the path: not a folder or .zip, unreadable, or without `shaders/`.
  static ShaderPack open(const std::filesystem::path& path);

  // The pack's name: its folder's or archive's.
  const std::string& name() const { return name_; }

  // The program of exactly this name, where the pack has both its stages; nothing otherwise.
  std::optional<PackProgram> program(std::string_view name) const;
  // The program or the first of its fallbacks the pack has; nothing when none is there.
  std::optional<PackProgram> resolve(std::string_view name) const;
  // The programs the pack has, of every name OptiFine knows, in the frame's order.
  std::vector<std::string> programs() const;

  // A file inside `shaders/` ("block.properties"), or nothing.
  std::optional<std::string> text(const std::string& path) const;
  // A stage's source with its includes expanded and `defines` after `#version`; throws Error naming
  // the pack's file and line.
  PreprocessedShader source(const std::string& path, const std::vector<ShaderDefine>& defines) const;
  // How messages name a file inside `shaders/`.
  std::string displayName(const std::string& path) const;

 private:
  ShaderPack(std::unique_ptr<PackSource> files, std::string name);
  bool has(const std::string& path) const;

  std::shared_ptr<const PackSource> files_;
  std::string name_;
  std::set<std::string> programFiles_;  // the program files in shaders/ and shaders/world0/
  bool world0_ = false;
};

// OptiFine's program names in the frame's order: shadow, shadowcomp*, prepare*, the gbuffers,
// deferred*, composite*, final (numbered ones from 0, "composite" then "composite1" to "composite99").
const std::vector<std::string>& packProgramNames();
// The program that stands in for `name` when the pack lacks it (OptiFine's, with Iris's clouds to
// textured); empty at the end of a chain.
std::string_view programFallback(std::string_view name);

}  // namespace terrasol
