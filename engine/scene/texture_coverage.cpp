#include "scene/texture_coverage.h"

#include <cctype>
#include <set>

#include "assets/crack_textures.h"
#include "scene/block_atlas.h"
#include "scene/texture_names.h"

namespace terrasol {
namespace {

// Sorts the unused of `top` (the top pack's base names) into TextureCoverage's three kinds.
void classifyUnused(TextureCoverage& coverage, const std::set<std::string>& top) {
  for (const std::string& name : coverage.unused) {
    // "stone7", "wheat_stage7-1": digits (and a dash) after a name the pack has.
    std::size_t end = name.size();
    while (end > 0 && std::isdigit(static_cast<unsigned char>(name[end - 1]))) --end;
    if (end < name.size() && end > 0 && name[end - 1] == '-') --end;
    const bool variant = end < name.size() && top.contains(name.substr(0, end));
    const bool layer = name.ends_with("_e") && top.contains(name.substr(0, name.size() - 2));
    bool older = false;
    for (const auto& [now, old] : renamedTextures()) older |= name == old && top.contains(std::string(now));
    if (variant)
      coverage.variants.push_back(name);
    else if (layer)
      coverage.emissiveLayers.push_back(name);
    else if (older)
      coverage.superseded.push_back(name);
  }
}

}  // namespace

TextureCoverage textureCoverage(const BlockRegistry& blocks, const PackStack& packs) {
  // What the game loads for a list of candidates: the first the stack has.
  std::set<std::string> drawn;
  const auto use = [&](const std::vector<std::string>& candidates) {
    if (const auto named = packs.findBlockTextureNamed(candidates)) drawn.insert(named->name);
  };
  const BlockModelBake baked =
      bakeBlockModels(blocks, packs);  // its problems: inspect and the atlas report them
  for (BlockId id = 0; id < blocks.size(); ++id) {
    for (const auto& face : blocks.faceTextures(id)) use(withOlderNames(face));
    // A state drawn as an earlier one has empty lists.
    for (const BakedQuad& q : baked.quads[id]) use(candidatesOf(q.texture));
    for (const BakedChoice& c : baked.choices[id])
      for (const BakedQuad& q : c.quads) use(candidatesOf(q.texture));
  }
  for (int stage = 0; stage < kCrackStages; ++stage) use({crackTextureName(stage)});
  TextureCoverage coverage;
  if (packs.packs().empty()) return coverage;
  std::set<std::string> top;
  for (const std::string& file : packs.packs().back()->blockTextureFiles()) {
    if (!file.ends_with(".png") || file.ends_with("_n.png") || file.ends_with("_s.png")) continue;
    top.insert(file.substr(0, file.size() - 4));
  }
  for (const std::string& name : top)
    (drawn.contains(name) ? coverage.used : coverage.unused).push_back(name);
  classifyUnused(coverage, top);
  return coverage;
}

}  // namespace terrasol
