// shaders.properties and OptiFine's expression language for custom uniforms, variables and
// program.<name>.enabled: each operator and function, names and vector components, smooth() over
// frames, conditionals, and errors with the file and line.

#include "shaderpack/shader_properties.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "shaderpack/pack_draw_state.h"
#include "shaderpack/pack_macros.h"
#include "support/error_of.h"

namespace terrasol {
namespace {

float eval(const char* text, const PackEvaluation& context = {}) {
  return PackExpression::parse(text, "test:1").evaluate(context).scalar();
}

using testing::errorOf;

TEST(PackExpression, OperatorsAndFunctionsAsOptiFineWritesThem) {
  EXPECT_FLOAT_EQ(eval("1 + 2 * 3"), 7.0f);
  EXPECT_FLOAT_EQ(eval("(1 + 2) * 3"), 9.0f);
  EXPECT_FLOAT_EQ(eval("-2 * -3"), 6.0f);
  EXPECT_FLOAT_EQ(eval("7 % 4"), 3.0f);
  EXPECT_FLOAT_EQ(eval("1 < 2 && 2 <= 2 && !(3 != 3) || false"), 1.0f);
  EXPECT_FLOAT_EQ(eval("true && 2 > 3"), 0.0f);
  EXPECT_FLOAT_EQ(eval("1 || 0 && 0"), 1.0f) << "&& binds tighter than ||";
  EXPECT_FLOAT_EQ(eval("2 + 3 > 4"), 1.0f) << "+ binds tighter than >";
  EXPECT_FLOAT_EQ(eval("1 / 0"), 0.0f) << "no Inf reaches a uniform";
  EXPECT_FLOAT_EQ(eval("clamp(5, 0, 1) + min(4, 2, 3) + max(1, 6)"), 9.0f);
  EXPECT_FLOAT_EQ(eval("if(0, 10, 1, 20, 30)"), 20.0f);
  EXPECT_FLOAT_EQ(eval("if(0, 10, 0, 20, 30)"), 30.0f);
  EXPECT_FLOAT_EQ(eval("in(3, 1, 2, 3) + between(0.5, 0, 1) + equals(1.0, 1.05, 0.1)"), 3.0f);
  EXPECT_FLOAT_EQ(eval("frac(2.75) + floor(-0.5) + ceil(0.2) + round(1.5) + signum(-4)"),
                  0.75f - 1 + 1 + 2 - 1);
  EXPECT_NEAR(eval("sin(pi / 2) + cos(0) + todeg(torad(90)) + atan2(1, 1) * 4 / pi"), 93.0f, 1e-4f);
  EXPECT_FLOAT_EQ(eval("pow(2, 10) + sqrt(16) + fmod(7, 3) + abs(-1) + exp(0) + log(1)"),
                  1024 + 4 + 1 + 1 + 1);
  EXPECT_FLOAT_EQ(eval("sqrt(-1) + log(0) + acos(2)"), 0.0f) << "no NaN reaches a uniform";
  const PackValue v = PackExpression::parse("vec3(1, 2, 1 + 2)", "t").evaluate({});
  EXPECT_EQ(v.size, 3);
  EXPECT_EQ(v.v, glm::vec4(1, 2, 3, 0));
}

TEST(PackExpression, NamesComponentsAndSmooth) {
  PackEvaluation context;
  context.lookUp = [](std::string_view name) -> std::optional<PackValue> {
    if (name == "worldTime") return PackValue::of(6000.0f);
    if (name == "cameraPosition") return PackValue{3, glm::vec4(1, 70, -3, 0)};
    return std::nullopt;
  };
  EXPECT_FLOAT_EQ(eval("worldTime / 24000.0", context), 0.25f);
  EXPECT_FLOAT_EQ(eval("cameraPosition.y - 64", context), 6.0f);
  EXPECT_FLOAT_EQ(eval("cameraPosition.z", context), -3.0f);
  const std::string unknown = errorOf([&] { eval("wetness * 2", context); });
  EXPECT_NE(unknown.find("unknown name 'wetness'"), std::string::npos) << unknown;
  EXPECT_NE(errorOf([&] { eval("cameraPosition.w", context); }).find("unknown name"), std::string::npos);

  // smooth: starts at its value, then moves 1 - 1/e of the way per fade time.
  float target = 0.0f;
  context.lookUp = [&](std::string_view name) -> std::optional<PackValue> {
    if (name == "target") return PackValue::of(target);
    return std::nullopt;
  };
  const PackExpression smooth = PackExpression::parse("smooth(target, 2, 1)", "t");
  context.frameTime = 0.0f;
  EXPECT_FLOAT_EQ(smooth.evaluate(context).scalar(), 0.0f);
  target = 1.0f;
  context.frameTime = 2.0f;  // one fade-up time
  EXPECT_NEAR(smooth.evaluate(context).scalar(), 1.0f - std::exp(-1.0f), 1e-5f);
  target = 0.0f;
  context.frameTime = 1.0f;  // one fade-down time
  EXPECT_NEAR(smooth.evaluate(context).scalar(), (1.0f - std::exp(-1.0f)) * std::exp(-1.0f), 1e-5f);
}

TEST(PackExpression, MalformedExpressionsNameTheirPlace) {
  for (const char* bad :
       {"1 +", "(1", "clamp(1, 2", "2 3", "@", "sin(1, 2)", "nofunction(1)", "if(1, 2)", "1.2.3"}) {
    const std::string e =
        errorOf([&] { PackExpression::parse(bad, "pack/shaders.properties:4").evaluate({}); });
    EXPECT_NE(e.find("pack/shaders.properties:4"), std::string::npos) << bad << ": " << e;
  }
}

TEST(ShaderProperties, KeysConditionalsCustomsAndPrograms) {
  const std::string text =
      "# a comment\n"
      "sun = false\n"
      "#if MC_VERSION >= 11700\n"
      "clouds = off\n"
      "#else\n"
      "clouds = fancy\n"
      "#endif\n"
      "sliders = A B \\\n"
      "  C\n"
      "variable.float.dayFraction = worldTime / 24000.0\n"
      "uniform.float.noonness = 1 - abs(dayFraction - 0.25) * 4\n"
      "uniform.vec2.offset = vec2(1, noonness)\n"
      "program.composite1.enabled = noonness > 0.5\n"
      "sun = true\n";
  const ShaderProperties p = parseShaderProperties(text, "shaders.properties", PackMacros(packMacros()));
  EXPECT_EQ(p.find("sun")->value, "true") << "the later line";
  EXPECT_EQ(p.find("clouds")->value, "off");
  EXPECT_EQ(p.find("sliders")->value, "A B C") << "joined as Java joins: the next line's indent dropped";
  EXPECT_EQ(p.find("nothing"), nullptr);
  ASSERT_EQ(p.customs.size(), 3u);
  EXPECT_FALSE(p.customs[0].uniform);
  EXPECT_EQ(p.customs[1].name, "noonness");
  EXPECT_EQ(p.customs[2].type, "vec2");
  EXPECT_EQ(p.customs[1].where, "shaders.properties:11");

  // Evaluated in order, each custom visible to those after it.
  float worldTime = 6000.0f;
  std::map<std::string, PackValue, std::less<>> values;
  PackEvaluation context;
  context.lookUp = [&](std::string_view name) -> std::optional<PackValue> {
    if (name == "worldTime") return PackValue::of(worldTime);
    if (const auto found = values.find(name); found != values.end()) return found->second;
    return std::nullopt;
  };
  const auto frame = [&] {
    values.clear();
    for (const PackCustom& c : p.customs) values[c.name] = c.expression.evaluate(context);
  };
  frame();
  EXPECT_FLOAT_EQ(values["noonness"].scalar(), 1.0f);
  EXPECT_EQ(values["offset"].v, glm::vec4(1, 1, 0, 0));
  EXPECT_TRUE(p.programEnabled("composite1", context));
  EXPECT_TRUE(p.programEnabled("composite2", context)) << "no line: enabled";
  worldTime = 12000.0f;
  frame();
  EXPECT_FALSE(p.programEnabled("composite1", context));

  for (const auto& [bad, line] :
       std::vector<std::pair<std::string, std::string>>{{"a = 1\nno separator here\n", ":2"},
                                                        {"uniform.double.x = 1\n", ":1"},
                                                        {"uniform.float.x = 1 +\n", ":1"},
                                                        {"a = 1\nprogram.composite.enabled = (1\n", ":2"},
                                                        {"#if 1\nx = 1\n", ":1"}}) {
    const std::string e = errorOf([&] { parseShaderProperties(bad, "sp", PackMacros()); });
    EXPECT_NE(e.find("sp" + line), std::string::npos) << bad << ": " << e;
  }
}

TEST(PackDrawState, AlphaTestBlendAndSwitchesPerProgram) {
  const ShaderProperties p = parseShaderProperties(
      "alphaTest.gbuffers_terrain = GREATER 0.5\nalphaTest.shadow=off\n"
      "blend.gbuffers_water=ONE ONE_MINUS_SRC_ALPHA\nblend.gbuffers_skytextured=off\n"
      "blend.gbuffers_clouds=SRC_ALPHA ONE_MINUS_SRC_ALPHA ONE ZERO\nsun=false\noldLighting=true\n"
      "alphaTest.gbuffers_hand=LESS 0.5\nblend.gbuffers_hand=ONE PLUS\nmoon=maybe\n",
      "shaders.properties", PackMacros(packMacros()));
  EXPECT_EQ(packDrawState(p, "gbuffers_terrain").alphaTestRef, 0.5f);
  EXPECT_EQ(packDrawState(p, "shadow").alphaTestRef, 0.0f) << "off";
  EXPECT_FALSE(packDrawState(p, "gbuffers_water").alphaTestRef) << "the program's default";
  const PackDrawState water = packDrawState(p, "gbuffers_water");
  ASSERT_TRUE(water.blend);
  EXPECT_EQ(water.blend->factors,
            (std::array<std::string, 4>{"ONE", "ONE_MINUS_SRC_ALPHA", "ONE", "ONE_MINUS_SRC_ALPHA"}))
      << "two factors serve alpha too";
  EXPECT_FALSE(packDrawState(p, "gbuffers_skytextured").blend->enabled);
  EXPECT_EQ(packDrawState(p, "gbuffers_clouds").blend->factors[3], "ZERO");
  EXPECT_FALSE(packSwitch(p, "sun", true));
  EXPECT_TRUE(packSwitch(p, "oldLighting", false));
  EXPECT_TRUE(packSwitch(p, "clouds", true)) << "absent: the default";
  EXPECT_NE(errorOf([&] { packDrawState(p, "gbuffers_hand"); }).find("shaders.properties:8"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { packSwitch(p, "moon", true); }).find("expected true or false"), std::string::npos);
}

}  // namespace
}  // namespace terrasol
