#include "light/light_frame.h"

#include <algorithm>
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

void LightFrame::reset(const ChunkWindow& window, LightChannel channel) {
  window_ = &window;
  channel_ = channel;
  minX_ = window.min.x;
  minZ_ = window.min.z;
  width_ = window.width;
  depth_ = window.depth;
  const auto chunks = static_cast<std::size_t>(width_ * depth_);
  if (refs_.size() < chunks * kSectionCount) refs_.resize(chunks * kSectionCount);
  resolved_.assign(chunks, 0);
  resolvedList_.clear();
}

void LightFrame::resolve(int index) {
  resolved_[static_cast<std::size_t>(index)] = 1;
  resolvedList_.push_back(index);
  Chunk* chunk = window_->chunks[static_cast<std::size_t>(index)];
  SectionRef* refs = chunkRefs(index);
  if (!chunk) {
    std::fill(refs, refs + kSectionCount, SectionRef{});  // not loaded
    return;
  }
  ChunkLight& light = chunk->light();
  for (int s = 0; s < kSectionCount; ++s) {
    SectionRef& r = refs[s];
    r.layer = channel_ == LightChannel::Block ? &light.block[static_cast<std::size_t>(s)]
                                              : &light.sky[static_cast<std::size_t>(s)];
    r.light = r.layer->bytes();
    r.write = nullptr;
    const Section& section = chunk->section(s);
    r.uniform = section.uniformBlock();
    r.blocks = section.blocks() ? section.blocks()->data() : &r.uniform;
    r.blockMask = section.blocks() ? Section::kVolume - 1 : 0;
    r.marks = 0;
    r.skyTop = light.skyTop.data();
  }
}

}  // namespace terrasol::light
