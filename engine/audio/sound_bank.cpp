#include "audio/sound_bank.h"

#include <AL/al.h>

#include "core/error.h"

namespace terrasol {

SoundBank::SoundBank(bool background) {
  if (background) worker_ = std::jthread([this](std::stop_token stop) { work(stop); });
}

SoundBank::~SoundBank() {
  if (worker_.joinable()) {
    worker_.request_stop();
    wake_.notify_all();
    worker_.join();
  }
}

void SoundBank::setPacks(PackStack packs) {
  {
    const std::lock_guard lock(queueMutex_);
    queue_.clear();
    done_.clear();
    ++generation_;
  }
  const std::lock_guard lock(readMutex_);
  packs_ = std::move(packs);
  buffers_.clear();
  states_.clear();
  bytes_ = 0;
}

std::vector<std::uint8_t> SoundBank::read(const std::string& file, std::string& shownAs,
                                          std::vector<std::string>& problems) const {
  const std::lock_guard lock(readMutex_);
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

SoundBank::Decoded SoundBank::decode(const std::string& file) const {
  Decoded d{file, std::nullopt, {}};
  std::vector<std::string> problems;
  std::string shownAs;
  std::vector<std::uint8_t> bytes = read(file, shownAs, problems);
  if (!problems.empty()) {
    d.problem = problems.front();
    return d;
  }
  try {
    Pcm pcm = decodeOgg(std::move(bytes), shownAs);
    if (pcm.samples.empty()) {
      d.problem = shownAs + ": no samples";
    } else {
      d.pcm = std::move(pcm);
    }
  } catch (const Error& e) {
    d.problem = e.what();
  }
  return d;
}

void SoundBank::store(Decoded d, std::vector<std::string>& problems) {
  if (!d.pcm) {
    states_[d.file] = State::Failed;
    problems.push_back(std::move(d.problem));
    return;
  }
  AlBuffer buffer = makeBuffer();
  if (!buffer) {
    states_[d.file] = State::Failed;
    return;
  }
  alBufferData(buffer.id(), d.pcm->channels == 2 ? AL_FORMAT_STEREO16 : AL_FORMAT_MONO16,
               d.pcm->samples.data(), static_cast<ALsizei>(d.pcm->samples.size() * sizeof(std::int16_t)),
               d.pcm->rate);
  bytes_ += d.pcm->samples.size() * sizeof(std::int16_t);
  buffers_[d.file] = std::move(buffer);
  states_[d.file] = State::Ready;
}

SoundBank::State SoundBank::request(const std::string& file, std::vector<std::string>& problems) {
  if (const auto it = states_.find(file); it != states_.end()) return it->second;
  if (!worker_.joinable()) {
    store(decode(file), problems);
    return states_[file];
  }
  states_[file] = State::Loading;
  {
    const std::lock_guard lock(queueMutex_);
    queue_.push_back(file);
  }
  wake_.notify_one();
  return State::Loading;
}

ALuint SoundBank::buffer(const std::string& file) const {
  const auto it = buffers_.find(file);
  return it != buffers_.end() ? it->second.id() : 0;
}

void SoundBank::collect(std::vector<std::string>& problems) {
  std::vector<Decoded> done;
  {
    const std::lock_guard lock(queueMutex_);
    done.swap(done_);
  }
  for (Decoded& d : done) store(std::move(d), problems);
}

void SoundBank::work(std::stop_token stop) {
  std::unique_lock lock(queueMutex_);
  while (!stop.stop_requested()) {
    if (queue_.empty()) {
      wake_.wait(lock, stop, [&] { return !queue_.empty(); });
      continue;
    }
    const std::string file = std::move(queue_.front());
    queue_.pop_front();
    const std::uint64_t generation = generation_;
    lock.unlock();
    Decoded d = decode(file);
    lock.lock();
    if (generation == generation_) done_.push_back(std::move(d));  // else the packs changed meanwhile
  }
}

}  // namespace terrasol
