#pragma once
// Golden-image checks for GL tests. Goldens live in tests/goldens/<name>.png; on a mismatch the actual
// image and an amplified diff go to build/test-output/. tools/update-goldens.sh rewrites goldens on
// purpose (it sets TERRASOL_UPDATE_GOLDENS=1, which makes this write instead of compare).

#include <gtest/gtest.h>

#include <string>

#include "assets/image.h"
#include "support/world_support.h"

namespace terrasol::testing {

::testing::AssertionResult matchesGolden(const Image& actual, const std::string& name,
                                         const ImageTolerance& tolerance = {});

}  // namespace terrasol::testing
