#include "game_audio.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/log.h"
#include "world/block_sounds.h"
#include "world/coords.h"

namespace terrasol {
namespace {

glm::vec3 toVec(glm::dvec3 v) {
  return glm::vec3(v);
}

}  // namespace

GameAudio::GameAudio(const GameOptions& options, const BlockRegistry& blocks) : sounds_(blocks) {
  const AudioOutput output = options.audioOut.empty() ? AudioOutput::Speakers : AudioOutput::Loopback;
  try {
    engine_ = std::make_unique<AudioEngine>(output);
    logInfo("sound: " + deviceLine());
    if (output == AudioOutput::Loopback)
      wav_ = std::make_unique<WavWriter>(options.audioOut, 2, engine_->device().rate());
  } catch (const Error& e) {
    engine_.reset();
    logWarning(std::string("no sound: ") + e.what() + "; the game runs silent");
  }
  if (!options.soundLog.empty()) {
    log_.open(options.soundLog, std::ios::trunc);
    if (!log_) logWarning(options.soundLog.string() + ": cannot be written; no sound log");
  }
}

GameAudio::~GameAudio() {
  if (frames_ > 0 && engine_)
    logInfo("sound: " + std::to_string(totalMs_ / static_cast<double>(frames_)).substr(0, 5) +
            " ms of the main thread a frame on average, at most " + std::to_string(maxMs_).substr(0, 5) +
            " ms, over " + std::to_string(frames_) + " frames");
}

void GameAudio::setPacks(const PackStack& packs) {
  if (!engine_) return;
  std::vector<std::string> problems;
  engine_->setPacks(packs, problems);
  // The sounds every walk and dig plays, decoded before they are first needed.
  for (const SoundGroup& g : soundGroups()) {
    if (g.like != g.name || g.name == kSilentSoundGroup) continue;
    for (const char* action : {"break", "place", "step"})
      engine_->preload("block." + std::string(g.name) + "." + action);
  }
  for (const std::string& p : problems) logWarning(p);
}

void GameAudio::setVolumes(const AudioVolumes& volumes) {
  if (engine_) engine_->setVolumes(volumes);
}

void GameAudio::tick(const PlayWorld& world, const std::optional<DigHit>& hit) {
  const auto start = std::chrono::steady_clock::now();
  tickSounds(world, hit);
  ticksMs_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void GameAudio::tickSounds(const PlayWorld& world, const std::optional<DigHit>& hit) {
  const std::int64_t now = world.level().time;
  const Player& player = world.player();
  footsteps_.tick(player, world.world(), sounds_, now, cues_);
  if (hit) {
    if (auto cue = sounds_.cue(hit->state, hit->at, BlockAction::Hit, now)) cues_.push_back(std::move(*cue));
  }
  ambience_.tick(world.world(), world.light(), sounds_, player.eye(), now, random_, cues_);
  if (!engine_) return;
  if (const auto event = music_.tick(engine_->musicPlaying(), MusicTimer::night(now), random_)) {
    const std::string_view chosen = engine_->events().find(*event) ? *event : MusicTimer::kDay;
    SoundCue cue;
    cue.sound.event = std::string(chosen);
    cue.sound.positional = false;
    cue.sound.category = SoundCategory::Music;
    cue.tick = now;
    log(cue, engine_->playMusic(chosen, static_cast<std::uint32_t>(random_())));
  }
}

void GameAudio::frame(PlayWorld& world, glm::dvec3 eye, glm::dvec3 forward, double seconds) {
  const auto start = std::chrono::steady_clock::now();
  const std::int64_t now = world.level().time;
  std::optional<SoundCue> last;
  for (const StateChange& c : world.takeStateChanges()) {
    std::optional<SoundCue> cue = sounds_.editCue(c.before, c.after, c.pos, now);
    // A door's two halves, a bed's two parts: one sound.
    if (!cue || (last && last->sound.event == cue->sound.event &&
                 glm::length(last->sound.at - cue->sound.at) <= 1.01f))
      continue;
    cues_.push_back(*cue);
    last = cue;
  }
  if (engine_) {
    const glm::dvec3 up = std::abs(forward.y) > 0.999 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
    engine_->setListener(toVec(eye), toVec(forward), toVec(up));
    engine_->setUnderwater(ambience_.underwater());
    engine_->setLoop(kUnderwaterLoop, ambience_.underwater() ? 1.0f : 0.0f, SoundCategory::Ambient,
                     static_cast<std::uint32_t>(random_()));
    engine_->setLoop(kWindLoop, ambience_.wind(), SoundCategory::Ambient,
                     static_cast<std::uint32_t>(random_()));
  }
  for (const SoundCue& cue : cues_) play(cue);
  cues_.clear();
  if (engine_) {
    engine_->update();
    for (const std::string& p : engine_->takeProblems()) logWarning(p);
  }
  frameMs_ =
      ticksMs_ + std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ticksMs_ = 0.0;
  totalMs_ += frameMs_;
  maxMs_ = std::max(maxMs_, frameMs_);
  ++frames_;
  if (wav_ && engine_) {
    unrendered_ += seconds * engine_->device().rate();
    const auto frames = static_cast<std::size_t>(std::floor(unrendered_));
    unrendered_ -= static_cast<double>(frames);
    mix_.resize(frames * 2);
    engine_->render(mix_);
    wav_->write(mix_);
    rendered_ += frames;
  }
}

std::string GameAudio::deviceLine() const {
  if (!engine_) return "No audio device: the game is silent.";
  return engine_->device().name() + ", " + std::to_string(engine_->device().voices()) + " voices" +
         (wav_ ? " (into the --audio-out file)" : "");
}

std::string GameAudio::overlayLine() const {
  if (!engine_) return "Sound: off (no audio device)";
  const AudioStats s = engine_->stats();
  char line[128];
  std::snprintf(line, sizeof line, "Sound: %d/%d voices%s%s, %.2f ms", s.playing, s.voices,
                s.music ? ", music" : "", ambience_.underwater() ? ", under water" : "", frameMs_);
  return line;
}

void GameAudio::play(const SoundCue& cue) {
  std::optional<std::string> file;
  if (engine_) file = engine_->play(cue.sound, static_cast<std::uint32_t>(random_()));
  log(cue, file);
}

void GameAudio::log(const SoundCue& cue, const std::optional<std::string>& file) {
  if (!log_.is_open()) return;
  using nlohmann::json;
  json line = {{"tick", cue.tick}, {"event", cue.sound.event}, {"file", file ? json(*file) : json(nullptr)}};
  if (cue.sound.positional) line["at"] = {cue.sound.at.x, cue.sound.at.y, cue.sound.at.z};
  if (wav_) line["sample"] = rendered_;  // the .wav's frame where it starts
  log_ << line.dump() << '\n';
  log_.flush();
}

}  // namespace terrasol
