#pragma once
// Sound files as OpenAL buffers, read through the pack stack (the topmost pack that has the file,
// as for textures) and decoded on first use. A file that is missing or does not decode is reported
// once, with its pack and path, and is silent from then on.

#include <map>
#include <string>
#include <vector>

#include "assets/resource_pack.h"
#include "audio/al_objects.h"

namespace terrasol {

class SoundBank {
 public:
  void setPacks(PackStack packs);
  // The buffer of pack file `file` ("assets/minecraft/sounds/dig/stone1.ogg"), 0 when it cannot be
  // had; a first failure is appended to `problems`.
  ALuint buffer(const std::string& file, std::vector<std::string>& problems);
  // The file's bytes from the topmost pack that has it; empty with a problem when none has.
  std::vector<std::uint8_t> read(const std::string& file, std::string& shownAs,
                                 std::vector<std::string>& problems) const;
  std::size_t loaded() const { return buffers_.size(); }
  std::size_t bytes() const { return bytes_; }

 private:
  PackStack packs_;
  std::map<std::string, AlBuffer, std::less<>> buffers_;  // empty where the file failed
  std::size_t bytes_ = 0;
};

}  // namespace terrasol
