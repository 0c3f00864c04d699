#pragma once
// Which voice a new sound takes when voices are few (Minecraft allows 247): a free one, else the
// quietest playing one if the new sound is louder than it; otherwise the new sound is not played.
// Plain C++: the audio engine keeps one slot per OpenAL source.

#include <optional>
#include <vector>

namespace terrasol {

class VoicePool {
 public:
  explicit VoicePool(int voices) : loudness_(static_cast<std::size_t>(voices), kFree) {}

  // The slot for a sound heard at `loudness` (its gain at the listener, > 0), now busy; none when
  // every voice plays something at least as loud.
  std::optional<int> claim(float loudness);
  void release(int slot) { loudness_[static_cast<std::size_t>(slot)] = kFree; }
  // A playing sound's loudness as the listener moves.
  void setLoudness(int slot, float loudness) { loudness_[static_cast<std::size_t>(slot)] = loudness; }
  bool busy(int slot) const { return loudness_[static_cast<std::size_t>(slot)] != kFree; }
  int size() const { return static_cast<int>(loudness_.size()); }
  int busyCount() const;

 private:
  static constexpr float kFree = -1.0f;
  std::vector<float> loudness_;
};

}  // namespace terrasol
