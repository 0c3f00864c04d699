#include "soundgen.h"

#include <fstream>

#include "audio/ogg_file.h"
#include "core/error.h"
#include "ogg_writer.h"

namespace terrasol::soundgen {

void Catalogue::event(const std::string& name, const std::vector<std::string>& names, float volume,
                      float pitch, bool stream) {
  nlohmann::json sounds = nlohmann::json::array();
  for (const std::string& n : names) {
    if (volume == 1.0f && pitch == 1.0f && !stream) {
      sounds.push_back(n);
      continue;
    }
    nlohmann::json e = {{"name", n}};
    if (volume != 1.0f) e["volume"] = volume;
    if (pitch != 1.0f) e["pitch"] = pitch;
    if (stream) e["stream"] = true;
    sounds.push_back(e);
  }
  events[name] = {{"sounds", sounds}};
}

namespace {

// Vorbis is lossy: noise near full scale comes back with peaks over it. Encoded, decoded, and
// turned down until it does not clip.
std::vector<std::uint8_t> encodeUnclipped(const SoundFile& f) {
  Wave samples = f.samples;
  for (int attempt = 0;; ++attempt) {
    std::vector<std::uint8_t> bytes = encodeOgg(samples, f.channels, f.rate, f.quality);
    const Pcm back = decodeOgg(bytes, f.name);
    int peak = 0;
    for (std::int16_t s : back.samples) peak = std::max(peak, std::abs(static_cast<int>(s)));
    if (peak < 31000 || attempt == 4) return bytes;
    for (float& s : samples) s *= 0.9f * 31000.0f / static_cast<float>(peak);
  }
}

}  // namespace

void writeSounds(const Catalogue& c, const std::filesystem::path& pack) {
  const std::filesystem::path root = pack / "assets" / "minecraft";
  std::filesystem::remove_all(root / "sounds");  // nothing stale from an earlier catalogue
  for (const SoundFile& f : c.files) {
    const std::filesystem::path file = root / "sounds" / (f.name + ".ogg");
    std::filesystem::create_directories(file.parent_path());
    const std::vector<std::uint8_t> bytes = encodeUnclipped(f);
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw Error(file.string() + ": cannot be written");
  }
  std::ofstream json(root / "sounds.json", std::ios::trunc);
  json << c.events.dump(2) << '\n';
  if (!json) throw Error((root / "sounds.json").string() + ": cannot be written");
}

}  // namespace terrasol::soundgen
