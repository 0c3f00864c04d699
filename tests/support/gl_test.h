#pragma once
// Base fixture for GL tests: a fresh headless 4.5 core context per test; any GL error the test
// leaves behind fails it.

#include <gtest/gtest.h>

#include <memory>

#include "platform/egl/egl_context.h"

namespace terrasol::testing {

class GlTest : public ::testing::Test {
 protected:
  void SetUp() override { context_ = createHeadlessContext(GlErrorPolicy::Throw); }
  void TearDown() override {
    if (!context_) return;  // skipped before SetUp made one
    try {
      context_->checkErrors("the end of the test");
    } catch (const GlError& e) {
      ADD_FAILURE() << e.what();
    }
  }

  std::unique_ptr<GlContext> context_;
};

}  // namespace terrasol::testing
