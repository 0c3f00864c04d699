#include <epoxy/gl.h>

#include "support/gl_test.h"

namespace terrasol {
namespace {

using testing::GlTest;

TEST_F(GlTest, GlErrorBecomesAnExceptionNamingTheCall) {
  glEnable(0xDEAD);  // GL_INVALID_ENUM
  try {
    context_->checkErrors("the bad call");
    FAIL() << "no GlError thrown";
  } catch (const GlError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("the bad call"), std::string::npos) << what;
    EXPECT_NE(what.find("GL_INVALID_ENUM"), std::string::npos) << what;
  }
  EXPECT_NO_THROW(context_->checkErrors("after draining"));
}

TEST_F(GlTest, ErrorsAreReportedOnceAndOnlyOnce) {
  GLuint notAName = 987654;
  glBindBuffer(GL_ARRAY_BUFFER, notAName);  // never generated: GL_INVALID_OPERATION in core profile
  EXPECT_THROW(context_->checkErrors("bind"), GlError);
  EXPECT_NO_THROW(context_->checkErrors("clean"));
}

}  // namespace
}  // namespace terrasol
