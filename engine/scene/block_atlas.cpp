#include "scene/block_atlas.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <set>
#include <tuple>

#include "assets/block_model.h"
#include "assets/block_states.h"
#include "assets/cloud_map.h"
#include "assets/crack_textures.h"
#include "assets/model_bake.h"
#include "assets/tints.h"
#include "core/error.h"
#include "core/json_check.h"
#include "core/model_units.h"
#include "core/paths.h"
#include "scene/texture_names.h"

namespace terrasol {
namespace {

// What Minecraft draws for a block whose blockstates or models cannot be read: a cube of the
// missing texture.
BlockModel missingModel() {
  BlockModel m;
  m.name = "missing";
  ModelElement& e = m.elements.emplace_back();
  for (int f = 0; f < 6; ++f) {
    ElementFace face;
    face.uv = {0.0f, 0.0f, kModelUnits, kModelUnits};
    face.texture = kMissingTexture;
    face.cullface = static_cast<ModelFace>(f);
    e.faces[static_cast<std::size_t>(f)] = face;
  }
  return m;
}

// Calls use(state, model, placement) for every model each state of a model block is drawn with, as
// its blockstates file picks them at the origin, and alternative(state, k, model, placement) for each
// of the weighted models k a state picks among by position (the mesher's per-cell pick); a state that
// picks just as an earlier state of its block did gets same(state, earlier) instead. A block whose
// blockstates or models cannot be read gets the missing cube instead, and the reason goes to
// `problems`; one of Minecraft's blocks that blocks.json leaves out and no pack describes gets it too,
// as a placeholder named in `placeholders`.
template <class Use, class Alternative, class Same>
void forEachModelOfEachState(const BlockRegistry& blocks, const PackStack& packs,
                             std::vector<PackProblem>& problems, std::vector<std::string>* placeholders,
                             Use&& use, Alternative&& alternative, Same&& same) {
  ModelLibrary library(packs);
  static const BlockModel kMissing = missingModel();
  for (std::size_t b = 0; b < blocks.blockCount(); ++b) {
    const BlockType& type = blocks.block(b);
    if (type.shape != BlockShape::Model) continue;
    using Models = std::vector<std::pair<const BlockModel*, ModelPlacement>>;
    std::vector<Models> models(type.stateCount), choices(type.stateCount);
    std::vector<std::uint16_t> sameAs(type.stateCount);  // the first state picking alike, or itself
    for (std::uint16_t i = 0; i < type.stateCount; ++i) sameAs[i] = i;
    if (!type.inBlocksJson && !packs.find(BlockStates::pathOf(type.name))) {
      if (placeholders) placeholders->push_back(type.name);
      use(type.firstState, kMissing, ModelPlacement{});
      for (std::uint16_t i = 1; i < type.stateCount; ++i)
        same(static_cast<BlockId>(type.firstState + i), type.firstState);
      continue;
    }
    try {
      const BlockStates states = BlockStates::load(packs, type.name);
      // States alike in every property the blockstates name pick the same models: picked once.
      const std::set<std::string> named = states.properties();
      // A property the block lacks matches no state: say so, or those states draw nothing unseen.
      for (const std::string& property : named) {
        if (std::none_of(type.properties.begin(), type.properties.end(),
                         [&](const BlockProperty& p) { return p.name == property; })) {
          problems.push_back({PackProblem::Severity::Warning,
                              json_check::join({BlockStates::pathOf(type.name), ": names the property \"",
                                                property, "\", which ", type.name, " does not have"})});
        }
      }
      // A state's offset counts its properties' values in mixed radix; with the unnamed ones zeroed it
      // is the first state alike in every named one.
      const std::size_t n = type.properties.size();
      std::vector<std::size_t> stride(n, 1);
      for (std::size_t k = n; k-- > 1;) stride[k - 1] = stride[k] * type.properties[k].values.size();
      std::vector<std::size_t> namedAt;
      for (std::size_t k = 0; k < n; ++k)
        if (named.contains(type.properties[k].name)) namedAt.push_back(k);
      for (std::uint16_t i = 0; i < type.stateCount; ++i) {
        std::size_t key = 0;
        for (const std::size_t k : namedAt)
          key += i / stride[k] % type.properties[k].values.size() * stride[k];
        if (key != i) {
          sameAs[i] = static_cast<std::uint16_t>(key);
          continue;
        }
        StateValues values = blocks.stateValues(static_cast<BlockId>(type.firstState + i));
        std::erase_if(values, [&](const auto& v) { return !named.contains(v.first); });
        for (const ModelPlacement& p : states.select(values, {}))
          models[i].emplace_back(&library.model(p.model), p);
        for (const ModelPlacement& p : states.choices(values))
          choices[i].emplace_back(&library.model(p.model), p);
      }
    } catch (const Error& e) {
      problems.push_back({PackProblem::Severity::Error, e.what()});
      for (std::uint16_t i = 0; i < type.stateCount; ++i) sameAs[i] = 0;
      models[0] = {{&kMissing, ModelPlacement{}}};
      choices[0].clear();
    }
    for (std::uint16_t i = 0; i < type.stateCount; ++i) {
      const auto state = static_cast<BlockId>(type.firstState + i);
      if (sameAs[i] != i) {
        same(state, static_cast<BlockId>(type.firstState + sameAs[i]));
        continue;
      }
      for (const auto& [model, placement] : models[i]) use(state, *model, placement);
      for (std::size_t k = 0; k < choices[i].size(); ++k)
        alternative(state, k, *choices[i][k].first, choices[i][k].second);
    }
  }
}

// A model's placed boxes in whole 1/16 units.
std::vector<ShapeBox> boxesOf(const BlockModel& model, const ModelPlacement& placement) {
  std::vector<ShapeBox> boxes;
  for (const std::array<float, 6>& b : placedBoxes(model, placement)) {
    const auto at = [&](int i) { return static_cast<int>(std::lround(b[static_cast<std::size_t>(i)])); };
    boxes.push_back({{at(0), at(1), at(2)}, {at(3), at(4), at(5)}});
  }
  return boxes;
}

}  // namespace

BlockModelBake bakeBlockModels(const BlockRegistry& blocks, const PackStack& packs) {
  BlockModelBake baked{std::vector<std::vector<BakedQuad>>(blocks.size()),
                       std::vector<std::vector<ShapeBox>>(blocks.size()),
                       std::vector<std::vector<BakedChoice>>(blocks.size()),
                       std::vector<BlockId>(blocks.size()),
                       {},
                       {}};
  for (BlockId s = 0; s < blocks.size(); ++s) baked.sameAs[s] = s;
  // Most states share their models with others (every waterlogged twin, every placeholder): each
  // model and placement is baked once.
  struct Baked {
    std::vector<BakedQuad> quads;
    std::vector<ShapeBox> boxes;
  };
  std::map<std::tuple<const BlockModel*, int, int, bool>, Baked> bakedOnce;
  forEachModelOfEachState(
      blocks, packs, baked.problems, &baked.placeholders,
      [&](BlockId s, const BlockModel& m, const ModelPlacement& p) {
        auto [it, added] = bakedOnce.try_emplace({&m, p.x, p.y, p.uvlock});
        if (added) it->second = {bakeModel(m, p), boxesOf(m, p)};
        baked.quads[s].insert(baked.quads[s].end(), it->second.quads.begin(), it->second.quads.end());
        baked.boxes[s].insert(baked.boxes[s].end(), it->second.boxes.begin(), it->second.boxes.end());
      },
      [&](BlockId s, std::size_t, const BlockModel& m, const ModelPlacement& p) {
        baked.choices[s].push_back({p.weight, bakeModel(m, p), boxesOf(m, p)});
      },
      [&](BlockId s, BlockId earlier) { baked.sameAs[s] = earlier; });
  return baked;
}

namespace {

int directionOf(ModelFace face) {
  static constexpr Direction kDirections[] = {Direction::Down,  Direction::Up,   Direction::North,
                                              Direction::South, Direction::West, Direction::East};
  return static_cast<int>(kDirections[static_cast<int>(face)]);
}

// The mesher's face basis nearest a quad's normal: an axis, or one of the diagonal planes.
std::uint8_t basisOf(glm::vec3 normal) {
  std::uint8_t best = 3;
  float bestDot = -2.0f;
  for (std::uint8_t i = 0; i < 10; ++i) {
    const float* n = kFaceBases[i].normal;
    const float d = glm::dot(normal, glm::vec3(n[0], n[1], n[2]));
    if (d > bestDot + 1e-4f) {
      bestDot = d;
      best = i;
    }
  }
  return best;
}

ModelQuad meshQuad(const BakedQuad& q, std::uint16_t texture) {
  ModelQuad m;
  for (std::size_t c = 0; c < 4; ++c) {
    for (int a = 0; a < 3; ++a) {
      // 1/32 block; a corner outside the cell (a torch leaning from a wall) is pulled back into it, and
      // one just inside (Minecraft's redstone dust, a quarter texel up) stays a step inside rather than
      // rounding into its neighbour's face.
      const float v = q.corners[c][a] * 32.0f;
      int rounded = std::clamp(static_cast<int>(std::lround(v)), 0, 32);
      if (rounded == 0 && v > 0.0f) rounded = 1;
      if (rounded == 32 && v < 32.0f) rounded = 31;
      m.corners32[c][static_cast<std::size_t>(a)] = rounded;
    }
    m.uvs16[c] = {static_cast<int>(std::lround(q.uvs[c].x * kModelUnits)),
                  static_cast<int>(std::lround(q.uvs[c].y * kModelUnits))};
  }
  m.texture = texture;
  m.face = basisOf(q.normal);
  m.cullface = q.cullface ? static_cast<std::int8_t>(directionOf(*q.cullface)) : std::int8_t{-1};
  m.tinted = q.tintIndex >= 0;
  m.smooth = q.ambientOcclusion && m.face < 6;
  return m;
}

}  // namespace

std::vector<std::vector<std::string>> atlasTextureNames(const BlockRegistry& blocks,
                                                        const BlockModelBake& baked) {
  std::set<std::vector<std::string>> names;
  for (BlockId id = 0; id < blocks.size(); ++id) {
    if (baked.sameAs[id] != id) continue;  // an earlier state's quads, its block's faces
    for (const auto& face : blocks.faceTextures(id)) {
      if (!face.empty()) names.insert(withOlderNames(face));
    }
    for (const BakedQuad& q : baked.quads[id]) names.insert(candidatesOf(q.texture));
    for (const BakedChoice& c : baked.choices[id])
      for (const BakedQuad& q : c.quads) names.insert(candidatesOf(q.texture));
  }
  return {names.begin(), names.end()};
}

BlockAtlas buildBlockAtlas(const BlockRegistry& blocks, const PackStack& packs) {
  return buildBlockAtlas(blocks, packs, bakeBlockModels(blocks, packs));
}

BlockAtlas buildBlockAtlas(const BlockRegistry& blocks, const PackStack& packs, const BlockModelBake& baked) {
  BlockAtlas result;
  result.problems = baked.problems;
  result.placeholders = baked.placeholders;
  result.sameAs = baked.sameAs;
  // A state drawn as an earlier one takes its quads (its face textures are its block's).
  const auto asEarlier = [&](BlockId id) { return baked.sameAs[id] != id; };
  std::map<std::vector<std::string>, std::uint16_t> index;
  std::vector<LoadedTexture> textures;
  for (std::vector<std::string>& candidates : atlasTextureNames(blocks, baked)) {
    index.emplace(candidates, static_cast<std::uint16_t>(textures.size()));
    textures.push_back(loadBlockTexture(packs, candidates, result.problems));
  }
  if (textures.empty()) textures.push_back(loadBlockTexture(packs, {"missing"}, result.problems));
  // The crack drawn over a block being dug, where some pack has it (none drawn otherwise).
  for (int stage = 0; stage < kCrackStages; ++stage) {
    const std::vector<std::string> name{crackTextureName(stage)};
    if (!index.contains(name) && packs.findBlockTextureNamed(name))
      textures.push_back(loadBlockTexture(packs, name, result.problems));
  }
  result.atlas = buildAtlas(textures);
  result.tints = loadColormaps(packs, result.problems);
  result.clouds = loadCloudMap(packs, result.problems);
  result.faceTextures.resize(blocks.size());
  result.modelQuads.resize(blocks.size());
  result.modelChoices.resize(blocks.size());
  for (BlockId id = 0; id < blocks.size(); ++id) {
    const FaceTextures faces = blocks.faceTextures(id);
    for (int f = 0; f < 6; ++f) {
      const auto& face = faces[static_cast<std::size_t>(f)];
      result.faceTextures[id][static_cast<std::size_t>(f)] =
          face.empty() ? 0 : index.at(withOlderNames(face));
    }
    if (asEarlier(id)) {
      result.modelQuads[id] = result.modelQuads[baked.sameAs[id]];
      result.modelChoices[id] = result.modelChoices[baked.sameAs[id]];
      continue;
    }
    for (const BakedQuad& q : baked.quads[id])
      result.modelQuads[id].push_back(meshQuad(q, index.at(candidatesOf(q.texture))));
    occludeByOwnShape(result.modelQuads[id], baked.boxes[id]);
    for (const BakedChoice& c : baked.choices[id]) {
      ModelChoice& choice = result.modelChoices[id].emplace_back();
      choice.weight = c.weight;
      for (const BakedQuad& q : c.quads)
        choice.quads.push_back(meshQuad(q, index.at(candidatesOf(q.texture))));
      occludeByOwnShape(choice.quads, c.boxes);
    }
  }
  return result;
}

BlockShapes blockShapesOf(const BlockRegistry& blocks, const PackStack& packs) {
  return blockShapesOf(blocks, bakeBlockModels(blocks, packs));
}

BlockShapes blockShapesOf(const BlockRegistry& blocks, const BlockModelBake& baked) {
  BlockShapes shapes(blocks);
  for (BlockId s = 0; s < blocks.size(); ++s) {
    if (blocks[s].shape == BlockShape::Model) shapes.setBoxes(s, baked.boxes[baked.sameAs[s]]);
  }
  return shapes;
}

bool isDefaultPackAlone(const PackStack& packs) {
  if (packs.packs().size() != 1) return false;
  std::error_code ec;
  return std::filesystem::equivalent(packs.packs().front()->files().location(), resourcePackDir() / "default",
                                     ec);
}

BlockShapes defaultPackShapes(const BlockRegistry& blocks) {
  PackStack packs;
  packs.push(ResourcePack::open(resourcePackDir() / "default"));
  return blockShapesOf(blocks, packs);
}

std::vector<BlockDrawing> blockDrawings(const BlockRegistry& blocks, const BlockAtlas& atlas) {
  const std::set<std::string> placeholders(atlas.placeholders.begin(), atlas.placeholders.end());
  std::vector<BlockDrawing> drawings(blocks.blockCount());
  for (std::size_t i = 0; i < blocks.blockCount(); ++i) {
    const BlockType& type = blocks.block(i);
    drawings[i] = type.shape == BlockShape::None     ? BlockDrawing::Nothing
                  : placeholders.contains(type.name) ? BlockDrawing::Placeholder
                  : type.shape == BlockShape::Model  ? BlockDrawing::Model
                                                     : BlockDrawing::Derived;
  }
  return drawings;
}

BlockMeshTable meshTableOf(const BlockRegistry& blocks, const BlockAtlas& atlas) {
  return BlockMeshTable(
      blocks, [&](BlockId id, int face) { return atlas.textureOf(id, face); },
      [&](BlockId id) { return atlas.modelQuads[id]; }, [&](BlockId id) { return atlas.modelChoices[id]; },
      [&](BlockId id) { return atlas.sameAs.empty() ? id : atlas.sameAs[id]; }, atlas.tints);
}

}  // namespace terrasol
