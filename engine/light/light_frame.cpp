#include "light/light_frame.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "core/assert.h"
#include "light/level_words.h"

namespace terrasol::light {

ChunkWindow::ChunkWindow(World& world, ChunkPos lo, ChunkPos hi, const Chunk* excluded)
    : min(lo), width(hi.x - lo.x + 1), depth(hi.z - lo.z + 1) {
  TERRASOL_ASSERT(width >= 1 && depth >= 1 && width <= kMaxFrameChunks && depth <= kMaxFrameChunks,
                  "light: a window of " + std::to_string(width) + " x " + std::to_string(depth) + " chunks");
  chunks.resize(static_cast<std::size_t>(width * depth));
  for (int z = 0; z < depth; ++z)
    for (int x = 0; x < width; ++x) {
      Chunk* chunk = world.chunk({min.x + x, min.z + z});
      chunks[static_cast<std::size_t>(z * width + x)] =
          chunk && chunk != excluded && chunk->light().lit ? chunk : nullptr;
    }
}

void LightFrame::reset(const ChunkWindow& window, LightChannel channel) {
  window_ = &window;
  channel_ = channel;
  minX_ = window.min.x;
  minZ_ = window.min.z;
  width_ = window.width;
  depth_ = window.depth;
  stride_ = width_ + 2;
  // Across a face the ref index moves by one section, chunk or row and the cell wraps to the far side.
  const std::int32_t section = 1 << kIndexBits, chunk = kRefSections << kIndexBits, row = stride_ * chunk;
  constexpr std::int32_t wrapX = kLastCell, wrapY = kLastCell * kChunkArea, wrapZ = kLastCell * kChunkSize;
  const std::int32_t steps[6] = {-chunk + wrapX,  chunk - wrapX, -section + wrapY,
                                 section - wrapY, -row + wrapZ,  row - wrapZ};
  std::copy(std::begin(steps), std::end(steps), across_);
  const auto chunks = static_cast<std::size_t>(stride_ * (depth_ + 2));
  if (refs_.size() < chunks * kRefSections) refs_.resize(chunks * kRefSections);
  if (++update_ == 0) {  // wrapped: no ref may look resolved
    for (SectionRef& r : refs_) r.update = 0;
    update_ = 1;
  }
  resolvedList_.clear();
  slabsUsed_ = 0;
}

void LightFrame::resolve(int index) {
  resolvedList_.push_back(index);
  SectionRef* refs = chunkRefs(index);
  SectionRef stamped;
  stamped.update = update_;
  std::fill(refs, refs + kRefSections, stamped);
  const int x = index % stride_ - 1, z = index / stride_ - 1;
  if (x < 0 || x >= width_ || z < 0 || z >= depth_) return;  // the ring around the window
  Chunk* chunk = window_->chunks[static_cast<std::size_t>(z * width_ + x)];
  if (!chunk) return;  // not loaded
  ChunkLight& light = chunk->light();
  for (int s = 0; s < kSectionCount; ++s) {
    SectionRef& r = refs[s + 1];
    r.layer = channel_ == LightChannel::Block ? &light.block[static_cast<std::size_t>(s)]
                                              : &light.sky[static_cast<std::size_t>(s)];
    const Section& section = chunk->section(s);
    r.uniform = section.uniformBlock();
    r.blocks = section.blocks() ? section.blocks()->data() : &r.uniform;
    r.blockMask = section.blocks() ? Section::kVolume - 1 : 0;
    r.emitters = &light.emitters[static_cast<std::size_t>(s)];
    r.shaped = &light.shaped[static_cast<std::size_t>(s)];
    r.skyTop = light.skyTop.data();
    r.minY = sectionMinY(s);
  }
}

Level* LightFrame::takeSlab() {
  if (slabsUsed_ == slabs_.size()) slabs_.push_back(std::make_unique<Slab>());
  return slabs_[slabsUsed_++]->data();
}

void LightFrame::unpack(SectionRef& r) {
  if (r.layer->isUniform()) {
    std::unique_ptr<Slab>& slab = levelSlabs_[r.layer->uniformLevel()];
    if (!slab) {
      slab = std::make_unique<Slab>();
      slab->fill(Level{r.layer->uniformLevel()});
    }
    r.levels = slab->data();
    r.shared = true;
    return;
  }
  r.levels = takeSlab();
  unpackNibbles(r.layer->bytes(), r.levelBytes());
}

void LightFrame::unshare(SectionRef& r) {
  r.levels = takeSlab();
  r.shared = false;
  std::memset(r.levelBytes(), r.layer->uniformLevel(), Section::kVolume);
}

unsigned LightFrame::pack(SectionRef& r) {
  const unsigned marks = r.marks;
  r.marks = 0;
  if (!marks) return 0;
  TERRASOL_ASSERT(!r.shared, "light: cells written into a shared slab");
  NibbleArray& layer = *r.layer;
  const bool wasUniform = layer.isUniform();
  // The bytes a section gave up when its light became uniform wait here for the next that needs
  // some, which saves an allocation and a free per section in a torch placed and taken away again.
  std::unique_ptr<NibbleArray::Bytes> spare;
  if (wasUniform && !spareBytes_.empty()) {
    spare = std::move(spareBytes_.back());
    spareBytes_.pop_back();
  }
  const std::uint8_t before = layer.uniformLevel();
  std::uint8_t* bytes = layer.overwrittenBytes(spare);
  // Only the bands of layers written are packed; new bytes get the old level in the others.
  int level = -2;  // the one level of every band packed so far; -1 once two differ
  unsigned skipped = 0;
  for (int band = 0; band < kBands; ++band) {
    const int begin = band * kBandNibbleBytes, end = begin + kBandNibbleBytes;
    if (marks & bandMark(band)) {
      const int l = packNibbles(r.levelBytes(), bytes, begin, end);
      level = level == -2 || level == l ? l : -1;
    } else {
      skipped |= bandMark(band);
      if (wasUniform) std::memset(bytes + begin, before * 0x11, kBandNibbleBytes);
    }
  }
  // A section back to one level throughout (a torch taken away in the dark) keeps no bytes: the bands
  // not written must have that level too.
  if (level >= 0 && skipped) {
    if (wasUniform) {
      if (level != before) level = -1;
    } else {
      for (int band = 0; band < kBands && level >= 0; ++band) {
        const int begin = band * kBandNibbleBytes;
        if ((skipped & bandMark(band)) && !nibblesAre(bytes, begin, begin + kBandNibbleBytes, level))
          level = -1;
      }
    }
  }
  if (level >= 0) spare = layer.release(static_cast<std::uint8_t>(level));
  if (spare && spareBytes_.size() < kMaxSpareBytes) spareBytes_.push_back(std::move(spare));
  return marks;
}

}  // namespace terrasol::light
