#pragma once
// The message of the Error a call throws: what the bad-input tests compare.

#include <string>

#include "core/error.h"

namespace terrasol::testing {

// The message of the Error `f` throws, or "no error".
template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace terrasol::testing
