#include "extreme_pack.h"

#include <fstream>

#include "assets/image.h"

namespace terrasol::packgen {
namespace {

Image solid(std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a) {
  Image image(16, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = r, p[1] = g, p[2] = b, p[3] = a;
    }
  return image;
}

}  // namespace

void writeExtremeMaterialsPack(const std::filesystem::path& dir) {
  const auto blocks = dir / "assets" / "minecraft" / "textures" / "block";
  std::filesystem::create_directories(blocks);
  std::ofstream(dir / "pack.mcmeta") << R"json({
  "pack": {
    "pack_format": 15,
    "description": "LabPBR values at the ends of their ranges (tests/scenes/extreme/materials.json)"
  }
}
)json";
  const auto put = [&](const std::string& name, const Image& albedo, const Image& normal,
                       const Image& specular) {
    saveImage(blocks / (name + ".png"), albedo);
    saveImage(blocks / (name + "_n.png"), normal);
    saveImage(blocks / (name + "_s.png"), specular);
  };
  const Image flat = solid(128, 128, 255, 255);
  // _s: R smoothness, G F0 (230..237 the predefined metals, 255 albedo metal), A emission (255 none).
  put("iron_block", solid(200, 200, 205, 255), flat, solid(255, 230, 0, 255));   // smoothness 255, iron
  put("gold_block", solid(230, 180, 60, 255), flat, solid(0, 237, 0, 255));      // smoothness 0, last metal
  put("copper_block", solid(200, 110, 80, 255), flat, solid(128, 255, 0, 255));  // albedo metal
  put("stone", solid(120, 120, 120, 255), solid(255, 255, 255, 255),
      solid(255, 0, 0, 255));  // F0 0, |xy| > 1
  put("cobblestone", solid(110, 110, 110, 255), solid(0, 128, 255, 255),
      solid(60, 10, 0, 255));                                                  // xy (-1, 0): in the surface
  put("glowstone", solid(250, 210, 120, 255), flat, solid(40, 10, 0, 254));    // emission 254: the brightest
  put("oak_planks", solid(160, 120, 70, 255), flat, solid(40, 10, 0, 255));    // emission 255: none
  put("dirt", solid(120, 80, 50, 255), solid(0, 0, 0, 0), solid(0, 0, 0, 0));  // every channel 0
}

}  // namespace terrasol::packgen
