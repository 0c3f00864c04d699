// Shader packs' GLSL rewritten for a 4.5 core context: each case packs write (Shadow-Tutorial's
// `#version 120` programs, Base-330's core-style outputs, the legacy texture functions and built-in
// inputs), where the prelude goes, the alpha test, and errors that name the pack's file and line.

#include "shaderpack/glsl_rewriter.h"

#include <gtest/gtest.h>

#include <map>

#include "shaderpack/glsl_tokens.h"
#include "support/error_of.h"

namespace terrasol {
namespace {

using testing::errorOf;

PreprocessedShader packSource(const std::string& text, const std::string& file = "gbuffers_terrain.vsh") {
  const ShaderPreprocessor files(
      [&](const std::string& path) -> std::optional<std::string> {
        if (path == file) return text;
        return std::nullopt;
      },
      "pack/shaders", IncludeRules::shaderPack());
  return files.process(file);
}

RewrittenStage rewrite(const std::string& text, PackStage stage, bool alphaTest = false,
                       const std::string& file = "gbuffers_terrain.vsh") {
  return rewritePackStage(packSource(text, file), {stage, nullptr, alphaTest});
}

int lineOf(const std::string& text, const std::string& needle) {
  const std::size_t at = text.find(needle);
  return at == std::string::npos ? -1
                                 : 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

TEST(GlslTokens, JoiningTheTokensGivesTheSourceBack) {
  const std::string source =
      "#version 120\n#define A(x) \\\n  (x * 2.0e-3f)\nuniform float b = .5; // c\n/* d\n e */ int f = "
      "0x1F;\n";
  const std::vector<GlslToken> tokens = tokenizeGlsl(source);
  EXPECT_EQ(joinTokens(tokens), source);
  const auto find = [&](const std::string& text) {
    return *std::find_if(tokens.begin(), tokens.end(), [&](const GlslToken& t) { return t.text == text; });
  };
  EXPECT_TRUE(find("x").directive) << "a continued #define line is still the directive";
  EXPECT_EQ(find("2.0e-3f").kind, GlslTokenKind::Number)
      << "an exponent's sign and a suffix stay in the number";
  EXPECT_FALSE(find("b").directive);
  EXPECT_EQ(find(".5").kind, GlslTokenKind::Number);
  EXPECT_EQ(find("0x1F").line, 6);
}

TEST(GlslRewriter, AVersion120VertexStageReadsTerrasolsInputs) {
  const std::string source =
      "#version 120\n"
      "attribute vec4 mc_Entity;\n"
      "varying vec2 texcoord; // gl_Vertex in a comment stays\n"
      "void main() {\n"
      "  texcoord = (gl_TextureMatrix[0] * gl_MultiTexCoord0).xy;\n"
      "  if (mc_Entity.x == 10000.0) texcoord *= 2.0;\n"
      "  gl_Position = ftransform() + gl_ModelViewMatrix * gl_Vertex;\n"
      "}\n";
  const RewrittenStage out = rewrite(source, PackStage::Vertex);
  const std::string& text = out.source.text;
  EXPECT_EQ(out.packVersion, 120);
  EXPECT_EQ(text.rfind("#version 450 core\n", 0), 0u) << text;
  ASSERT_EQ(out.attributes.size(), 1u);
  EXPECT_EQ(out.attributes[0].name, "mc_Entity");
  EXPECT_EQ(out.attributes[0].type, "vec4");
  EXPECT_NE(text.find(" vec4 mc_Entity;"), std::string::npos) << "a global, no longer an attribute";
  EXPECT_EQ(text.find("attribute"), std::string::npos);
  EXPECT_NE(text.find("out vec2 texcoord; // gl_Vertex in a comment stays"), std::string::npos);
  EXPECT_NE(text.find("(tsol_TextureMatrix[0] * tsol_MultiTexCoord0).xy"), std::string::npos);
  EXPECT_NE(text.find("tsol_ftransform() + tsol_ModelViewMatrix * tsol_Vertex"), std::string::npos);
  EXPECT_NE(text.find("void tsol_packMain()"), std::string::npos);
  EXPECT_NE(text.find("mc_Entity = vec4(tsol_Entity);"), std::string::npos);
  EXPECT_LT(lineOf(text, "tsol_readVertex();"), lineOf(text, "tsol_packMain();")) << "inputs read first";
  // Every line of the pack still names its place.
  const int line = lineOf(text, "tsol_ftransform() +");
  EXPECT_EQ(out.source.origin(line).file, "pack/shaders/gbuffers_terrain.vsh");
  EXPECT_EQ(out.source.origin(line).line, 7);
  EXPECT_EQ(out.source.origin(lineOf(text, "vec4 tsol_Vertex;")).file, "<shader pack prelude>");
  EXPECT_NE(out.source.mapLog("0:" + std::to_string(line) + "(3): error: x\n")
                .find("gbuffers_terrain.vsh:7: error: x"),
            std::string::npos);
}

TEST(GlslRewriter, AttributesKeepTheTypeEachProgramDeclares) {
  const RewrittenStage out = rewrite(
      "#version 330 compatibility\nlayout(location = 11) in vec2 mc_Entity;\nin vec4 at_tangent;\n"
      "in vec3 position;\nvoid main() { gl_Position = vec4(mc_Entity, at_tangent.xy); }\n",
      PackStage::Vertex);
  ASSERT_EQ(out.attributes.size(), 2u);
  EXPECT_EQ(out.attributes[0].type, "vec2");
  EXPECT_NE(out.source.text.find("mc_Entity = vec2(tsol_Entity);"), std::string::npos);
  EXPECT_NE(out.source.text.find("at_tangent = vec4(tsol_Tangent);"), std::string::npos);
  EXPECT_EQ(out.source.text.find("location = 11"), std::string::npos) << "its layout goes with the attribute";
  EXPECT_NE(out.source.text.find("in vec3 position;"), std::string::npos) << "an unknown input is left alone";
}

TEST(GlslRewriter, AVersion120FragmentStageWritesOutputsAndSamplesByTodaysNames) {
  const std::string source =
      "#version 120\n"
      "uniform sampler2D texture;\n"
      "uniform sampler2DShadow shadow;\n"
      "varying vec2 texcoord;\n"
      "float sample = 1.0;\n"
      "void main() {\n"
      "  vec4 c = texture2D(texture, texcoord) * shadow2D(shadow, vec3(texcoord, 0.5)).r * sample;\n"
      "  c += texture2DLod(texture, texcoord, 2.0) + gl_Color;\n"
      "/* DRAWBUFFERS:0 */\n"
      "  gl_FragData[0] = c;\n"
      "}\n";
  const RewrittenStage out = rewrite(source, PackStage::Fragment, false, "composite.fsh");
  const std::string& text = out.source.text;
  EXPECT_TRUE(out.fragData);
  EXPECT_NE(text.find("uniform sampler2D gtexture;"), std::string::npos);
  EXPECT_NE(text.find("in vec2 texcoord;"), std::string::npos);
  EXPECT_NE(
      text.find("texture(gtexture, texcoord) * tsol_shadow2D(shadow, vec3(texcoord, 0.5)).r * tsol_sample"),
      std::string::npos)
      << text;
  EXPECT_NE(text.find("vec4 tsol_shadow2D(sampler2DShadow s, vec3 c)"), std::string::npos);
  EXPECT_NE(text.find("textureLod(gtexture, texcoord, 2.0) + tsol_FrontColor"), std::string::npos);
  EXPECT_NE(text.find("in vec4 tsol_FrontColor;"), std::string::npos);
  EXPECT_NE(text.find("layout(location = 0) out vec4 tsol_FragData[8];"), std::string::npos);
  EXPECT_NE(text.find("tsol_FragData[0] = c;"), std::string::npos);
  EXPECT_NE(text.find("/* DRAWBUFFERS:0 */"), std::string::npos) << "comments are kept";
  EXPECT_EQ(text.find("tsol_packMain"), std::string::npos) << "no alpha test: main is the pack's";

  // From 1.30 on, `texture` is the function and newer keywords are keywords.
  const RewrittenStage core = rewrite(
      "#version 330 compatibility\nuniform sampler2D gtexture;\nin vec2 uv;\n"
      "layout(location = 0) out vec4 color;\nvoid main() { color = texture(gtexture, uv); }\n",
      PackStage::Fragment, true, "gbuffers_terrain.fsh");
  EXPECT_NE(core.source.text.find("color = texture(gtexture, uv);"), std::string::npos);
  ASSERT_EQ(core.outputs.size(), 1u);
  EXPECT_EQ(core.outputs[0].name, "color");
  EXPECT_EQ(core.outputs[0].location, 0);
  EXPECT_NE(core.source.text.find("tsol_packMain();\n  if (color.a < tsol_alphaTestRef) discard;"),
            std::string::npos)
      << "the alpha test reads the output at location 0";
}

TEST(GlslRewriter, DeclarationsGoAfterTheExtensionsOutsideTheirConditionals) {
  const std::string source =
      "#version 120\n"
      "#define A 1\n"
      "#ifdef GL_ARB_shader_texture_lod\n"
      "#extension GL_ARB_shader_texture_lod : enable\n"
      "#endif\n"
      "#extension GL_EXT_gpu_shader4 : enable\n"
      "varying vec4 c;\n"
      "void main() { gl_FragData[0] = c; }\n";
  const RewrittenStage out = rewrite(source, PackStage::Fragment, false, "final.fsh");
  const std::string& text = out.source.text;
  EXPECT_LT(lineOf(text, "#extension GL_EXT_gpu_shader4"), lineOf(text, "tsol_FragData[8]"));
  EXPECT_GT(lineOf(text, "tsol_FragData[8]"), 0);

  const RewrittenStage guarded = rewrite(
      "#version 120\n#ifdef X\n#extension GL_EXT_gpu_shader4 : enable\n#if 1\n#endif\n#endif\n"
      "varying vec4 c;\nvoid main() { gl_FragData[0] = c; }\n",
      PackStage::Fragment, false, "final.fsh");
  const std::string& g = guarded.source.text;
  EXPECT_GT(lineOf(g, "tsol_FragData[8]"), lineOf(g, "#endif\n#endif\n") + 1) << g;
  EXPECT_EQ(guarded.source.origin(lineOf(g, "in vec4 c;")).line, 7);
}

TEST(GlslRewriter, ErrorsNameThePacksFileAndLine) {
  const PreprocessedShader noVersion{"void main() {}\n", {{"pack/shaders/x.fsh", 1}}};
  EXPECT_NE(errorOf([&] { rewritePackStage(noVersion, {PackStage::Fragment}); }).find("x.fsh:1: no #version"),
            std::string::npos);
  const std::string noColour = errorOf([&] {
    rewrite("#version 330\nout vec4 a;\nout vec4 b;\nvoid main() { a = b = vec4(1.0); }\n",
            PackStage::Fragment, true, "shadow.fsh");
  });
  EXPECT_NE(noColour.find("shadow.fsh:1:"), std::string::npos) << noColour;
  EXPECT_NE(noColour.find("output at location 0"), std::string::npos) << noColour;
}

}  // namespace
}  // namespace terrasol
