#include "spectrogram.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace terrasol::soundgen {
namespace {

constexpr int kWindow = 1024, kWave = 24;  // samples per analysis; waveform strip pixels

// A dark-to-bright ramp (black, purple, orange, pale yellow) for 0..1.
void colour(std::uint8_t* px, float v) {
  const float stops[][3] = {{0, 0, 0}, {80, 20, 120}, {230, 90, 40}, {255, 240, 180}};
  const float x = std::clamp(v, 0.0f, 1.0f) * 3.0f;
  const int i = std::min(2, static_cast<int>(x));
  const float f = x - static_cast<float>(i);
  for (int c = 0; c < 3; ++c)
    px[c] = static_cast<std::uint8_t>(stops[i][c] + (stops[i + 1][c] - stops[i][c]) * f);
  px[3] = 255;
}

}  // namespace

Image spectrogram(const Pcm& pcm, int width, int height, double seconds) {
  Image img(width, height);
  const std::size_t frames = pcm.frames();
  const auto sample = [&](std::size_t i) {
    return i < frames ? pcm.samples[i * static_cast<std::size_t>(pcm.channels)] / 32768.0f : 0.0f;
  };
  const int bands = height - kWave;
  const float nyquist = pcm.rate * 0.5f, low = 40.0f;
  for (int x = 0; x < width; ++x) {
    const auto centre = static_cast<std::size_t>((x + 0.5) / width * seconds * pcm.rate);
    // The waveform: the loudest sample near this column.
    float peak = 0.0f;
    const auto span = static_cast<std::size_t>(seconds * pcm.rate / width) + 1;
    for (std::size_t i = centre; i < centre + span; ++i) peak = std::max(peak, std::abs(sample(i)));
    for (int y = 0; y < kWave; ++y) {
      const float level = std::abs(static_cast<float>(kWave / 2 - y)) / (kWave / 2.0f);
      colour(img.pixel(x, y), level <= peak ? 0.9f : 0.05f);
    }
    for (int y = 0; y < bands; ++y) {
      const float f =
          low * std::pow(nyquist / low, static_cast<float>(bands - 1 - y) / static_cast<float>(bands - 1));
      double re = 0.0, im = 0.0;
      for (int n = 0; n < kWindow; ++n) {
        const double hann = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * n / (kWindow - 1));
        const double s = sample(centre + static_cast<std::size_t>(n)) * hann;
        const double phase = 2.0 * std::numbers::pi * f * n / pcm.rate;
        re += s * std::cos(phase);
        im -= s * std::sin(phase);
      }
      const double db = 20.0 * std::log10(std::sqrt(re * re + im * im) / (kWindow / 4.0) + 1e-9);
      colour(img.pixel(x, kWave + y), static_cast<float>((db + 80.0) / 80.0));
    }
  }
  return img;
}

Image stack(const std::vector<Image>& bands) {
  int width = 0, height = 0;
  for (const Image& b : bands) {
    width = std::max(width, b.width);
    height += b.height + 2;
  }
  Image sheet(width, height);
  int y0 = 0;
  for (const Image& b : bands) {
    for (int y = 0; y < b.height; ++y)
      for (int x = 0; x < b.width; ++x) std::copy_n(b.pixel(x, y), 4, sheet.pixel(x, y0 + y));
    for (int y = b.height; y < b.height + 2; ++y)
      for (int x = 0; x < width; ++x) std::fill_n(sheet.pixel(x, y0 + y), 4, std::uint8_t{128});
    y0 += b.height + 2;
  }
  return sheet;
}

}  // namespace terrasol::soundgen
