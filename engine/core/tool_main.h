#pragma once
// The shared main() of Terrasol's command-line programs: any exception that escapes `run` becomes
// "TOOL: error: what" on stderr and exit status 1, never an abort.

#include <cstdio>
#include <exception>

namespace terrasol {

template <class Run>
int guardedMain(const char* tool, Run&& run) {
  try {
    return run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: error: %s\n", tool, e.what());
    return 1;
  }
}

}  // namespace terrasol
