#pragma once
// Ogg Vorbis, decoded by libvorbisfile from bytes in memory (a pack's file, read whole): at once for
// short sounds, piece by piece for streamed music. Bad bytes are an Error naming the file.

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace terrasol {

// Interleaved 16-bit samples.
struct Pcm {
  int channels = 1, rate = 44100;
  std::vector<std::int16_t> samples;
  std::size_t frames() const {
    return channels > 0 ? samples.size() / static_cast<std::size_t>(channels) : 0;
  }
};

class OggStream {
 public:
  // Takes the file's bytes; `file` names it in errors. Throws Error when they are not Ogg Vorbis.
  OggStream(std::vector<std::uint8_t> bytes, std::string file);
  ~OggStream();
  OggStream(const OggStream&) = delete;
  OggStream& operator=(const OggStream&) = delete;

  int channels() const { return channels_; }
  int rate() const { return rate_; }
  // Up to out.size() / channels() frames into `out`; 0 at the end. Throws Error on a corrupt page.
  std::size_t read(std::span<std::int16_t> out);
  void rewind();

  struct State;  // the bytes and libvorbisfile's reader over them (its callbacks see it)

 private:
  std::unique_ptr<State> state_;
  std::string file_;
  int channels_ = 1, rate_ = 44100;
};

// The whole file at once. Throws Error naming `file`.
Pcm decodeOgg(std::vector<std::uint8_t> bytes, const std::string& file);

}  // namespace terrasol
