#pragma once
// Per-pass timings for reports: GL_TIME_ELAPSED queries on a GPU, glFinish and the wall clock on a
// software renderer. Internal to engine/render.

#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include "render/gl/object.h"

namespace terrasol {

struct PassTiming {
  std::string pass;
  double ms;
};

// Times passes when asked: with GL_TIME_ELAPSED queries on a real GPU, or by waiting for the GPU
// (glFinish) and reading the wall clock on a software renderer, whose timer queries measure nothing
// useful.
class PassClock {
 public:
  PassClock(std::vector<PassTiming>* timings, bool gpuTimer) : timings_(timings), gpuTimer_(gpuTimer) {
    begin();
  }
  ~PassClock() { finish(); }
  PassClock(const PassClock&) = delete;
  PassClock& operator=(const PassClock&) = delete;

  // Ends the pass running since the last lap (or construction).
  void lap(const std::string& pass) {
    if (!timings_) return;
    if (gpuTimer_) {
      glEndQuery(GL_TIME_ELAPSED);
      queries_.push_back({pass, std::move(current_)});
      begin();
      return;
    }
    glFinish();
    const auto now = std::chrono::steady_clock::now();
    timings_->push_back({pass, std::chrono::duration<double, std::milli>(now - start_).count()});
    start_ = now;
  }

 private:
  void begin() {
    if (!timings_) return;
    if (gpuTimer_) {
      current_ = gl::Query::create(GL_TIME_ELAPSED);
      glBeginQuery(GL_TIME_ELAPSED, current_.id());
      return;
    }
    glFinish();
    start_ = std::chrono::steady_clock::now();
  }
  // Waits for the queries' results (the frame is over by then).
  void finish() {
    if (!timings_ || !gpuTimer_) return;
    glEndQuery(GL_TIME_ELAPSED);
    for (const auto& [pass, query] : queries_) {
      GLuint64 ns = 0;
      glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT, &ns);
      timings_->push_back({pass, static_cast<double>(ns) / 1e6});
    }
  }

  std::vector<PassTiming>* timings_;
  bool gpuTimer_;
  std::chrono::steady_clock::time_point start_;
  gl::Query current_;
  std::vector<std::pair<std::string, gl::Query>> queries_;
};

// True on llvmpipe, softpipe and SwiftShader, whose timer queries measure nothing useful.
bool softwareRenderer();

}  // namespace terrasol
