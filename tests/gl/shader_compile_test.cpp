
#include "render/gl/program.h"
#include "render/gl/uniforms.h"
#include "render/gl_slots.h"
#include "support/gl_test.h"
#include "support/memory_shaders.h"

namespace terrasol {
namespace {

using testing::GlTest;

const std::string kVertex =
    "#version 450 core\n"
    "layout(location = ATTRIB_POSITION) in vec3 a_position;\n"
    "void main() { gl_Position = vec4(a_position, 1.0); }\n";

TEST_F(GlTest, BrokenShaderErrorNamesTheOriginalFileAndLine) {
  const auto sources = testing::memoryShaders({
      {"t.vert", kVertex},
      {"t.frag",
       "#version 450 core\n"
       "#include \"lib/helpers.glsl\"\n"
       "out vec4 o;\n"
       "void main() { o = vec4(helper()); }\n"},
      {"lib/helpers.glsl",
       "// helpers\n"
       "float helper() {\n"
       "  return undefined_variable * 2.0;\n"
       "}\n"},
  });
  try {
    buildProgram(sources, {{GL_VERTEX_SHADER, "t.vert"}, {GL_FRAGMENT_SHADER, "t.frag"}}, slotDefines());
    FAIL() << "the broken shader compiled";
  } catch (const ShaderError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("shaders/lib/helpers.glsl:3:"), std::string::npos) << what;
    EXPECT_NE(what.find("undefined_variable"), std::string::npos) << what;
  }
}

TEST_F(GlTest, InjectedSlotDefinesReachTheShader) {
  const auto sources = testing::memoryShaders({
      {"t.vert", kVertex},
      {"t.frag",
       "#version 450 core\nlayout(location = OUT_COLOR) out vec4 o;\nvoid main() { o = vec4(1.0); }\n"},
  });
  const gl::Program program =
      buildProgram(sources, {{GL_VERTEX_SHADER, "t.vert"}, {GL_FRAGMENT_SHADER, "t.frag"}}, slotDefines());
  EXPECT_EQ(glGetAttribLocation(program.id(), "a_position"), slots::kAttribPosition);
  EXPECT_EQ(glGetFragDataLocation(program.id(), "o"), slots::kOutColor);
}

TEST_F(GlTest, LinkErrorNamesTheStages) {
  const auto sources = testing::memoryShaders({
      {"t.vert",
       "#version 450 core\nout vec3 v_missing;\nvoid main() { v_missing = vec3(0); gl_Position = vec4(0); "
       "}\n"},
      {"t.frag", "#version 450 core\nin vec4 v_other;\nout vec4 o;\nvoid main() { o = v_other; }\n"},
  });
  try {
    buildProgram(sources, {{GL_VERTEX_SHADER, "t.vert"}, {GL_FRAGMENT_SHADER, "t.frag"}}, {});
    FAIL() << "mismatched stages linked";
  } catch (const ShaderError& e) {
    EXPECT_NE(std::string(e.what()).find("shaders/t.vert + shaders/t.frag"), std::string::npos) << e.what();
  }
}

// A uniform table names each uniform once; the names are checked against the sources at link time.
TEST_F(GlTest, AUniformNoSourceDeclaresIsAnErrorNamingProgramAndUniform) {
  const auto sources = testing::memoryShaders({
      {"t.vert", kVertex},
      {"t.frag",
       "#version 450 core\n"
       "uniform vec4 u_tint;\n"
       "uniform float u_unused;  // optimised out: declared, so not an error\n"
       "#ifdef NEVER\n"
       "uniform float u_elsewhere;  // only another variant's\n"
       "#endif\n"
       "out vec4 o;\n"
       "void main() { o = u_tint; }\n"},
  });
  const LinkedProgram program =
      linkProgram(sources, {{GL_VERTEX_SHADER, "t.vert"}, {GL_FRAGMENT_SHADER, "t.frag"}}, slotDefines());
  EXPECT_GE(gl::uniformLocation(program, "u_tint"), 0);
  EXPECT_EQ(gl::uniformLocation(program, "u_unused"), -1);
  EXPECT_EQ(gl::uniformLocation(program, "u_elsewhere"), -1);
  const gl::Uniform<float> unused(program, "u_unused");
  unused.set(1.0f);  // nothing to set, no GL error
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  try {
    const gl::Uniform<glm::vec4> misspelt(program, "u_tnit");
    FAIL() << "a misspelt uniform was accepted";
  } catch (const ShaderError& e) {
    EXPECT_EQ(std::string(e.what()), "shaders/t.vert + shaders/t.frag declares no uniform u_tnit");
  }
}

}  // namespace
}  // namespace terrasol
