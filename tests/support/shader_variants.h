#pragma once
// Whether a scene's renderer built a shader variant ("lighting+SHADOWS+PCF_SAMPLES=1+..."), naming
// every variant it did build when not.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "scene_render.h"

namespace terrasol::testing {

inline ::testing::AssertionResult hasVariant(SceneRenderer& r, const std::string& name) {
  const auto& built = r.renderer().shaderVariants();
  if (std::find(built.begin(), built.end(), name) != built.end()) return ::testing::AssertionSuccess();
  std::string list;
  for (const std::string& v : built) list += "\n  " + v;
  return ::testing::AssertionFailure() << "no variant " << name << "; built:" << list;
}

}  // namespace terrasol::testing
