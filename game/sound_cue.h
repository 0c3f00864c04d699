#pragma once
// A sound the game asks for, at the tick it happened: what the audio plays and the sound log records.

#include <cstdint>

#include "audio/audio_engine.h"

namespace terrasol {

struct SoundCue {
  SoundPlay sound;
  std::int64_t tick = 0;  // the world's tick (Level::time) it fired at
};

}  // namespace terrasol
