#pragma once
// A lit world of 3 x 3 chunks to build shapes in and mesh, for the mesher's tests: the table decides
// how blocks are drawn (numbered textures, or a real atlas's).

#include <memory>
#include <string>

#include "light/light_engine.h"
#include "mesh/mesh_scheduler.h"
#include "mesh/mesher.h"
#include "support/world_support.h"
#include "world/generator.h"

namespace terrasol::testing {

struct MeshWorld {
  explicit MeshWorld(BlockMeshTable meshTable, const std::string& generator = "void")
      : world(defaultBlocks(), &handShapes()), light(world), table(std::move(meshTable)) {
    gen = makeGenerator({generator, 3, {}}, defaultBlocks());
    for (int z = -1; z <= 1; ++z)
      for (int x = -1; x <= 1; ++x) {
        auto c = std::make_unique<Chunk>(ChunkPos{x, z});
        gen->generate(*c);
        world.insertChunk(std::move(c));
        light.chunkLoaded({x, z});
      }
  }
  void set(const BlockPos& p, const std::string& name) {
    if (auto change = world.setBlock(p, defaultBlocks().id(name))) light.blockChanged(*change);
  }
  SectionMesh mesh(SectionPos s = {0, sectionOf(64), 0}) {
    SectionSnapshot snapshot;
    if (captureSection(world, s, snapshot) != CaptureResult::Captured) return SectionMesh{s, {}};
    return meshSection(snapshot, table);
  }
  std::size_t quads(MeshLayer layer, SectionPos s = {0, sectionOf(64), 0}) {
    return mesh(s).layers[static_cast<std::size_t>(layer)].faces();  // block faces, before merging
  }

  World world;
  LightEngine light;
  BlockMeshTable table;
  std::unique_ptr<ChunkGenerator> gen;
};

}  // namespace terrasol::testing
