#pragma once
// The game's sound: what the world and the player do, heard. Block edits, footsteps, falls,
// ambience and music become cues (plain C++: block_sound_cues.h, footsteps.h, ambience.h,
// music_timer.h) played by the audio engine with the listener at the camera. Without an audio
// device the game runs silent and says so once; --audio-out plays into a .wav in step with the
// frames instead, --sound-log writes every cue.

#include <fstream>
#include <memory>
#include <random>
#include <vector>

#include "ambience.h"
#include "audio/audio_engine.h"
#include "audio/wav_file.h"
#include "block_sound_cues.h"
#include "digging.h"
#include "footsteps.h"
#include "music_timer.h"
#include "options.h"
#include "play_world.h"

namespace terrasol {

class GameAudio {
 public:
  GameAudio(const GameOptions& options, const BlockRegistry& blocks);
  ~GameAudio();

  void setPacks(const PackStack& packs);
  void setVolumes(const AudioVolumes& volumes);
  // After each tick of the player and the world's clock: steps, falls, the block `hit` while dug,
  // ambience, music.
  void tick(const PlayWorld& world, const std::optional<DigHit>& hit);
  // Once a frame after its ticks: the player's edits heard, the listener at the camera (`eye`,
  // looking along `forward`), and with --audio-out `seconds` of sound rendered into the file.
  void frame(PlayWorld& world, glm::dvec3 eye, glm::dvec3 forward, double seconds);

  bool on() const { return engine_ != nullptr; }
  AudioStats stats() const { return engine_ ? engine_->stats() : AudioStats{}; }
  double frameMs() const { return frameMs_; }  // the last frame's cost on this thread, its ticks' too
  // The device and its voices, or that there is none and the game is silent.
  std::string deviceLine() const;
  // For F3: voices playing, music, the cost per frame.
  std::string overlayLine() const;

 private:
  void tickSounds(const PlayWorld& world, const std::optional<DigHit>& hit);
  void play(const SoundCue& cue);
  void log(const SoundCue& cue, const std::optional<std::string>& file);

  std::unique_ptr<AudioEngine> engine_;
  BlockSoundTable sounds_;
  Footsteps footsteps_;
  Ambience ambience_;
  MusicTimer music_;
  std::mt19937 random_{20260};  // fixed: a scripted run hears the same sounds every time
  std::vector<SoundCue> cues_;
  std::unique_ptr<WavWriter> wav_;
  std::vector<std::int16_t> mix_;
  double unrendered_ = 0.0;     // frames owed to the .wav, carried between frames
  std::uint64_t rendered_ = 0;  // frames in the .wav so far: where a sound played now starts
  std::ofstream log_;
  double frameMs_ = 0.0, ticksMs_ = 0.0;  // this frame's, so far
  double totalMs_ = 0.0, maxMs_ = 0.0;    // over the run, said at the end
  std::int64_t frames_ = 0;
};

}  // namespace terrasol
