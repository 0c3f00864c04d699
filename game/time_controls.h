#pragma once
// The player's hold on the world's clock (F6, F7, F8): how many ticks of world time pass per game tick,
// whether time stands still, and the jump to the next time of day. Plain C++.

#include <cstdint>
#include <iterator>

namespace terrasol {

class TimeControls {
 public:
  static constexpr int kSpeeds[] = {1, 10, 100};  // world ticks per game tick

  int speed() const { return kSpeeds[speed_]; }
  bool stopped() const { return stopped_; }
  void faster() { speed_ = (speed_ + 1) % static_cast<int>(std::size(kSpeeds)); }  // and round again
  void toggleStop() { stopped_ = !stopped_; }
  void stop() { stopped_ = true; }
  // One game tick of world time.
  void tick(std::int64_t& time) const {
    if (!stopped_) time += speed();
  }
  // The first of morning, noon, sunset and midnight after `time`, in the same or the next day.
  static std::int64_t nextPreset(std::int64_t time);

 private:
  int speed_ = 0;  // index into kSpeeds
  bool stopped_ = false;
};

}  // namespace terrasol
