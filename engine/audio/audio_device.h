#pragma once
// The OpenAL Soft device and its context: the default output, or a loopback device that renders
// only when asked (tests and --audio-out write what the game plays, in step with its frames, with
// no sound card). One at a time: its context is the process's current one.

#include <cstdint>
#include <span>
#include <string>

namespace terrasol {

enum class AudioOutput { Speakers, Loopback };

class AudioDevice {
 public:
  static constexpr int kLoopbackRate = 44100;

  // Throws Error when there is no device to open (no sound server, no card) or no context on it.
  AudioDevice(AudioOutput output, int voices);
  ~AudioDevice();
  AudioDevice(const AudioDevice&) = delete;
  AudioDevice& operator=(const AudioDevice&) = delete;

  const std::string& name() const { return name_; }
  AudioOutput output() const { return output_; }
  int rate() const { return rate_; }
  // Mono sources the context grants (at most what was asked for).
  int voices() const { return voices_; }
  // The EFX extension, for the under-water low-pass filter.
  bool efx() const { return efx_; }
  // Loopback only: the next frames of interleaved stereo (out.size() / 2 frames).
  void render(std::span<std::int16_t> out);

 private:
  AudioOutput output_;
  void* device_ = nullptr;   // ALCdevice*: OpenAL's header stays out of the game's
  void* context_ = nullptr;  // ALCcontext*
  std::string name_;
  int rate_ = kLoopbackRate, voices_ = 0;
  bool efx_ = false;
  void* renderSamples_ = nullptr;  // alcRenderSamplesSOFT
};

}  // namespace terrasol
