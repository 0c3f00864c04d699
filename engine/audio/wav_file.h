#pragma once
// 16-bit PCM .wav files: written as sound is rendered (the header's sizes filled in at the end), and
// read back whole by tests and tools.

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <span>

#include "audio/ogg_file.h"

namespace terrasol {

class WavWriter {
 public:
  // Throws Error when the file cannot be created.
  WavWriter(const std::filesystem::path& file, int channels, int rate);
  ~WavWriter();  // finishes the header
  WavWriter(const WavWriter&) = delete;
  WavWriter& operator=(const WavWriter&) = delete;
  void write(std::span<const std::int16_t> samples);

 private:
  void header();
  std::ofstream out_;
  int channels_, rate_;
  std::uint64_t bytes_ = 0;
};

// Throws Error naming the file and what is wrong for anything but 16-bit PCM.
Pcm readWav(const std::filesystem::path& file);

}  // namespace terrasol
