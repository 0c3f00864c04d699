#include "mesh/block_icon_mesh.h"

#include <algorithm>
#include <memory>
#include <set>
#include <string_view>

#include "core/light_level.h"
#include "mesh/section_snapshot.h"

namespace terrasol {

SectionMesh iconMesh(const BlockMeshTable& table, const BlockRegistry& blocks, BlockId state) {
  // Big (about 35 KB): on the heap.
  auto snapshot = std::make_unique<SectionSnapshot>();
  snapshot->pos = {0, 0, 0};
  snapshot->blocks.fill(kAir);
  snapshot->opaque.fill(0);
  snapshot->light.fill(SectionSnapshot::lightTerm(false, 0, kMaxLight));
  snapshot->tints.fill(kPlainsColumn);
  const auto cell = static_cast<std::size_t>(SectionSnapshot::index(kIconCell, kIconCell, kIconCell));
  const bool opaque = blocks.opaqueCubes()[state] != 0;
  snapshot->blocks[cell] = state;
  snapshot->opaque[cell] = opaque ? 1 : 0;
  snapshot->light[cell] = SectionSnapshot::lightTerm(opaque, 0, kMaxLight);
  return meshSection(*snapshot, table);
}

std::vector<BlockId> iconStates(const BlockRegistry& blocks, std::span<const std::string> placeholders) {
  const std::set<std::string_view> leftOut(placeholders.begin(), placeholders.end());
  std::set<std::size_t> wallVariants;
  for (std::size_t j = 0; j < blocks.blockCount(); ++j)
    if (blocks.block(j).wallVariant != kAir)
      wallVariants.insert(blocks.blockIndex(blocks.block(j).wallVariant));
  std::vector<BlockId> states;
  for (std::size_t i = 0; i < blocks.blockCount(); ++i) {
    const BlockType& type = blocks.block(i);
    if (type.defaultState == kAir || type.shape == BlockShape::None || !type.placeable) continue;
    if (wallVariants.contains(i) || leftOut.contains(type.name)) continue;
    // Fences, panes and walls show a piece running across, not their lone post.
    BlockId state = type.defaultState;
    if (type.connects != Connects::None && type.connects != Connects::Gate) {
      for (const char* side : {"east", "west"}) {
        state = blocks.with(state, side, "true").value_or(blocks.with(state, side, "low").value_or(state));
      }
    }
    // Out of water (corals, pickles and conduits default to waterlogged), growing plants grown.
    state = blocks.with(state, "waterlogged", "false").value_or(state);
    for (const BlockProperty& p : type.properties)
      if (p.name == "age") state = blocks.with(state, "age", p.values.back()).value_or(state);
    // Growths that hold to faces (vines, lichen) and tripwire hold none by default: show two held.
    const auto holds = [&](const char* side) {
      return blocks.with(state, side, "true") == std::optional(state);
    };
    if (type.connects == Connects::None && !holds("north") && !holds("east") && !holds("south") &&
        !holds("west")) {
      for (const char* side : {"north", "south"}) state = blocks.with(state, side, "true").value_or(state);
    }
    states.push_back(state);
  }
  return states;
}

}  // namespace terrasol
