#include <type_traits>

#include "render/gl/object.h"
#include "support/gl_test.h"

namespace terrasol {
namespace {

using testing::GlTest;

static_assert(!std::is_copy_constructible_v<gl::Buffer>);
static_assert(!std::is_copy_assignable_v<gl::Texture>);
static_assert(std::is_nothrow_move_constructible_v<gl::Program>);
static_assert(std::is_nothrow_move_assignable_v<gl::Framebuffer>);

TEST_F(GlTest, ObjectsAreCreatedMovedAndDeletedExactlyOnce) {
  gl::Buffer a = gl::Buffer::create();
  const GLuint id = a.id();
  ASSERT_NE(id, 0u);
  EXPECT_TRUE(glIsBuffer(id));

  gl::Buffer b = std::move(a);
  EXPECT_EQ(a.id(), 0u);  // NOLINT(bugprone-use-after-move): the empty state is the contract
  EXPECT_EQ(b.id(), id);

  gl::Buffer c = gl::Buffer::create();
  const GLuint other = c.id();
  c = std::move(b);  // releases `other`
  EXPECT_FALSE(glIsBuffer(other));
  EXPECT_EQ(c.id(), id);

  c.reset();
  EXPECT_FALSE(glIsBuffer(id));
  c.reset();  // twice is harmless
}

TEST_F(GlTest, EveryObjectKindHasAWorkingCreate) {
  const auto vertexArray = gl::VertexArray::create();
  EXPECT_TRUE(glIsVertexArray(vertexArray.id()));
  const auto texture = gl::Texture::create(GL_TEXTURE_2D);
  EXPECT_TRUE(glIsTexture(texture.id()));
  const auto framebuffer = gl::Framebuffer::create();
  EXPECT_TRUE(glIsFramebuffer(framebuffer.id()));
  const auto renderbuffer = gl::Renderbuffer::create();
  EXPECT_TRUE(glIsRenderbuffer(renderbuffer.id()));
  const auto query = gl::Query::create(GL_TIME_ELAPSED);
  EXPECT_TRUE(glIsQuery(query.id()));
  const auto shader = gl::Shader::create(GL_FRAGMENT_SHADER);
  EXPECT_TRUE(glIsShader(shader.id()));
  const auto program = gl::Program::create();
  EXPECT_TRUE(glIsProgram(program.id()));
}

}  // namespace
}  // namespace terrasol
