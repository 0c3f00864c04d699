#pragma once
// KHR_debug output: driver messages become log lines, and errors are collected so the owner can
// throw at a safe point. (Throwing from inside the callback would unwind through the driver.)

#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace terrasol {

// Thrown by GlContext::checkErrors() when the driver reported a GL error.
class GlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class GlErrorPolicy {
  Throw,  // tests and tools: checkErrors() throws GlError
  Log,    // the game: errors are logged and play goes on
};

class GlDebugOutput {
 public:
  explicit GlDebugOutput(GlErrorPolicy policy) : policy_(policy) {}
  GlDebugOutput(const GlDebugOutput&) = delete;  // the driver holds a pointer to this object
  GlDebugOutput& operator=(const GlDebugOutput&) = delete;

  // Installs the callback on the current context (synchronous, so errors point at their call).
  void install();
  // Also polls glGetError, for drivers without debug output. Throws under GlErrorPolicy::Throw.
  void check(const char* where);

  // Called by the driver callback (GL enums as unsigned, so this header needs no GL).
  void onMessage(unsigned type, unsigned severity, const char* message);

 private:
  GlErrorPolicy policy_;
  std::mutex mutex_;
  std::vector<std::string> errors_;
};

}  // namespace terrasol
