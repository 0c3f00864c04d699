#pragma once
// OpenAL buffers and sources as move-only owners (copy deleted, noexcept move, empty after a move),
// like the renderer's GL objects. They need the audio device's context current.

#include <AL/al.h>

#include <utility>

namespace terrasol {

template <void (*Delete)(ALsizei, const ALuint*)>
class AlObject {
 public:
  AlObject() = default;
  explicit AlObject(ALuint id) : id_(id) {}
  ~AlObject() { reset(); }
  AlObject(const AlObject&) = delete;
  AlObject& operator=(const AlObject&) = delete;
  AlObject(AlObject&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  AlObject& operator=(AlObject&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  ALuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_) Delete(1, &id_);
    id_ = 0;
  }

 private:
  ALuint id_ = 0;
};

inline void deleteBuffers(ALsizei n, const ALuint* ids) {
  alDeleteBuffers(n, ids);
}
inline void deleteSources(ALsizei n, const ALuint* ids) {
  alDeleteSources(n, ids);
}

using AlBuffer = AlObject<deleteBuffers>;
using AlSource = AlObject<deleteSources>;

// A new buffer or source, empty when OpenAL has none left.
inline AlBuffer makeBuffer() {
  ALuint id = 0;
  alGetError();
  alGenBuffers(1, &id);
  return alGetError() == AL_NO_ERROR ? AlBuffer(id) : AlBuffer();
}
inline AlSource makeSource() {
  ALuint id = 0;
  alGetError();
  alGenSources(1, &id);
  return alGetError() == AL_NO_ERROR ? AlSource(id) : AlSource();
}

}  // namespace terrasol
