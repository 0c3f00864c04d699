#pragma once
// The generator of Terrasol's default resource pack (resourcepacks/default): procedural 16x textures
// for every block, each with a LabPBR normal (_n) and specular (_s) map. Deterministic: the same
// program writes the same pixels, so the committed pack can be checked against it.

#include <filesystem>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "assets/image.h"

namespace terrasol::packgen {

struct GeneratedTexture {
  std::string name;  // file name without ".png"
  Image albedo, normal, specular;
  std::string mcmeta;  // "" when not animated
};

std::vector<GeneratedTexture> generateDefaultTextures();

struct GeneratedColormap {
  std::string name;  // "grass", "foliage"
  Image map;         // 256 x 256
};
std::vector<GeneratedColormap> generateColormaps();

// Writes every texture (and _n, _s, .png.mcmeta) into DIR/assets/minecraft/textures/block/, and the
// colormaps into DIR/assets/minecraft/textures/colormap/.
void writeDefaultPack(const std::filesystem::path& dir);

}  // namespace terrasol::packgen
