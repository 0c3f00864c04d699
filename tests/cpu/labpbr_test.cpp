#include "assets/labpbr.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

namespace terrasol {
namespace {

using namespace labpbr;

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

TEST(LabPbrNormal, DefaultsAndConventions) {
  const auto flat = decodeNormal(kDefaultNormal);
  EXPECT_EQ(flat.normal, glm::vec3(0.0f, 0.0f, 1.0f)) << "the default _n is exactly flat";
  const std::uint8_t other[4] = {128, 128, 255, 255};
  EXPECT_EQ(decodeNormal(other).normal, glm::vec3(0.0f, 0.0f, 1.0f)) << "so is the other centre code";
  const std::uint8_t tilted[4] = {126, 129, 255, 255};
  EXPECT_LT(decodeNormal(tilted).normal.x, 0.0f);
  EXPECT_LT(decodeNormal(tilted).normal.y, 0.0f);
  EXPECT_FLOAT_EQ(flat.ao, 1.0f);
  EXPECT_FLOAT_EQ(flat.depth, 0.0f);
  // LabPBR is DirectX: green 0 points up the texture (+y here); an OpenGL-convention pack flips it.
  const std::uint8_t up[4] = {128, 0, 128, 255};
  EXPECT_GT(decodeNormal(up).normal.y, 0.7f);
  EXPECT_LT(decodeNormal(up, true).normal.y, -0.7f);
  // B is AO, A is height: 0 means 25 % deep.
  const std::uint8_t deep[4] = {128, 128, 0, 0};
  EXPECT_FLOAT_EQ(decodeNormal(deep).ao, 0.0f);
  EXPECT_FLOAT_EQ(decodeNormal(deep).depth, 0.25f);
}

TEST(LabPbrNormal, OutsideTheUnitDiscIsClampedNeverNaN) {
  for (int r = 0; r < 256; r += 5)
    for (int g = 0; g < 256; g += 5) {
      const std::uint8_t texel[4] = {static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g), 255, 255};
      const auto n = decodeNormal(texel).normal;
      ASSERT_TRUE(finite(n)) << r << "," << g;
      ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f) << r << "," << g;
      ASSERT_GE(n.z, 0.0f);
    }
  const std::uint8_t corner[4] = {255, 255, 255, 255};
  EXPECT_FLOAT_EQ(decodeNormal(corner).normal.z, 0.0f);
}

TEST(LabPbrNormal, EncodeRoundTrips) {
  const glm::vec3 n = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
  std::uint8_t texel[4];
  encodeNormal(n, 0.5f, 0.1f, texel);
  const auto back = decodeNormal(texel);
  EXPECT_NEAR(back.normal.x, n.x, 0.01f);
  EXPECT_NEAR(back.normal.y, n.y, 0.01f);
  EXPECT_NEAR(back.ao, 0.5f, 0.003f);
  EXPECT_NEAR(back.depth, 0.1f, 0.002f);
  encodeNormal(glm::vec3(0.0f), 1.0f, 0.0f, texel);  // a zero vector becomes straight up, not NaN
  EXPECT_NEAR(decodeNormal(texel).normal.z, 1.0f, 1e-3f);
}

TEST(LabPbrSpecular, SmoothnessAndDielectricF0) {
  const glm::vec3 albedo(0.2f, 0.4f, 0.6f);
  const std::uint8_t smooth[4] = {255, 229, 0, 255}, rough[4] = {0, 0, 0, 255}, half[4] = {128, 10, 0, 255};
  EXPECT_FLOAT_EQ(decodeSpecular(smooth, albedo).roughness, 0.0f);
  EXPECT_NEAR(decodeSpecular(smooth, albedo).f0.x, 0.898f, 0.001f);
  EXPECT_EQ(decodeSpecular(smooth, albedo).reflectance, Reflectance::Dielectric);
  EXPECT_FLOAT_EQ(decodeSpecular(rough, albedo).roughness, 1.0f);
  EXPECT_NEAR(decodeSpecular(half, albedo).roughness, (1.0f - 128.0f / 255.0f) * (1.0f - 128.0f / 255.0f),
              1e-6f);
  EXPECT_NEAR(decodeSpecular(half, albedo).f0.y, 10.0f / 255.0f, 1e-6f);
}

TEST(LabPbrSpecular, PredefinedMetalsUseTheStandardsIndices) {
  const glm::vec3 albedo(0.1f);
  struct Expected {
    int id;
    glm::vec3 f0;
    const char* name;
  };
  const Expected metals[] = {
      {230, {0.531f, 0.512f, 0.496f}, "iron"},      {231, {0.944f, 0.776f, 0.373f}, "gold"},
      {232, {0.912f, 0.914f, 0.920f}, "aluminium"}, {233, {0.556f, 0.555f, 0.555f}, "chrome"},
      {234, {0.926f, 0.721f, 0.504f}, "copper"},    {235, {0.632f, 0.626f, 0.641f}, "lead"},
      {236, {0.679f, 0.642f, 0.588f}, "platinum"},  {237, {0.962f, 0.949f, 0.922f}, "silver"},
  };
  for (const auto& m : metals) {
    const std::uint8_t texel[4] = {200, static_cast<std::uint8_t>(m.id), 0, 255};
    const auto s = decodeSpecular(texel, albedo);
    EXPECT_EQ(s.reflectance, Reflectance::Metal) << m.name;
    EXPECT_EQ(s.metalId, m.id);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.f0[c], m.f0[c], 0.0015f) << m.name << " channel " << c;
    EXPECT_STREQ(metalName(m.id), m.name);
  }
  for (int g : {238, 250, 254, 255}) {  // undefined ids and 255: metal whose F0 is the albedo
    const std::uint8_t texel[4] = {200, static_cast<std::uint8_t>(g), 0, 255};
    const auto s = decodeSpecular(texel, glm::vec3(0.9f, 0.5f, 0.2f));
    EXPECT_EQ(s.reflectance, Reflectance::AlbedoMetal) << g;
    EXPECT_EQ(s.f0, glm::vec3(0.9f, 0.5f, 0.2f));
  }
}

TEST(LabPbrSpecular, PorositySubsurfaceAndEmission) {
  const glm::vec3 albedo(0.5f);
  auto s = [&](std::uint8_t b, std::uint8_t a) {
    const std::uint8_t texel[4] = {0, 0, b, a};
    return decodeSpecular(texel, albedo);
  };
  EXPECT_FLOAT_EQ(s(64, 255).porosity, 1.0f);
  EXPECT_FLOAT_EQ(s(64, 255).subsurface, 0.0f);
  EXPECT_FLOAT_EQ(s(65, 255).subsurface, 0.0f);
  EXPECT_FLOAT_EQ(s(65, 255).porosity, 0.0f);
  EXPECT_FLOAT_EQ(s(255, 255).subsurface, 1.0f);
  EXPECT_FLOAT_EQ(s(0, 254).emission, 1.0f);
  EXPECT_FLOAT_EQ(s(0, 255).emission, 0.0f);
  EXPECT_FLOAT_EQ(s(0, 127).emission, 0.5f);
  // The default (absent map) is all zero, and alpha 0 is data: zero emission, not "transparent".
  const auto none = decodeSpecular(kDefaultSpecular, albedo);
  EXPECT_FLOAT_EQ(none.emission, 0.0f);
  EXPECT_FLOAT_EQ(none.roughness, 1.0f);
  EXPECT_FLOAT_EQ(none.f0.x, 0.0f);
}

}  // namespace
}  // namespace terrasol
