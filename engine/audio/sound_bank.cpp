#include "audio/sound_bank.h"

#include <AL/al.h>

#include "audio/ogg_file.h"
#include "core/error.h"

namespace terrasol {

void SoundBank::setPacks(PackStack packs) {
  packs_ = std::move(packs);
  buffers_.clear();
  bytes_ = 0;
}

std::vector<std::uint8_t> SoundBank::read(const std::string& file, std::string& shownAs,
                                          std::vector<std::string>& problems) const {
  const auto found = packs_.find(file);
  shownAs = file;
  if (!found) {
    problems.push_back(file + ": no pack has this sound file");
    return {};
  }
  shownAs = found->pack->files().displayName(found->path);
  auto bytes = found->pack->files().read(found->path);
  if (!bytes) problems.push_back(shownAs + ": cannot be read");
  return bytes ? std::move(*bytes) : std::vector<std::uint8_t>{};
}

ALuint SoundBank::buffer(const std::string& file, std::vector<std::string>& problems) {
  if (const auto it = buffers_.find(file); it != buffers_.end()) return it->second.id();
  AlBuffer& slot = buffers_[file];
  std::string shownAs;
  std::vector<std::uint8_t> bytes = read(file, shownAs, problems);
  if (bytes.empty()) return 0;
  try {
    const Pcm pcm = decodeOgg(std::move(bytes), shownAs);
    if (pcm.samples.empty()) {
      problems.push_back(shownAs + ": no samples");
      return 0;
    }
    AlBuffer buffer = makeBuffer();
    if (!buffer) return 0;
    alBufferData(buffer.id(), pcm.channels == 2 ? AL_FORMAT_STEREO16 : AL_FORMAT_MONO16, pcm.samples.data(),
                 static_cast<ALsizei>(pcm.samples.size() * sizeof(std::int16_t)), pcm.rate);
    bytes_ += pcm.samples.size() * sizeof(std::int16_t);
    slot = std::move(buffer);
  } catch (const Error& e) {
    problems.push_back(e.what());
  }
  return slot.id();
}

}  // namespace terrasol
