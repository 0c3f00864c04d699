#include "audio/ogg_file.h"

#include <vorbis/vorbisfile.h>

#include <algorithm>
#include <cstring>

#include "core/error.h"

namespace terrasol {

// The bytes and where libvorbisfile is reading them.
struct OggStream::State {
  std::vector<std::uint8_t> bytes;
  std::size_t at = 0;
  OggVorbis_File file{};
  bool open = false;
};

namespace {

std::size_t readBytes(void* out, std::size_t size, std::size_t count, void* source) {
  auto& s = *static_cast<OggStream::State*>(source);
  const std::size_t n = std::min(size * count, s.bytes.size() - s.at);
  std::memcpy(out, s.bytes.data() + s.at, n);
  s.at += n;
  return size > 0 ? n / size : 0;
}

int seekBytes(void* source, ogg_int64_t offset, int whence) {
  auto& s = *static_cast<OggStream::State*>(source);
  const auto size = static_cast<ogg_int64_t>(s.bytes.size());
  ogg_int64_t to = whence == SEEK_SET   ? offset
                   : whence == SEEK_CUR ? static_cast<ogg_int64_t>(s.at) + offset
                                        : size + offset;
  if (to < 0 || to > size) return -1;
  s.at = static_cast<std::size_t>(to);
  return 0;
}

long tellBytes(void* source) {
  return static_cast<long>(static_cast<OggStream::State*>(source)->at);
}

}  // namespace

OggStream::OggStream(std::vector<std::uint8_t> bytes, std::string file)
    : state_(std::make_unique<State>()), file_(std::move(file)) {
  state_->bytes = std::move(bytes);
  const ov_callbacks callbacks{readBytes, seekBytes, nullptr, tellBytes};
  if (ov_open_callbacks(state_.get(), &state_->file, nullptr, 0, callbacks) != 0)
    throw Error(file_ + ": not an Ogg Vorbis file");
  state_->open = true;
  const vorbis_info* info = ov_info(&state_->file, -1);
  if (!info || info->channels < 1 || info->channels > 2 || info->rate < 4000 || info->rate > 192000)
    throw Error(file_ + ": Ogg Vorbis with " + std::to_string(info ? info->channels : 0) + " channels at " +
                std::to_string(info ? info->rate : 0) + " Hz (1 or 2 channels, 4-192 kHz)");
  channels_ = info->channels;
  rate_ = static_cast<int>(info->rate);
}

OggStream::~OggStream() {
  if (state_ && state_->open) ov_clear(&state_->file);
}

std::size_t OggStream::read(std::span<std::int16_t> out) {
  std::size_t filled = 0;  // samples
  const std::size_t want = out.size() - out.size() % static_cast<std::size_t>(channels_);
  while (filled < want) {
    int section = 0;
    const long got =
        ov_read(&state_->file, reinterpret_cast<char*>(out.data() + filled),
                static_cast<int>(std::min<std::size_t>((want - filled) * 2, 1 << 16)), 0, 2, 1, &section);
    if (got == 0) break;
    if (got == OV_HOLE) continue;  // a gap in the pages: skip it, as players do
    if (got < 0) throw Error(file_ + ": corrupt Ogg Vorbis data at byte " + std::to_string(state_->at));
    filled += static_cast<std::size_t>(got) / 2;
  }
  return filled / static_cast<std::size_t>(channels_);
}

void OggStream::rewind() {
  ov_raw_seek(&state_->file, 0);
}

Pcm decodeOgg(std::vector<std::uint8_t> bytes, const std::string& file) {
  OggStream stream(std::move(bytes), file);
  Pcm pcm{stream.channels(), stream.rate(), {}};
  std::vector<std::int16_t> block(8192);
  while (const std::size_t frames = stream.read(block))
    pcm.samples.insert(pcm.samples.end(), block.begin(),
                       block.begin() + static_cast<long>(frames) * pcm.channels);
  return pcm;
}

}  // namespace terrasol
