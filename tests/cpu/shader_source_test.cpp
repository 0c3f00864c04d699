#include "assets/shader_source.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/paths.h"
#include "support/error_of.h"
#include "support/memory_shaders.h"

namespace terrasol {
namespace {

std::string errorOf(const ShaderPreprocessor& pre, const std::string& file) {
  return testing::errorOf([&] { pre.process(file); });
}

TEST(ShaderPreprocessor, InjectsDefinesRightAfterVersion) {
  const auto pre = testing::memoryShaders({{"a.frag", "// header\n#version 450 core\nvoid main() {}\n"}});
  const auto out = pre.process("a.frag", {{"ATTRIB_POSITION", "0"}, {"FEATURE_FOG", "1"}});
  EXPECT_EQ(
      out.text,
      "// header\n#version 450 core\n#define ATTRIB_POSITION 0\n#define FEATURE_FOG 1\nvoid main() {}\n");
  EXPECT_EQ(out.origin(3).file, "<defines>");
  EXPECT_EQ(out.origin(5).file, "shaders/a.frag");
  EXPECT_EQ(out.origin(5).line, 3);
}

TEST(ShaderPreprocessor, MapsIncludedLinesToTheirFiles) {
  const auto pre = testing::memoryShaders({
      {"main.frag", "#version 450 core\n#include \"lib/x.glsl\"\nvoid main() {}\n"},
      {"lib/x.glsl", "float x1;\nfloat x2;\n"},
  });
  const auto out = pre.process("main.frag");
  EXPECT_EQ(out.text, "#version 450 core\nfloat x1;\nfloat x2;\nvoid main() {}\n");
  EXPECT_EQ(out.origin(3).file, "shaders/lib/x.glsl");
  EXPECT_EQ(out.origin(3).line, 2);
  EXPECT_EQ(out.origin(4).file, "shaders/main.frag");
  EXPECT_EQ(out.origin(4).line, 3);
}

TEST(ShaderPreprocessor, IncludesEachFileOnceEvenInDiamondsAndCycles) {
  const auto pre = testing::memoryShaders({
      {"main.frag", "#version 450 core\n#include \"lib/a.glsl\"\n#include \"lib/b.glsl\"\n"},
      {"lib/a.glsl", "#include \"lib/common.glsl\"\nA\n"},
      {"lib/b.glsl", "#  include \"lib/./common.glsl\"\n#include \"lib/a.glsl\"\nB\n"},
      {"lib/common.glsl", "#include \"lib/b.glsl\"\nCOMMON\n"},
  });
  EXPECT_EQ(pre.process("main.frag").text, "#version 450 core\nB\nCOMMON\nA\n");
}

TEST(ShaderPreprocessor, MissingIncludeNamesTheIncludingFileAndLine) {
  const auto pre =
      testing::memoryShaders({{"main.frag", "#version 450 core\n\n#include \"lib/nope.glsl\"\n"}});
  const std::string error = errorOf(pre, "main.frag");
  EXPECT_NE(error.find("shaders/main.frag:3:"), std::string::npos) << error;
  EXPECT_NE(error.find("shaders/lib/nope.glsl"), std::string::npos) << error;
}

TEST(ShaderPreprocessor, RejectsMalformedDirectives) {
  const auto pre = testing::memoryShaders({
      {"noversion.frag", "void main() {}\n"},
      {"early.frag", "#include \"lib/x.glsl\"\n#version 450 core\n"},
      {"twice.frag", "#version 450 core\n#version 450 core\n"},
      {"unquoted.frag", "#version 450 core\n#include <lib/x.glsl>\n"},
      {"escape.frag", "#version 450 core\n#include \"../secret.glsl\"\n"},
      {"nested.frag", "#version 450 core\n#include \"lib/v.glsl\"\n"},
      {"lib/x.glsl", "X\n"},
      {"lib/v.glsl", "\n#version 330\n"},
  });
  EXPECT_NE(errorOf(pre, "noversion.frag").find("shaders/noversion.frag:1: missing #version"),
            std::string::npos);
  EXPECT_NE(errorOf(pre, "early.frag").find("shaders/early.frag:1: #include before #version"),
            std::string::npos);
  EXPECT_NE(errorOf(pre, "twice.frag").find("shaders/twice.frag:2: second #version"), std::string::npos);
  EXPECT_NE(errorOf(pre, "unquoted.frag").find("shaders/unquoted.frag:2: malformed #include"),
            std::string::npos);
  EXPECT_NE(errorOf(pre, "escape.frag").find("shaders/escape.frag:2: include path"), std::string::npos);
  EXPECT_NE(errorOf(pre, "nested.frag").find("shaders/lib/v.glsl:2: #version in an included file"),
            std::string::npos);
  EXPECT_NE(errorOf(pre, "absent.frag").find("cannot find shader file 'shaders/absent.frag'"),
            std::string::npos);
}

TEST(ShaderPreprocessor, MapsDriverLogPositionsBackToSourceFiles) {
  const auto pre = testing::memoryShaders({
      {"main.frag", "#version 450 core\n#include \"lib/x.glsl\"\nvoid main() {}\n"},
      {"lib/x.glsl", "float a;\nfloat b = c;\n"},
  });
  const auto out = pre.process("main.frag", {{"D", "1"}});
  // Output line 4 is lib/x.glsl:2 (line 2 is the injected define).
  EXPECT_EQ(out.mapLog("0:4(11): error: `c' undeclared"), "shaders/lib/x.glsl:2: error: `c' undeclared\n");
  EXPECT_EQ(out.mapLog("0(4) : error C1008: undefined variable \"c\""),
            "shaders/lib/x.glsl:2: error C1008: undefined variable \"c\"\n");
  EXPECT_EQ(out.mapLog("ERROR: 0:5: 'main' : syntax error"),
            "shaders/main.frag:3: ERROR: 'main' : syntax error\n");
  EXPECT_EQ(out.mapLog("a line without position"), "a line without position\n");
  EXPECT_EQ(out.mapLog("0:99(1): error: past the end"), "<unknown>:99: error: past the end\n");
}

TEST(ShaderPreprocessor, EveryShipedShaderPreprocesses) {
  const ShaderPreprocessor pre(shaderDir());
  int count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(shaderDir())) {
    const auto ext = entry.path().extension();
    if (ext != ".vert" && ext != ".frag" && ext != ".geom" && ext != ".comp") continue;
    const auto relative = std::filesystem::relative(entry.path(), shaderDir()).generic_string();
    EXPECT_NO_THROW(pre.process(relative)) << relative;
    ++count;
  }
  EXPECT_GE(count, 2);
}

TEST(DeclaredUniforms, ListsEveryNameOfPlainDeclarationsAndSkipsBlocksAndComments) {
  const std::string source =
      "#version 450 core\n"
      "uniform mat4 u_a;  // uniform float u_commented;\n"
      "layout(binding = 3) uniform sampler2D u_map;\n"
      "uniform float u_b, u_c[4];\n"
      "/* uniform vec3 u_blockComment; */\n"
      "layout(std140) uniform Block { vec4 inBlock; };\n"
      "#ifdef SOME_VARIANT\n"
      "uniform highp vec2 u_d;\n"
      "#endif\n"
      "void main() {}\n";
  EXPECT_EQ(declaredUniforms(source), (std::vector<std::string>{"u_a", "u_map", "u_b", "u_c", "u_d"}));
}

}  // namespace
}  // namespace terrasol
