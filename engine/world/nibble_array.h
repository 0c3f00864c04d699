#pragma once
// 4096 light levels (0..15) for one 16³ section, two per byte: 2048 bytes, in Section::index order
// (the low nibble holds the even index). A uniform array (all 15 in open sky, all 0 underground)
// stores no bytes at all; writing a different level allocates them.

#include <array>
#include <cstdint>
#include <memory>

namespace terrasol {

class NibbleArray {
 public:
  static constexpr int kBytes = 2048;
  using Bytes = std::array<std::uint8_t, kBytes>;

  explicit NibbleArray(std::uint8_t uniform = 0) : uniform_(uniform) {}
  NibbleArray(const NibbleArray& other)
      : data_(other.data_ ? std::make_unique<Bytes>(*other.data_) : nullptr), uniform_(other.uniform_) {}
  NibbleArray& operator=(const NibbleArray& other) {
    if (this != &other) *this = NibbleArray(other);
    return *this;
  }
  NibbleArray(NibbleArray&&) noexcept = default;
  NibbleArray& operator=(NibbleArray&&) noexcept = default;

  std::uint8_t get(int index) const {
    if (!data_) return uniform_;
    return static_cast<std::uint8_t>(((*data_)[static_cast<std::size_t>(index >> 1)] >> ((index & 1) * 4)) & 15);
  }
  void set(int index, std::uint8_t level) {
    if (!data_) {
      if (level == uniform_) return;
      data_ = std::make_unique<Bytes>();
      data_->fill(static_cast<std::uint8_t>(uniform_ * 0x11));
    }
    std::uint8_t& byte = (*data_)[static_cast<std::size_t>(index >> 1)];
    const int shift = (index & 1) * 4;
    byte = static_cast<std::uint8_t>((byte & ~(15 << shift)) | (level << shift));
  }
  void fill(std::uint8_t level) {
    data_.reset();
    uniform_ = level;
  }
  // Frees the bytes when every level is the same.
  void compact() {
    if (!data_) return;
    const std::uint8_t first = (*data_)[0];
    if ((first & 15) != (first >> 4)) return;
    for (std::uint8_t b : *data_) {
      if (b != first) return;
    }
    fill(first & 15);
  }

  bool isUniform() const { return !data_; }
  std::uint8_t uniformLevel() const { return uniform_; }  // meaningful when isUniform()
  std::size_t memoryBytes() const { return data_ ? kBytes : 0; }

 private:
  std::unique_ptr<Bytes> data_;
  std::uint8_t uniform_ = 0;
};

}  // namespace terrasol
