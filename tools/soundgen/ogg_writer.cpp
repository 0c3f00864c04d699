#include "ogg_writer.h"

#include <vorbis/vorbisenc.h>

#include <algorithm>

#include "core/error.h"

namespace terrasol::soundgen {
namespace {

void append(std::vector<std::uint8_t>& out, const ogg_page& page) {
  out.insert(out.end(), page.header, page.header + page.header_len);
  out.insert(out.end(), page.body, page.body + page.body_len);
}

}  // namespace

std::vector<std::uint8_t> encodeOgg(const Wave& samples, int channels, int rate, float quality) {
  vorbis_info info;
  vorbis_info_init(&info);
  if (vorbis_encode_init_vbr(&info, channels, rate, quality) != 0) {
    vorbis_info_clear(&info);
    throw Error("vorbis: no encoder for " + std::to_string(channels) + " channels at " +
                std::to_string(rate) + " Hz");
  }
  vorbis_comment comment;
  vorbis_comment_init(&comment);
  vorbis_comment_add_tag(&comment, "ENCODER", "terrasol-soundgen");
  vorbis_dsp_state dsp;
  vorbis_block block;
  vorbis_analysis_init(&dsp, &info);
  vorbis_block_init(&dsp, &block);
  ogg_stream_state stream;
  ogg_stream_init(&stream, 0x7e55a501);
  std::vector<std::uint8_t> out;
  ogg_page page;
  ogg_packet packet;
  {
    ogg_packet header, commentHeader, codeHeader;
    vorbis_analysis_headerout(&dsp, &comment, &header, &commentHeader, &codeHeader);
    ogg_stream_packetin(&stream, &header);
    ogg_stream_packetin(&stream, &commentHeader);
    ogg_stream_packetin(&stream, &codeHeader);
    while (ogg_stream_flush(&stream, &page) != 0) append(out, page);
  }
  const std::size_t frames = samples.size() / static_cast<std::size_t>(channels);
  constexpr std::size_t kChunk = 4096;
  for (std::size_t at = 0;; at += kChunk) {
    const std::size_t n = at < frames ? std::min(kChunk, frames - at) : 0;
    if (n == 0) {
      vorbis_analysis_wrote(&dsp, 0);  // the end
    } else {
      float** buffer = vorbis_analysis_buffer(&dsp, static_cast<int>(n));
      for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < channels; ++c)
          buffer[c][i] =
              std::clamp(samples[(at + i) * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)],
                         -1.0f, 1.0f);
      vorbis_analysis_wrote(&dsp, static_cast<int>(n));
    }
    while (vorbis_analysis_blockout(&dsp, &block) == 1) {
      vorbis_analysis(&block, nullptr);
      vorbis_bitrate_addblock(&block);
      while (vorbis_bitrate_flushpacket(&dsp, &packet) != 0) {
        ogg_stream_packetin(&stream, &packet);
        while (ogg_stream_pageout(&stream, &page) != 0) append(out, page);
      }
    }
    if (n == 0) break;
  }
  while (ogg_stream_flush(&stream, &page) != 0) append(out, page);
  ogg_stream_clear(&stream);
  vorbis_block_clear(&block);
  vorbis_dsp_clear(&dsp);
  vorbis_comment_clear(&comment);
  vorbis_info_clear(&info);
  return out;
}

}  // namespace terrasol::soundgen
