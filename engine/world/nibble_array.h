#pragma once
// 4096 light levels (0..15) for one 16³ section, two per byte: 2048 bytes, in Section::index order
// (the low nibble holds the even index). A uniform array (all 15 in open sky, all 0 underground)
// stores no bytes at all; writing a different level allocates them.

#include <array>
#include <cstdint>
#include <memory>

#include "core/light_level.h"
#include "world/coords.h"

namespace terrasol {

class NibbleArray {
 public:
  static constexpr int kBytes = kChunkSize * kChunkArea / 2;  // two levels a byte
  static_assert(kBytes == 2048);
  using Bytes = std::array<std::uint8_t, kBytes>;

  explicit NibbleArray(std::uint8_t uniform = 0) : read_(uniformBytes(uniform)), uniform_(uniform) {}
  NibbleArray(const NibbleArray& other)
      : owned_(other.owned_ ? std::make_unique<Bytes>(*other.owned_) : nullptr),
        read_(owned_ ? owned_->data() : other.read_),
        uniform_(other.uniform_) {}
  NibbleArray& operator=(const NibbleArray& other) {
    if (this != &other) *this = NibbleArray(other);
    return *this;
  }
  NibbleArray(NibbleArray&& other) noexcept
      : owned_(std::move(other.owned_)), read_(other.read_), uniform_(other.uniform_) {
    other.fill(0);
  }
  NibbleArray& operator=(NibbleArray&& other) noexcept {
    owned_ = std::move(other.owned_);
    read_ = other.read_;
    uniform_ = other.uniform_;
    other.fill(0);
    return *this;
  }

  // Branch-free: a uniform array reads from a shared constant buffer of its level.
  std::uint8_t get(int index) const { return get(read_, index); }
  void set(int index, std::uint8_t level) {
    if (!owned_ && level == uniform_) return;
    set(writableBytes(), index, level);
  }
  // Reads a level from bytes() or writableBytes(): for loops that read many levels.
  static std::uint8_t get(const std::uint8_t* bytes, int index) {
    return static_cast<std::uint8_t>((bytes[index >> 1] >> ((index & 1) * 4)) & kLightMask);
  }
  // Sets a level in bytes from writableBytes(): for loops that write many levels.
  static void set(std::uint8_t* bytes, int index, std::uint8_t level) {
    std::uint8_t& byte = bytes[index >> 1];
    const int shift = (index & 1) * 4;
    byte = static_cast<std::uint8_t>((byte & ~(kLightMask << shift)) | (level << shift));
  }
  // The bytes to write through, allocated (holding the uniform level) on first use; valid until the
  // next fill().
  std::uint8_t* writableBytes() {
    if (!owned_) {
      owned_ = std::make_unique<Bytes>();
      owned_->fill(static_cast<std::uint8_t>(uniform_ * 0x11));
      read_ = owned_->data();
    }
    return owned_->data();
  }
  // Bytes for a caller that writes all 2048 of them, not filled: those in `spare` if it holds any
  // (from release()), else new ones.
  std::uint8_t* overwrittenBytes(std::unique_ptr<Bytes>& spare) {
    if (!owned_) {
      owned_ = spare ? std::move(spare) : std::make_unique_for_overwrite<Bytes>();
      read_ = owned_->data();
    }
    return owned_->data();
  }
  // fill(level), handing the bytes it held (if any) to the caller for reuse.
  std::unique_ptr<Bytes> release(std::uint8_t level) {
    std::unique_ptr<Bytes> bytes = std::move(owned_);
    fill(level);
    return bytes;
  }
  void fill(std::uint8_t level) {
    owned_.reset();
    uniform_ = level;
    read_ = uniformBytes(level);
  }
  // The bytes get() reads (the shared buffer while uniform); valid until the next set() or fill().
  const std::uint8_t* bytes() const { return read_; }

  bool isUniform() const { return !owned_; }
  std::uint8_t uniformLevel() const { return uniform_; }  // meaningful when isUniform()
  std::size_t memoryBytes() const { return owned_ ? kBytes : 0; }

 private:
  // A shared read-only buffer per level: 32 KiB for the whole process.
  static const std::uint8_t* uniformBytes(std::uint8_t level) {
    static const auto buffers = [] {
      std::array<Bytes, kLightLevels> all;
      for (int l = 0; l < kLightLevels; ++l)
        all[static_cast<std::size_t>(l)].fill(static_cast<std::uint8_t>(l * 0x11));
      return all;
    }();
    return buffers[level & kLightMask].data();
  }

  std::unique_ptr<Bytes> owned_;
  const std::uint8_t* read_;  // owned_ bytes, or the uniform level's shared buffer
  std::uint8_t uniform_ = 0;
};

}  // namespace terrasol
