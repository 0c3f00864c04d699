#pragma once
// Minecraft Java resource packs: a folder or .zip with pack.mcmeta and
// assets/minecraft/textures/block/<name>.png (the pre-1.13 folder "blocks" works too). Packs stack
// like Minecraft's pack list: later packs override earlier ones, file by file.

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "assets/pack_source.h"

namespace terrasol {

struct PackInfo {
  int packFormat = 0;
  std::string description;
  // Terrasol extension in pack.mcmeta, {"terrasol": {"normal_map_convention": "opengl"}}: green points
  // up in this pack's _n maps. LabPBR's own convention (the default) is DirectX, green down.
  bool openGlNormals = false;
};

class ResourcePack {
 public:
  // A folder or zip with pack.mcmeta, or Minecraft's own assets without one: its client jar
  // (.minecraft/versions/<v>/<v>.jar) or a folder holding its extracted assets/ (or that assets/
  // folder itself). Throws Error naming the file for a missing or malformed pack.mcmeta.
  static ResourcePack open(const std::filesystem::path& path);

  const PackInfo& info() const { return info_; }
  const PackSource& files() const { return *source_; }
  std::string name() const { return source_->location().filename().string(); }

  // Path inside the pack of block texture `file` ("stone.png", "stone_n.png", "stone.png.mcmeta"), in
  // "block/" or else "blocks/", or nothing.
  std::optional<std::string> blockTexture(const std::string& file) const;
  // Every .png directly in the pack's block texture folders.
  std::vector<std::string> blockTextureFiles() const;

 private:
  std::unique_ptr<PackSource> source_;
  PackInfo info_;
  std::map<std::string, std::string> blockFiles_;  // file name -> path; "block/" wins over "blocks/"
};

// Packs bottom to top.
class PackStack {
 public:
  void push(ResourcePack pack) { packs_.push_back(std::make_shared<ResourcePack>(std::move(pack))); }
  const std::vector<std::shared_ptr<ResourcePack>>& packs() const { return packs_; }

  struct Found {
    const ResourcePack* pack;
    std::string path;
  };
  // The topmost pack that has block texture `file`.
  std::optional<Found> findBlockTexture(const std::string& file) const;
  // The topmost pack that has any of the block textures `names` (without ".png"), its first of them:
  // a pack made for an older Minecraft, naming a texture the old way, still covers the packs below.
  struct FoundName {
    Found found;
    std::string name;
  };
  std::optional<FoundName> findBlockTextureNamed(const std::vector<std::string>& names) const;
  // The topmost pack that has `path` (e.g. the grass colormap).
  std::optional<Found> find(const std::string& path) const;

 private:
  std::vector<std::shared_ptr<ResourcePack>> packs_;
};

}  // namespace terrasol
