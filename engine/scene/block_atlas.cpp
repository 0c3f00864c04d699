#include "scene/block_atlas.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <set>
#include <tuple>

#include "assets/block_model.h"
#include "assets/block_states.h"
#include "assets/model_bake.h"
#include "core/error.h"
#include "core/json_check.h"
#include "core/model_units.h"
#include "core/paths.h"

namespace terrasol {
namespace {

// A model's texture name ("block/oak_planks") as the block texture loader looks it up ("oak_planks").
std::vector<std::string> candidatesOf(const std::string& texture) {
  const std::string prefix = "block/";
  return {texture.compare(0, prefix.size(), prefix) == 0 ? texture.substr(prefix.size()) : texture};
}

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
// of the weighted models k a state picks among by position (the mesher's per-cell pick). A block
// whose blockstates or models cannot be read gets the missing cube instead, and the reason goes to
// `problems`; one of Minecraft's blocks that blocks.json leaves out and no pack describes gets it too,
// as a placeholder named in `placeholders`.
template <class Use, class Alternative>
void forEachModelOfEachState(const BlockRegistry& blocks, const PackStack& packs,
                             std::vector<PackProblem>& problems, std::vector<std::string>* placeholders,
                             Use&& use, Alternative&& alternative) {
  ModelLibrary library(packs);
  static const BlockModel kMissing = missingModel();
  for (std::size_t b = 0; b < blocks.blockCount(); ++b) {
    const BlockType& type = blocks.block(b);
    if (type.shape != BlockShape::Model) continue;
    using Models = std::vector<std::pair<const BlockModel*, ModelPlacement>>;
    std::vector<Models> models(type.stateCount), choices(type.stateCount);
    if (!type.inBlocksJson && !packs.find(BlockStates::pathOf(type.name))) {
      if (placeholders) placeholders->push_back(type.name);
      for (std::uint16_t i = 0; i < type.stateCount; ++i)
        use(static_cast<BlockId>(type.firstState + i), kMissing, ModelPlacement{});
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
      std::map<StateValues, std::uint16_t> picked;
      for (std::uint16_t i = 0; i < type.stateCount; ++i) {
        StateValues values = blocks.stateValues(static_cast<BlockId>(type.firstState + i));
        std::erase_if(values, [&](const auto& v) { return !named.contains(v.first); });
        const auto [first, added] = picked.try_emplace(values, i);
        if (!added) {
          models[i] = models[first->second];
          choices[i] = choices[first->second];
          continue;
        }
        for (const ModelPlacement& p : states.select(values, {}))
          models[i].emplace_back(&library.model(p.model), p);
        for (const ModelPlacement& p : states.choices(values))
          choices[i].emplace_back(&library.model(p.model), p);
      }
    } catch (const Error& e) {
      problems.push_back({PackProblem::Severity::Error, e.what()});
      for (auto& m : models) m = {{&kMissing, ModelPlacement{}}};
      for (auto& c : choices) c.clear();
    }
    for (std::uint16_t i = 0; i < type.stateCount; ++i) {
      const auto state = static_cast<BlockId>(type.firstState + i);
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

// Model blocks: each state's models baked, and their boxes; per state picking among weighted models
// by position, each choice's weight, quads and boxes.
struct BakedChoice {
  int weight = 1;
  std::vector<BakedQuad> quads;
  std::vector<ShapeBox> boxes;
};
struct BakedStates {
  std::vector<std::vector<BakedQuad>> quads;
  std::vector<std::vector<ShapeBox>> boxes;
  std::vector<std::vector<BakedChoice>> choices;
};
BakedStates bakeModelStates(const BlockRegistry& blocks, const PackStack& packs,
                            std::vector<PackProblem>& problems,
                            std::vector<std::string>* placeholders = nullptr) {
  BakedStates baked{std::vector<std::vector<BakedQuad>>(blocks.size()),
                    std::vector<std::vector<ShapeBox>>(blocks.size()),
                    std::vector<std::vector<BakedChoice>>(blocks.size())};
  // Most states share their models with others (every waterlogged twin, every placeholder): each
  // model and placement is baked once.
  struct Baked {
    std::vector<BakedQuad> quads;
    std::vector<ShapeBox> boxes;
  };
  std::map<std::tuple<const BlockModel*, int, int, bool>, Baked> bakedOnce;
  forEachModelOfEachState(
      blocks, packs, problems, placeholders,
      [&](BlockId s, const BlockModel& m, const ModelPlacement& p) {
        auto [it, added] = bakedOnce.try_emplace({&m, p.x, p.y, p.uvlock});
        if (added) it->second = {bakeModel(m, p), boxesOf(m, p)};
        baked.quads[s].insert(baked.quads[s].end(), it->second.quads.begin(), it->second.quads.end());
        baked.boxes[s].insert(baked.boxes[s].end(), it->second.boxes.begin(), it->second.boxes.end());
      },
      [&](BlockId s, std::size_t, const BlockModel& m, const ModelPlacement& p) {
        baked.choices[s].push_back({p.weight, bakeModel(m, p), boxesOf(m, p)});
      });
  return baked;
}

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

BlockAtlas buildBlockAtlas(const BlockRegistry& blocks, const PackStack& packs) {
  BlockAtlas result;
  const BakedStates baked = bakeModelStates(blocks, packs, result.problems, &result.placeholders);
  // A state drawn as the one before it (its waterlogged twin, a placeholder's every state) takes its
  // textures and quads.
  std::vector<bool> asBefore(blocks.size());
  for (BlockId id = 1; id < blocks.size(); ++id) {
    asBefore[id] = baked.choices[id].empty() && baked.choices[id - 1].empty() &&
                   baked.quads[id] == baked.quads[id - 1] && baked.boxes[id] == baked.boxes[id - 1] &&
                   blocks[id].textures == blocks[id - 1].textures;
  }
  // Each distinct candidate list is loaded once, in a stable order.
  std::map<std::vector<std::string>, std::uint16_t> index;
  for (BlockId id = 0; id < blocks.size(); ++id) {
    if (asBefore[id]) continue;
    for (const auto& face : blocks[id].textures) {
      if (!face.empty()) index.emplace(face, 0);
    }
    for (const BakedQuad& q : baked.quads[id]) index.emplace(candidatesOf(q.texture), 0);
    for (const BakedChoice& c : baked.choices[id])
      for (const BakedQuad& q : c.quads) index.emplace(candidatesOf(q.texture), 0);
  }
  std::vector<LoadedTexture> textures;
  for (auto& [candidates, texture] : index) {
    texture = static_cast<std::uint16_t>(textures.size());
    textures.push_back(loadBlockTexture(packs, candidates, result.problems));
  }
  if (textures.empty()) textures.push_back(loadBlockTexture(packs, {"missing"}, result.problems));
  result.atlas = buildAtlas(textures);
  result.faceTextures.resize(blocks.size());
  result.modelQuads.resize(blocks.size());
  result.modelChoices.resize(blocks.size());
  for (BlockId id = 0; id < blocks.size(); ++id) {
    for (int f = 0; f < 6; ++f) {
      const auto& face = blocks[id].textures[static_cast<std::size_t>(f)];
      result.faceTextures[id][static_cast<std::size_t>(f)] = face.empty() ? 0 : index.at(face);
    }
    if (asBefore[id]) {
      result.modelQuads[id] = result.modelQuads[id - 1];
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

TextureCoverage textureCoverage(const BlockRegistry& blocks, const PackStack& packs) {
  // What the game loads for a list of candidates: the first the stack has.
  std::set<std::string> drawn;
  const auto use = [&](const std::vector<std::string>& candidates) {
    for (const std::string& name : candidates) {
      if (packs.findBlockTexture(name + ".png")) {
        drawn.insert(name);
        return;
      }
    }
  };
  std::vector<PackProblem> problems;  // inspect and the atlas report them
  const BakedStates baked = bakeModelStates(blocks, packs, problems);
  for (BlockId id = 0; id < blocks.size(); ++id) {
    for (const auto& face : blocks[id].textures) use(face);
    for (const BakedQuad& q : baked.quads[id]) use(candidatesOf(q.texture));
    for (const BakedChoice& c : baked.choices[id])
      for (const BakedQuad& q : c.quads) use(candidatesOf(q.texture));
  }
  TextureCoverage coverage;
  if (packs.packs().empty()) return coverage;
  std::set<std::string> top;
  for (const std::string& file : packs.packs().back()->blockTextureFiles()) {
    if (!file.ends_with(".png") || file.ends_with("_n.png") || file.ends_with("_s.png")) continue;
    top.insert(file.substr(0, file.size() - 4));
  }
  for (const std::string& name : top)
    (drawn.contains(name) ? coverage.used : coverage.unused).push_back(name);
  return coverage;
}

BlockShapes blockShapesOf(const BlockRegistry& blocks, const PackStack& packs) {
  BlockShapes shapes(blocks);
  std::vector<std::vector<ShapeBox>> boxes(blocks.size());
  std::vector<PackProblem> problems;  // the atlas reports them
  std::map<std::tuple<const BlockModel*, int, int>, std::vector<ShapeBox>> placedOnce;
  forEachModelOfEachState(
      blocks, packs, problems, nullptr,
      [&](BlockId s, const BlockModel& m, const ModelPlacement& p) {
        auto [it, added] = placedOnce.try_emplace({&m, p.x, p.y});
        if (added) it->second = boxesOf(m, p);
        boxes[s].insert(boxes[s].end(), it->second.begin(), it->second.end());
      },
      [](BlockId, std::size_t, const BlockModel&, const ModelPlacement&) {});  // collision: the origin's pick
  for (BlockId s = 0; s < blocks.size(); ++s) {
    if (blocks[s].shape == BlockShape::Model) shapes.setBoxes(s, std::move(boxes[s]));
  }
  return shapes;
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
      [&](BlockId id) { return atlas.modelQuads[id]; }, [&](BlockId id) { return atlas.modelChoices[id]; });
}

}  // namespace terrasol
