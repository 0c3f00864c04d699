#include "audio/audio_engine.h"

#include <AL/al.h>
#include <AL/efx.h>

#include <algorithm>
#include <map>

#include "audio/al_objects.h"
#include "audio/music_stream.h"
#include "audio/sound_bank.h"
#include "audio/voice_pool.h"
#include "core/error.h"

namespace terrasol {
namespace {

constexpr float kUnderwaterGainHf = 0.05f;  // the low-pass filter's high frequencies under water

// Minecraft's limits on a sound's pitch.
float clampPitch(float pitch) {
  return std::clamp(pitch, 0.5f, 2.0f);
}

// EFX's filter functions, where the device has them.
struct Efx {
  LPALGENFILTERS gen = nullptr;
  LPALDELETEFILTERS del = nullptr;
  LPALFILTERI filteri = nullptr;
  LPALFILTERF filterf = nullptr;

  static Efx load() {
    Efx e;
    e.gen = reinterpret_cast<LPALGENFILTERS>(alGetProcAddress("alGenFilters"));
    e.del = reinterpret_cast<LPALDELETEFILTERS>(alGetProcAddress("alDeleteFilters"));
    e.filteri = reinterpret_cast<LPALFILTERI>(alGetProcAddress("alFilteri"));
    e.filterf = reinterpret_cast<LPALFILTERF>(alGetProcAddress("alFilterf"));
    return e;
  }
  bool ok() const { return gen && del && filteri && filterf; }
};

}  // namespace

float AudioVolumes::of(SoundCategory c) const {
  const float v = c == SoundCategory::Blocks ? blocks : c == SoundCategory::Ambient ? ambient : music;
  return std::clamp(master, 0.0f, 1.0f) * std::clamp(v, 0.0f, 1.0f);
}

// The positional and listener voices: a source per pool slot, made as needed.
struct AudioEngine::Voices {
  struct Voice {
    AlSource source;
    SoundCategory category = SoundCategory::Blocks;
    float gain = 1.0f, reach = kDefaultSoundReach;  // the sound's own, before the category's volume
    glm::vec3 at{0.0f};
    bool positional = true;
  };
  // A sound whose file is still being decoded: started once it is, if it is still in time.
  struct Pending {
    SoundPlay sound;
    SoundPick pick;
    int frames = 0;  // updates waited
  };
  Voices(int count, bool background)
      : pool(count), voices(static_cast<std::size_t>(count)), bank(background) {}
  VoicePool pool;
  std::vector<Voice> voices;
  std::vector<Pending> pending;
  SoundBank bank;
  std::unique_ptr<MusicStream> music;
  Efx efx;
  ALuint lowPass = 0;
  int dropped = 0;
};

// Loops at the listener by event.
struct AudioEngine::Loops {
  struct Loop {
    AlSource source;
    SoundCategory category = SoundCategory::Ambient;
    float gain = 0.0f, volume = 1.0f;
  };
  std::map<std::string, Loop, std::less<>> byEvent;
};

AudioEngine::AudioEngine(AudioOutput output, int voices)
    : device_(output, voices),
      voices_(std::make_unique<Voices>(device_.voices(), output == AudioOutput::Speakers)),
      loops_(std::make_unique<Loops>()) {
  alDistanceModel(AL_LINEAR_DISTANCE_CLAMPED);
  if (device_.efx()) {
    voices_->efx = Efx::load();
    if (voices_->efx.ok()) {
      voices_->efx.gen(1, &voices_->lowPass);
      voices_->efx.filteri(voices_->lowPass, AL_FILTER_TYPE, AL_FILTER_LOWPASS);
      voices_->efx.filterf(voices_->lowPass, AL_LOWPASS_GAIN, 1.0f);
      voices_->efx.filterf(voices_->lowPass, AL_LOWPASS_GAINHF, kUnderwaterGainHf);
    }
  }
}

AudioEngine::~AudioEngine() {
  voices_->music.reset();
  loops_->byEvent.clear();
  for (auto& v : voices_->voices) {
    if (v.source) alSourceStop(v.source.id());
    v.source.reset();
  }
  voices_->bank.setPacks({});
  if (voices_->lowPass) voices_->efx.del(1, &voices_->lowPass);
}

void AudioEngine::setPacks(const PackStack& packs, std::vector<std::string>& problems) {
  voices_->music.reset();
  loops_->byEvent.clear();
  for (std::size_t i = 0; i < voices_->voices.size(); ++i) {
    if (voices_->voices[i].source) alSourceStop(voices_->voices[i].source.id());
    voices_->voices[i].source.reset();
    voices_->pool.release(static_cast<int>(i));
  }
  voices_->pending.clear();
  events_ = SoundEvents::load(packs, problems);
  voices_->bank.setPacks(packs);
}

void AudioEngine::preload(std::string_view event) {
  for (const std::string& file : events_.files(event)) voices_->bank.request(file, problems_);
}

float AudioEngine::loudness(const SoundPlay& sound, float volume, float reach) const {
  const float gain = std::min(volume, 1.0f) * volumes_.of(sound.category);
  if (!sound.positional) return gain;
  const float d = glm::length(sound.at - listener_);
  return gain * std::max(0.0f, 1.0f - d / reach);
}

std::optional<std::string> AudioEngine::play(const SoundPlay& sound, std::uint32_t random) {
  std::optional<SoundPick> pick = events_.pick(sound.event, random);
  if (!pick && !sound.fallback.empty()) pick = events_.pick(sound.fallback, random);
  if (!pick) return std::nullopt;
  // Minecraft: a volume over 1 plays no louder but carries farther.
  const float volume = pick->volume * sound.volume;
  if (loudness(sound, volume, pick->reach * std::max(volume, 1.0f)) <= 0.0f) return std::nullopt;
  switch (voices_->bank.request(pick->file, problems_)) {
    case SoundBank::State::Failed:
      return std::nullopt;
    case SoundBank::State::Loading:
      voices_->pending.push_back({sound, *pick, 0});
      return pick->file;
    case SoundBank::State::Ready:
      break;
  }
  return start(sound, *pick) ? std::optional(pick->file) : std::nullopt;
}

bool AudioEngine::start(const SoundPlay& sound, const SoundPick& pick) {
  const float volume = pick.volume * sound.volume;
  const float reach = pick.reach * std::max(volume, 1.0f);
  const float heard = loudness(sound, volume, reach);
  const ALuint buffer = voices_->bank.buffer(pick.file);
  if (heard <= 0.0f || !buffer) return false;
  const std::optional<int> slot = voices_->pool.claim(heard);
  if (!slot) {
    ++voices_->dropped;
    return false;
  }
  Voices::Voice& v = voices_->voices[static_cast<std::size_t>(*slot)];
  if (!v.source) v.source = makeSource();
  if (!v.source) {
    voices_->pool.release(*slot);
    return false;
  }
  const ALuint s = v.source.id();
  alSourceStop(s);
  alSourcei(s, AL_BUFFER, static_cast<ALint>(buffer));
  v.category = sound.category;
  v.gain = std::min(volume, 1.0f);
  v.reach = reach;
  v.at = sound.at;
  v.positional = sound.positional;
  alSourcei(s, AL_SOURCE_RELATIVE, sound.positional ? AL_FALSE : AL_TRUE);
  const glm::vec3 at = sound.positional ? sound.at : glm::vec3(0.0f);
  alSource3f(s, AL_POSITION, at.x, at.y, at.z);
  alSourcef(s, AL_REFERENCE_DISTANCE, 0.0f);
  alSourcef(s, AL_MAX_DISTANCE, reach);
  alSourcef(s, AL_ROLLOFF_FACTOR, sound.positional ? 1.0f : 0.0f);
  alSourcef(s, AL_GAIN, v.gain * volumes_.of(v.category));
  alSourcef(s, AL_PITCH, clampPitch(pick.pitch * sound.pitch));
  alSourcei(s, AL_LOOPING, AL_FALSE);
  if (voices_->lowPass)
    alSourcei(s, AL_DIRECT_FILTER,
              static_cast<ALint>(underwater_ && v.category != SoundCategory::Music ? voices_->lowPass : 0));
  alSourcePlay(s);
  return true;
}

void AudioEngine::setLoop(std::string_view event, float gain, SoundCategory category, std::uint32_t random) {
  auto it = loops_->byEvent.find(event);
  if (gain <= 0.0f) {
    if (it != loops_->byEvent.end()) loops_->byEvent.erase(it);  // the source stops as it goes
    return;
  }
  if (it == loops_->byEvent.end()) {
    const std::optional<SoundPick> pick = events_.pick(event, random);
    // Still decoding: asked again next frame.
    if (!pick || voices_->bank.request(pick->file, problems_) != SoundBank::State::Ready) return;
    const ALuint buffer = voices_->bank.buffer(pick->file);
    AlSource source = makeSource();
    if (!source) return;
    const ALuint s = source.id();
    alSourcei(s, AL_BUFFER, static_cast<ALint>(buffer));
    alSourcei(s, AL_SOURCE_RELATIVE, AL_TRUE);
    alSource3f(s, AL_POSITION, 0.0f, 0.0f, 0.0f);
    alSourcef(s, AL_ROLLOFF_FACTOR, 0.0f);
    alSourcei(s, AL_LOOPING, AL_TRUE);
    alSourcef(s, AL_PITCH, clampPitch(pick->pitch));
    it = loops_->byEvent
             .emplace(std::string(event), Loops::Loop{std::move(source), category, 0.0f, pick->volume})
             .first;
    alSourcePlay(s);
  }
  Loops::Loop& loop = it->second;
  loop.gain = gain;
  alSourcef(loop.source.id(), AL_GAIN, std::min(gain * loop.volume, 1.0f) * volumes_.of(loop.category));
}

std::optional<std::string> AudioEngine::playMusic(std::string_view event, std::uint32_t random) {
  const std::optional<SoundPick> pick = events_.pick(event, random);
  if (!pick) return std::nullopt;
  std::string shownAs;
  std::vector<std::uint8_t> bytes = voices_->bank.read(pick->file, shownAs, problems_);
  if (bytes.empty()) return std::nullopt;
  try {
    auto track = std::make_unique<OggStream>(std::move(bytes), shownAs);
    const float gain = std::min(pick->volume, 1.0f) * volumes_.of(SoundCategory::Music);
    voices_->music.reset();
    voices_->music =
        std::make_unique<MusicStream>(std::move(track), gain, device_.output() == AudioOutput::Speakers);
  } catch (const Error& e) {
    problems_.push_back(e.what());
    return std::nullopt;
  }
  if (!voices_->music->playing()) return std::nullopt;
  return pick->file;
}

bool AudioEngine::musicPlaying() const {
  return voices_->music && voices_->music->playing();
}

void AudioEngine::setListener(glm::vec3 position, glm::vec3 forward, glm::vec3 up) {
  listener_ = position;
  alListener3f(AL_POSITION, position.x, position.y, position.z);
  const ALfloat orientation[] = {forward.x, forward.y, forward.z, up.x, up.y, up.z};
  alListenerfv(AL_ORIENTATION, orientation);
}

void AudioEngine::setVolumes(const AudioVolumes& volumes) {
  volumes_ = volumes;
  for (auto& v : voices_->voices) {
    if (v.source) alSourcef(v.source.id(), AL_GAIN, v.gain * volumes_.of(v.category));
  }
  for (auto& [event, loop] : loops_->byEvent)
    alSourcef(loop.source.id(), AL_GAIN,
              std::min(loop.gain * loop.volume, 1.0f) * volumes_.of(loop.category));
  if (voices_->music) voices_->music->setGain(volumes_.of(SoundCategory::Music));
}

void AudioEngine::setUnderwater(bool underwater) {
  if (underwater == underwater_) return;
  underwater_ = underwater;
  if (!voices_->lowPass) return;
  const auto filter = static_cast<ALint>(underwater ? voices_->lowPass : 0);
  for (std::size_t i = 0; i < voices_->voices.size(); ++i) {
    if (voices_->pool.busy(static_cast<int>(i)))
      alSourcei(voices_->voices[i].source.id(), AL_DIRECT_FILTER, filter);
  }
}

void AudioEngine::update() {
  voices_->bank.collect(problems_);
  startPending();
  for (std::size_t i = 0; i < voices_->voices.size(); ++i) {
    const int slot = static_cast<int>(i);
    if (!voices_->pool.busy(slot)) continue;
    Voices::Voice& v = voices_->voices[i];
    ALint state = AL_STOPPED;
    alGetSourcei(v.source.id(), AL_SOURCE_STATE, &state);
    if (state != AL_PLAYING) {
      voices_->pool.release(slot);
      continue;
    }
    SoundPlay where;
    where.at = v.at;
    where.positional = v.positional;
    where.category = v.category;
    voices_->pool.setLoudness(slot, loudness(where, v.gain, v.reach));
  }
  if (voices_->music && device_.output() == AudioOutput::Loopback) voices_->music->pump();
  if (voices_->music && !voices_->music->playing()) {
    musicUnderruns_ += voices_->music->underruns();
    voices_->music.reset();
  }
}

void AudioEngine::startPending() {
  std::vector<Voices::Pending> waiting;
  for (Voices::Pending& p : voices_->pending) {
    if (voices_->bank.buffer(p.pick.file)) {
      start(p.sound, p.pick);
    } else if (++p.frames < kPendingFrames &&
               voices_->bank.request(p.pick.file, problems_) == SoundBank::State::Loading) {
      waiting.push_back(std::move(p));
    }
  }
  voices_->pending = std::move(waiting);
}

AudioStats AudioEngine::stats() const {
  AudioStats s;
  s.voices = voices_->pool.size();
  s.playing = voices_->pool.busyCount();
  s.loops = static_cast<int>(loops_->byEvent.size());
  s.dropped = voices_->dropped;
  s.music = musicPlaying();
  s.musicUnderruns = musicUnderruns_ + (voices_->music ? voices_->music->underruns() : 0);
  s.bufferBytes = voices_->bank.bytes();
  return s;
}

}  // namespace terrasol
