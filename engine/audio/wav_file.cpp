#include "audio/wav_file.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <iterator>
#include <vector>

#include "core/error.h"

namespace terrasol {
namespace {

constexpr std::size_t kHeaderBytes = 44;

void put32(char* at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) at[i] = static_cast<char>((v >> (8 * i)) & 0xff);
}
void put16(char* at, std::uint16_t v) {
  at[0] = static_cast<char>(v & 0xff);
  at[1] = static_cast<char>(v >> 8);
}
std::uint32_t get32(const std::uint8_t* at) {
  return static_cast<std::uint32_t>(at[0] | (at[1] << 8) | (at[2] << 16)) |
         (static_cast<std::uint32_t>(at[3]) << 24);
}
std::uint16_t get16(const std::uint8_t* at) {
  return static_cast<std::uint16_t>(at[0] | (at[1] << 8));
}

}  // namespace

WavWriter::WavWriter(const std::filesystem::path& file, int channels, int rate)
    : out_(file, std::ios::binary | std::ios::trunc), channels_(channels), rate_(rate) {
  if (!out_) throw Error(file.string() + ": cannot be written");
  header();
}

WavWriter::~WavWriter() {
  out_.seekp(0);
  header();
}

void WavWriter::header() {
  std::array<char, kHeaderBytes> h{};
  const auto data = static_cast<std::uint32_t>(std::min<std::uint64_t>(bytes_, 0xffffffffu - kHeaderBytes));
  std::memcpy(h.data(), "RIFF", 4);
  put32(h.data() + 4, static_cast<std::uint32_t>(kHeaderBytes - 8) + data);
  std::memcpy(h.data() + 8, "WAVEfmt ", 8);
  put32(h.data() + 16, 16);
  put16(h.data() + 20, 1);  // PCM
  put16(h.data() + 22, static_cast<std::uint16_t>(channels_));
  put32(h.data() + 24, static_cast<std::uint32_t>(rate_));
  put32(h.data() + 28, static_cast<std::uint32_t>(rate_ * channels_ * 2));
  put16(h.data() + 32, static_cast<std::uint16_t>(channels_ * 2));
  put16(h.data() + 34, 16);
  std::memcpy(h.data() + 36, "data", 4);
  put32(h.data() + 40, data);
  out_.write(h.data(), static_cast<std::streamsize>(h.size()));
  out_.flush();
}

void WavWriter::write(std::span<const std::int16_t> samples) {
  // .wav is little-endian, as every machine Terrasol builds for.
  out_.write(reinterpret_cast<const char*>(samples.data()),
             static_cast<std::streamsize>(samples.size_bytes()));
  bytes_ += samples.size_bytes();
}

Pcm readWav(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(file.string() + ": cannot be read");
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
  const std::string name = file.string();
  if (bytes.size() < 12 || std::memcmp(bytes.data(), "RIFF", 4) != 0 ||
      std::memcmp(bytes.data() + 8, "WAVE", 4) != 0)
    throw Error(name + ": not a RIFF WAVE file");
  Pcm pcm;
  bool format = false;
  for (std::size_t at = 12; at + 8 <= bytes.size();) {
    const std::uint32_t size = get32(bytes.data() + at + 4);
    const std::uint8_t* body = bytes.data() + at + 8;
    if (at + 8 + size > bytes.size())
      throw Error(name + ": chunk at byte " + std::to_string(at) + " runs past the end");
    if (std::memcmp(bytes.data() + at, "fmt ", 4) == 0) {
      // PCM, or WAVE_FORMAT_EXTENSIBLE (as OpenAL Soft's wave writer and others write it) whose
      // subformat is PCM.
      const std::uint16_t tag = get16(body);
      const bool linear = tag == 1 || (tag == 0xfffe && size >= 40 && get16(body + 24) == 1);
      if (size < 16 || !linear || get16(body + 14) != 16) throw Error(name + ": only 16-bit PCM is read");
      pcm.channels = get16(body + 2);
      pcm.rate = static_cast<int>(get32(body + 4));
      format = true;
    } else if (std::memcmp(bytes.data() + at, "data", 4) == 0) {
      if (!format) throw Error(name + ": data before its format");
      pcm.samples.resize(size / 2);
      std::memcpy(pcm.samples.data(), body, pcm.samples.size() * 2);
      return pcm;
    }
    at += 8 + size + (size & 1);
  }
  throw Error(name + ": no data chunk");
}

}  // namespace terrasol
