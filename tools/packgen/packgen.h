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
// The cloud layer's map (textures/environment/clouds.png), 256 x 256, repeating.
Image generateClouds();

// The crack over a block being dug (textures/block/destroy_stage_0..9.png), 16 x 16, stage by stage.
std::vector<Image> generateCracks();

// A text file of the pack: its path under the pack's root and its contents.
struct GeneratedFile {
  std::string path;  // "assets/minecraft/blockstates/granite_slab.json"
  std::string text;
};
// The blockstates and models of the slabs, stairs and walls of the pack's materials
// (shaped_blocks.cpp) and of its other block families (block_family_files.cpp: bark, carpets, panes,
// the newer woods, pressure plates, columns), and the names of those blocks.
std::vector<GeneratedFile> generateShapedBlockFiles();
std::vector<std::string> shapedBlockNames();

// Writes every texture (and _n, _s, .png.mcmeta) and the crack's stages into
// DIR/assets/minecraft/textures/block/, the colormaps into DIR/assets/minecraft/textures/colormap/, the
// cloud layer into .../environment/, and the shaped blocks' blockstates and models.
void writeDefaultPack(const std::filesystem::path& dir);

}  // namespace terrasol::packgen
