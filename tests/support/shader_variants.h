#pragma once
// Whether a scene's renderer built a shader variant ("lighting+SHADOWS+PCF_DISK+..."), naming every
// variant it did build when not.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "scene_render/scene_render.h"

namespace terrasol::testing {

inline ::testing::AssertionResult builtVariant(SceneRenderer& r, const std::string& name,
                                               bool withMoreDefines) {
  std::string list;
  for (const std::string& v : r.renderer().shaderVariants()) {
    if (v == name || (withMoreDefines && v.starts_with(name + "+"))) {
      return ::testing::AssertionSuccess() << "built " << v;
    }
    list += "\n  " + v;
  }
  return ::testing::AssertionFailure()
         << "no variant " << name << (withMoreDefines ? "[+...]" : "") << "; built:" << list;
}

// Exactly this variant.
inline ::testing::AssertionResult hasVariant(SceneRenderer& r, const std::string& name) {
  return builtVariant(r, name, false);
}

// This variant or one with more defines: for checking that none was built, whatever else it has.
inline ::testing::AssertionResult hasAnyVariantOf(SceneRenderer& r, const std::string& name) {
  return builtVariant(r, name, true);
}

}  // namespace terrasol::testing
