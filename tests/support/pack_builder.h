#pragma once
// Builds small resource packs on disk for tests: pack.mcmeta plus chosen block textures.

#include <filesystem>
#include <initializer_list>
#include <string>

#include "assets/image.h"
#include "assets/resource_pack.h"

namespace terrasol::testing {

class PackBuilder {
 public:
  // Creates (emptied) build/test-output/<name> with a pack.mcmeta; `blocksDir` is "block" or "blocks".
  explicit PackBuilder(const std::string& name, const std::string& blocksDir = "block",
                       const std::string& mcmeta = R"({"pack": {"pack_format": 15, "description": "test"}})");

  // Writes assets/minecraft/textures/<blocksDir>/<file> (an image or raw text).
  PackBuilder& image(const std::string& file, const Image& image);
  PackBuilder& text(const std::string& file, const std::string& contents);
  // Writes assets/minecraft/<path> ("models/block/slab.json", "blockstates/oak_slab.json").
  PackBuilder& asset(const std::string& path, const std::string& contents);
  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path file(const std::string& name) const { return blockDir_ / name; }

 private:
  std::filesystem::path dir_, blockDir_;
};

// The packs in these folders (or zips), bottom to top.
PackStack stackOf(std::initializer_list<std::filesystem::path> dirs);

// An image filled with one colour.
Image solidImage(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a = 255);

}  // namespace terrasol::testing
