#pragma once
// Progress of a long render: on a terminal, one bar redrawn in place (frames done, ms per frame, ETA);
// otherwise one plain line per frame, so logs stay readable. Lines printed through line() appear
// above the bar.

#include <chrono>
#include <cstdio>
#include <string>

namespace terrasol {

class Progress {
 public:
  Progress(int frames, std::FILE* out);
  // Frame `done` (1-based count) finished after `ms` milliseconds of work.
  void frameDone(int done, double ms);
  void line(const std::string& text);
  void finish();

 private:
  void drawBar();

  int frames_, done_ = 0;
  double totalMs_ = 0.0;
  std::FILE* out_;
  bool terminal_;
  bool barShown_ = false;
};

}  // namespace terrasol
