#pragma once
// Plays the packs' sound events through OpenAL Soft: positional voices that fade out linearly to
// their event's reach (16 blocks unless the pack says otherwise; farther for volumes over 1, as in
// Minecraft), at most `voices` at once with the quietest dropped first, loops at the listener
// (wind, under water), streamed music, volumes per category, and a low-pass filter while the
// listener is under water. The game says what to play; the renderer and the world never see it.

#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "assets/resource_pack.h"
#include "assets/sound_events.h"
#include "audio/audio_device.h"

namespace terrasol {

enum class SoundCategory : std::uint8_t { Blocks, Ambient, Music };

struct AudioVolumes {
  float master = 1.0f, blocks = 1.0f, ambient = 1.0f, music = 1.0f;  // 0..1
  float of(SoundCategory c) const;                                   // with master
};

struct SoundPlay {
  std::string event;                  // "block.stone.break"
  std::string fallback;               // played where no pack has `event` ("block.stone.step" for deepslate's)
  glm::vec3 at{0.0f};                 // world position
  bool positional = true;             // false: at the listener, at full volume wherever it is
  float volume = 1.0f, pitch = 1.0f;  // times the pack's
  SoundCategory category = SoundCategory::Blocks;
};

struct AudioStats {
  int voices = 0, playing = 0, loops = 0, dropped = 0;  // dropped: sounds no voice was free for
  bool music = false;
  int musicUnderruns = 0;  // times streamed music ran dry: gaps heard
  std::size_t bufferBytes = 0;
};

class AudioEngine {
 public:
  static constexpr int kMaxVoices = 247;  // Minecraft's

  // Throws Error when there is no device (the game then runs silent).
  explicit AudioEngine(AudioOutput output, int voices = kMaxVoices);
  ~AudioEngine();
  AudioEngine(const AudioEngine&) = delete;
  AudioEngine& operator=(const AudioEngine&) = delete;

  // The packs' sound events; problems name their file and key. Stops what plays.
  void setPacks(const PackStack& packs, std::vector<std::string>& problems);
  const SoundEvents& events() const { return events_; }

  // Plays a sound of the event (or its fallback) with `random` choosing among its files. The pack
  // file played, or none: an unknown event, out of reach, no voice, or a file that cannot be read.
  // With speakers a file not yet decoded is promised and starts at the update after it is.
  std::optional<std::string> play(const SoundPlay& sound, std::uint32_t random);
  // `event` looping at the listener at `gain` (0 stops it).
  void setLoop(std::string_view event, float gain, SoundCategory category, std::uint32_t random);
  // Decodes the files of `event` ahead of its first play (with speakers, in the background).
  void preload(std::string_view event);
  // Starts a track of the music event: the file playing, or none when it cannot play.
  std::optional<std::string> playMusic(std::string_view event, std::uint32_t random);
  bool musicPlaying() const;

  void setListener(glm::vec3 position, glm::vec3 forward, glm::vec3 up);
  void setVolumes(const AudioVolumes& volumes);
  void setUnderwater(bool underwater);
  // Once a frame: starts sounds whose files are now decoded, frees finished voices, refills music
  // on a loopback device, follows the listener.
  void update();
  // Loopback only: the next out.size() / 2 frames of interleaved stereo.
  void render(std::span<std::int16_t> out) { device_.render(out); }

  const AudioDevice& device() const { return device_; }
  AudioStats stats() const;
  // Files that could not be played since the last call, each once.
  std::vector<std::string> takeProblems() { return std::exchange(problems_, {}); }

 private:
  // A sound whose file is decoding waits this many updates at most: later it would be out of step.
  static constexpr int kPendingFrames = 30;

  struct Voices;
  struct Loops;
  float loudness(const SoundPlay& sound, float volume, float reach) const;
  // A voice for the sound (its file decoded): false when out of reach or no voice is free.
  bool start(const SoundPlay& sound, const SoundPick& pick);
  void startPending();

  AudioDevice device_;
  SoundEvents events_;
  std::unique_ptr<Voices> voices_;
  std::unique_ptr<Loops> loops_;
  AudioVolumes volumes_;
  glm::vec3 listener_{0.0f};
  bool underwater_ = false;
  int musicUnderruns_ = 0;  // of tracks that have ended
  std::vector<std::string> problems_;
};

}  // namespace terrasol
