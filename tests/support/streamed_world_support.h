#pragma once
// Streaming a test world until it is still: the chunks round the origin loaded, lit and meshed.

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "pipeline/streamed_world.h"

namespace terrasol::testing {

inline void settle(StreamedWorld& w) {
  for (int i = 0; i < 20000; ++i) {
    w.update({0, 0}, std::chrono::steady_clock::now() + std::chrono::milliseconds(50));
    const WorldCounts c = w.counts();
    if (c.pending == 0 && c.meshDirty == 0 && c.meshInFlight == 0 && c.loaded > 0) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  FAIL() << "the world never settled";
}

}  // namespace terrasol::testing
