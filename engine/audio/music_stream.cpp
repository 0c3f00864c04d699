#include "audio/music_stream.h"

#include <AL/al.h>

#include <chrono>

#include "core/error.h"
#include "core/log.h"

namespace terrasol {

MusicStream::MusicStream(std::unique_ptr<OggStream> track, float gain, bool threaded)
    : track_(std::move(track)),
      source_(makeSource()),
      scratch_(static_cast<std::size_t>(kFramesPerBuffer * track_->channels())) {
  if (!source_) {
    playing_ = false;
    return;
  }
  alSourcei(source_.id(), AL_SOURCE_RELATIVE, AL_TRUE);
  alSource3f(source_.id(), AL_POSITION, 0.0f, 0.0f, 0.0f);
  alSourcef(source_.id(), AL_GAIN, gain);
  for (AlBuffer& b : buffers_) b = makeBuffer();
  if (!threaded) {
    start();
    return;
  }
  // The first buffers are decoded on the stream's thread too: starting a track costs the caller nothing.
  thread_ = std::jthread([this](std::stop_token stop) {
    start();
    while (!stop.stop_requested() && pump()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  });
}

void MusicStream::start() {
  const std::lock_guard lock(mutex_);
  for (const AlBuffer& b : buffers_) {
    const ALuint id = b.id();
    if (id && fill(id)) alSourceQueueBuffers(source_.id(), 1, &id);
  }
  alSourcePlay(source_.id());
}

MusicStream::~MusicStream() {
  if (thread_.joinable()) {
    thread_.request_stop();
    thread_.join();
  }
  if (source_) {
    alSourceStop(source_.id());
    alSourcei(source_.id(), AL_BUFFER, 0);  // unqueues everything, so the buffers can go
  }
}

// Decodes the next piece into `buffer`; false at the track's end.
bool MusicStream::fill(ALuint buffer) {
  if (ended_) return false;
  std::size_t frames = 0;
  try {
    frames = track_->read(scratch_);
  } catch (const Error& e) {
    logWarning(e.what());
  }
  if (frames == 0) {
    ended_ = true;
    return false;
  }
  alBufferData(
      buffer, track_->channels() == 2 ? AL_FORMAT_STEREO16 : AL_FORMAT_MONO16, scratch_.data(),
      static_cast<ALsizei>(frames * static_cast<std::size_t>(track_->channels()) * sizeof(std::int16_t)),
      track_->rate());
  return true;
}

bool MusicStream::pump() {
  const std::lock_guard lock(mutex_);
  if (!playing_) return false;
  ALint processed = 0, queued = 0, state = 0;
  alGetSourcei(source_.id(), AL_BUFFERS_PROCESSED, &processed);
  while (processed-- > 0) {
    ALuint buffer = 0;
    alSourceUnqueueBuffers(source_.id(), 1, &buffer);
    if (fill(buffer)) alSourceQueueBuffers(source_.id(), 1, &buffer);
  }
  alGetSourcei(source_.id(), AL_BUFFERS_QUEUED, &queued);
  alGetSourcei(source_.id(), AL_SOURCE_STATE, &state);
  if (queued == 0) {
    playing_ = false;
  } else if (state != AL_PLAYING) {
    ++underruns_;
    alSourcePlay(source_.id());  // ran dry for a moment: carry on rather than stop
  }
  return playing_;
}

void MusicStream::setGain(float gain) {
  const std::lock_guard lock(mutex_);
  if (source_) alSourcef(source_.id(), AL_GAIN, gain);
}

}  // namespace terrasol
