#pragma once
// How much of a pack the world can show: the top pack's block textures the blocks draw, and why the
// rest are not drawn (terrasol-pack coverage).

#include <string>
#include <vector>

#include "assets/resource_pack.h"
#include "world/block_registry.h"

namespace terrasol {

// Of the top pack's block textures (base names: no _n, _s or .mcmeta), those the blocks draw with (their
// faces' textures and their models', as the stack resolves them, and the crack over a block being dug)
// and the rest, each sorted: how much of a pack the world can show.
// Of the unused, those no Minecraft model could name, by why: a numbered variant of a texture the pack
// has ("stone7" beside "stone", for random-variant models the pack does not ship), an emissive layer
// ("torch_e", OptiFine's `_e` beside its base), and an older name whose current name the pack also has.
struct TextureCoverage {
  std::vector<std::string> used, unused;
  std::vector<std::string> variants, emissiveLayers, superseded;
  // The unused that are none of those three.
  std::size_t otherUnused() const {
    return unused.size() - variants.size() - emissiveLayers.size() - superseded.size();
  }
};
TextureCoverage textureCoverage(const BlockRegistry& blocks, const PackStack& packs);

}  // namespace terrasol
