#pragma once
// TERRASOL_ASSERT(condition) or TERRASOL_ASSERT(condition, message): an internal invariant, checked in
// every build, Release included. On failure it writes "FILE:LINE: assertion failed: CONDITION: MESSAGE"
// to stderr as one line and aborts. The message (anything a std::string_view is made from) is built
// only when the condition fails.
//
// Aborts rather than throws: a broken invariant means the world or the frame in memory may already be
// wrong, and unwinding would run the handlers that carry on (the streamer keeps a chunk after a failed
// save) or save on the way out, which could write that state over the last good save. An abort leaves
// the saves on disk as they were last written whole, and it works the same on a worker thread.
// Problems with input (files, scenes, packs) are Errors thrown at the load boundary, never assertions.
//
// A passing check costs a compare and a branch; still keep it out of the innermost per-voxel loops.

#include <string_view>

namespace terrasol::detail {

[[noreturn]] void assertionFailed(const char* file, int line, const char* condition,
                                  std::string_view message);

}  // namespace terrasol::detail

#define TERRASOL_ASSERT(condition, ...)                                                                     \
  do {                                                                                                      \
    if (!(condition)) [[unlikely]]                                                                          \
      ::terrasol::detail::assertionFailed(__FILE__, __LINE__, #condition, ::std::string_view{__VA_ARGS__}); \
  } while (false)
