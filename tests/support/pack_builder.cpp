#include "support/pack_builder.h"

#include <fstream>

#include "support/world_support.h"

namespace terrasol::testing {

PackBuilder::PackBuilder(const std::string& name, const std::string& blocksDir, const std::string& mcmeta)
    : dir_(scratchDir(name)), blockDir_(dir_ / "assets" / "minecraft" / "textures" / blocksDir) {
  std::filesystem::create_directories(blockDir_);
  std::ofstream(dir_ / "pack.mcmeta") << mcmeta;
}

PackBuilder& PackBuilder::image(const std::string& file, const Image& img) {
  saveImage(blockDir_ / file, img);
  return *this;
}

PackBuilder& PackBuilder::text(const std::string& file, const std::string& contents) {
  std::ofstream(blockDir_ / file, std::ios::binary) << contents;
  return *this;
}

PackBuilder& PackBuilder::asset(const std::string& path, const std::string& contents) {
  const std::filesystem::path file = dir_ / "assets" / "minecraft" / path;
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << contents;
  return *this;
}

Image solidImage(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a) {
  Image image(w, h);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    image.rgba[i] = r, image.rgba[i + 1] = g, image.rgba[i + 2] = b, image.rgba[i + 3] = a;
  }
  return image;
}

PackStack stackOf(std::initializer_list<std::filesystem::path> dirs) {
  PackStack stack;
  for (const auto& d : dirs) stack.push(ResourcePack::open(d));
  return stack;
}

}  // namespace terrasol::testing
