#include "progress.h"

#include <unistd.h>

#include <algorithm>

namespace terrasol {

Progress::Progress(int frames, std::FILE* out)
    : frames_(std::max(frames, 1)), out_(out), terminal_(isatty(fileno(out)) != 0) {}

void Progress::frameDone(int done, double ms) {
  done_ = done;
  totalMs_ += ms;
  if (terminal_) {
    drawBar();
  } else {
    std::fprintf(out_, "frame %d/%d: %.1f ms\n", done_, frames_, ms);
    std::fflush(out_);
  }
}

void Progress::line(const std::string& text) {
  if (terminal_ && barShown_) std::fputs("\r\033[K", out_);
  std::fprintf(out_, "%s\n", text.c_str());
  if (terminal_ && barShown_) drawBar();
  std::fflush(out_);
}

void Progress::finish() {
  if (terminal_ && barShown_) std::fputs("\n", out_);
  barShown_ = false;
  std::fflush(out_);
}

void Progress::drawBar() {
  constexpr int kWidth = 30;
  const int filled = done_ * kWidth / frames_;
  const double perFrame = done_ > 0 ? totalMs_ / done_ : 0.0;
  const double etaSeconds = perFrame * (frames_ - done_) / 1000.0;
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(kWidth, '.');
  std::fprintf(out_, "\r\033[K[%s] %d/%d frames  %.1f ms/frame  ETA %.1f s", bar.c_str(), done_, frames_,
               perFrame, etaSeconds);
  barShown_ = true;
  std::fflush(out_);
}

}  // namespace terrasol
