#pragma once
// Float samples to Ogg Vorbis bytes with libvorbisenc, at a quality (-0.1..1) and a fixed stream
// serial, so the same samples give the same file.

#include <cstdint>
#include <vector>

#include "synth.h"

namespace terrasol::soundgen {

// `channels` interleaved in `samples`.
std::vector<std::uint8_t> encodeOgg(const Wave& samples, int channels, int rate, float quality);

}  // namespace terrasol::soundgen
