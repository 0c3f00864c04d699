#pragma once
// Sounds as pictures, to look at what was made: a waveform strip over a spectrogram (log frequency
// from 40 Hz up, -80..0 dB), one band per file in a contact sheet.

#include <vector>

#include "assets/image.h"
#include "audio/ogg_file.h"

namespace terrasol::soundgen {

// `pcm` (first channel) as a band `width` x `height` pixels: time left to right, over `seconds`
// (the sheet's longest file, so lengths compare).
Image spectrogram(const Pcm& pcm, int width, int height, double seconds);
// The bands one under another, a grey line between.
Image stack(const std::vector<Image>& bands);

}  // namespace terrasol::soundgen
