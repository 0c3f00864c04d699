#pragma once
// Sound files as OpenAL buffers, read through the pack stack (the topmost pack that has the file,
// as for textures) and decoded on first use: on a thread of its own with speakers (a first play is
// then a few milliseconds late, not a main-thread stall), at once on a loopback device (the same
// frames every run). A file that is missing or does not decode is reported once, with its pack and
// path, and is silent from then on.

#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "assets/resource_pack.h"
#include "audio/al_objects.h"
#include "audio/ogg_file.h"

namespace terrasol {

class SoundBank {
 public:
  explicit SoundBank(bool background);
  ~SoundBank();
  SoundBank(const SoundBank&) = delete;
  SoundBank& operator=(const SoundBank&) = delete;

  void setPacks(PackStack packs);
  enum class State { Ready, Loading, Failed };
  // Asks for pack file `file` ("assets/minecraft/sounds/dig/stone1.ogg") and says where it stands;
  // a failure is appended to `problems` once.
  State request(const std::string& file, std::vector<std::string>& problems);
  // Its buffer, 0 unless Ready.
  ALuint buffer(const std::string& file) const;
  // Main thread, once a frame: turns what the decoder finished into buffers.
  void collect(std::vector<std::string>& problems);
  // The file's bytes from the topmost pack that has it; empty with a problem when none has.
  std::vector<std::uint8_t> read(const std::string& file, std::string& shownAs,
                                 std::vector<std::string>& problems) const;
  std::size_t bytes() const { return bytes_; }

 private:
  struct Decoded {
    std::string file;
    std::optional<Pcm> pcm;
    std::string problem;
  };
  Decoded decode(const std::string& file) const;
  void store(Decoded decoded, std::vector<std::string>& problems);
  void work(std::stop_token stop);

  PackStack packs_;
  mutable std::mutex readMutex_;  // pack sources (zips) are read by one thread at a time
  std::map<std::string, AlBuffer, std::less<>> buffers_;
  std::map<std::string, State, std::less<>> states_;
  std::size_t bytes_ = 0;
  // The decoder's queue and results, and the pack generation they belong to.
  std::mutex queueMutex_;
  std::condition_variable_any wake_;
  std::deque<std::string> queue_;
  std::vector<Decoded> done_;
  std::uint64_t generation_ = 0;
  std::jthread worker_;  // last: stops before the rest goes
};

}  // namespace terrasol
