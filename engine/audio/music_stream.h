#pragma once
// One long sound (music, a record) streamed through a queue of small buffers on a voice of its own,
// so a track of minutes costs a few hundred milliseconds of memory. With speakers a thread of its
// own keeps the queue full, so a main thread busy loading chunks never lets it run dry; a loopback
// device renders only when the game asks, so there the game's update fills it, in step.

#include <atomic>
#include <memory>
#include <mutex>
#include <thread>

#include "audio/al_objects.h"
#include "audio/ogg_file.h"

namespace terrasol {

class MusicStream {
 public:
  // Plays `track` from its start at `gain`; `threaded` refills on a thread of its own.
  MusicStream(std::unique_ptr<OggStream> track, float gain, bool threaded);
  ~MusicStream();
  MusicStream(const MusicStream&) = delete;
  MusicStream& operator=(const MusicStream&) = delete;

  // Refills played buffers; false once the track has ended and played out. Thread-safe.
  bool pump();
  bool playing() const { return playing_; }
  // Times the queue ran dry and the track stalled: a gap heard.
  int underruns() const { return underruns_; }
  void setGain(float gain);
  ALuint source() const { return source_.id(); }

 private:
  static constexpr int kBuffers = 4;
  static constexpr int kFramesPerBuffer = 8192;  // ~0.19 s at 44.1 kHz: 0.74 s queued

  void start();  // fills the queue and plays
  bool fill(ALuint buffer);

  std::unique_ptr<OggStream> track_;
  AlSource source_;
  AlBuffer buffers_[kBuffers];
  std::vector<std::int16_t> scratch_;
  std::mutex mutex_;
  std::atomic<bool> playing_{true}, ended_{false};
  std::atomic<int> underruns_{0};
  std::jthread thread_;
};

}  // namespace terrasol
