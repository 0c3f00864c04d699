#include "light/light_frame.h"

#include <cassert>

namespace terrasol::light {

ChunkWindow::ChunkWindow(World& world, ChunkPos lo, ChunkPos hi, const Chunk* excluded)
    : min(lo), width(hi.x - lo.x + 1), depth(hi.z - lo.z + 1) {
  assert(width <= kMaxFrameChunks && depth <= kMaxFrameChunks);
  chunks.resize(static_cast<std::size_t>(width * depth));
  for (int z = 0; z < depth; ++z)
    for (int x = 0; x < width; ++x) {
      Chunk* chunk = world.chunk({min.x + x, min.z + z});
      chunks[static_cast<std::size_t>(z * width + x)] = chunk && chunk != excluded && chunk->light().lit ? chunk : nullptr;
    }
}

LightFrame::LightFrame(const ChunkWindow& window, LightChannel channel)
    : window_(window),
      channel_(channel),
      minX_(window.min.x),
      minZ_(window.min.z),
      width_(window.width),
      depth_(window.depth),
      refs_(static_cast<std::size_t>(width_ * depth_ * kSectionCount)),
      resolved_(static_cast<std::size_t>(width_ * depth_), false) {}

void LightFrame::resolve(int index) {
  resolved_[static_cast<std::size_t>(index)] = true;
  Chunk* chunk = window_.chunks[static_cast<std::size_t>(index)];
  if (!chunk) return;  // refs stay empty: not loaded
  ChunkLight& light = chunk->light();
  for (int s = 0; s < kSectionCount; ++s) {
    SectionRef& r = refs_[static_cast<std::size_t>(index * kSectionCount + s)];
    r.layer = channel_ == LightChannel::Block ? &light.block[static_cast<std::size_t>(s)]
                                              : &light.sky[static_cast<std::size_t>(s)];
    r.light = r.layer->bytes();
    const Section& section = chunk->section(s);
    r.blocks = section.blocks() ? section.blocks()->data() : nullptr;
    r.uniform = section.uniformBlock();
    r.skyTop = light.skyTop.data();
  }
}

}  // namespace terrasol::light
