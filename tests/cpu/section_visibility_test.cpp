// Cave culling's per-section face links (mesh/section_visibility.h).

#include "mesh/section_visibility.h"

#include <gtest/gtest.h>

namespace terrasol {
namespace {

constexpr int kWest = 0, kEast = 1, kDown = 2, kUp = 3, kNorth = 4, kSouth = 5;

SectionSnapshot openSection() {
  SectionSnapshot s;
  s.pos = {0, 4, 0};
  s.blocks.fill(kAir);
  s.opaque.fill(0);
  s.light.fill(SectionSnapshot::kOpen);
  return s;
}

void solid(SectionSnapshot& s, int x, int y, int z) {
  s.opaque[SectionSnapshot::index(x, y, z)] = 1;
  s.light[SectionSnapshot::index(x, y, z)] = 0;
}

TEST(SectionVisibility, AnOpenSectionLinksEveryFaceAndASolidOneNone) {
  SectionSnapshot s = openSection();
  EXPECT_EQ(sectionFaceLinks(s), kAllFacesLinked);
  for (int y = 0; y < 16; ++y)
    for (int z = 0; z < 16; ++z)
      for (int x = 0; x < 16; ++x) solid(s, x, y, z);
  EXPECT_EQ(sectionFaceLinks(s), kNoFacesLinked);
}

TEST(SectionVisibility, AFloorSplitsUpFromDownButNotTheSides) {
  SectionSnapshot s = openSection();
  for (int z = 0; z < 16; ++z)
    for (int x = 0; x < 16; ++x) solid(s, x, 8, z);
  const FaceLinks links = sectionFaceLinks(s);
  EXPECT_FALSE(linked(links, kUp, kDown));
  EXPECT_TRUE(linked(links, kUp, kWest));    // above the floor the sides are open
  EXPECT_TRUE(linked(links, kDown, kEast));  // and below it
  EXPECT_TRUE(linked(links, kNorth, kSouth));
  EXPECT_TRUE(linked(links, kEast, kWest));
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b) EXPECT_EQ(linked(links, a, b), linked(links, b, a)) << a << " " << b;
}

TEST(SectionVisibility, ATunnelLinksOnlyItsEnds) {
  SectionSnapshot s = openSection();
  for (int y = 0; y < 16; ++y)
    for (int z = 0; z < 16; ++z)
      for (int x = 0; x < 16; ++x)
        if (!(y == 5 && z == 5)) solid(s, x, y, z);  // a 1x1 tunnel along x
  const FaceLinks links = sectionFaceLinks(s);
  EXPECT_TRUE(linked(links, kWest, kEast));
  EXPECT_FALSE(linked(links, kWest, kUp));
  EXPECT_FALSE(linked(links, kNorth, kSouth));
  EXPECT_FALSE(linked(links, kUp, kDown));
  // A sealed pocket inside links nothing.
  SectionSnapshot pocket = openSection();
  for (int y = 0; y < 16; ++y)
    for (int z = 0; z < 16; ++z)
      for (int x = 0; x < 16; ++x)
        if (!(x == 7 && y == 7 && z == 7)) solid(pocket, x, y, z);
  EXPECT_EQ(sectionFaceLinks(pocket), kNoFacesLinked);
}

TEST(SectionVisibility, TheHaloDoesNotLink) {
  SectionSnapshot s = openSection();
  // Solid everywhere inside except two cells at opposite faces; the open halo must not join them.
  for (int y = 0; y < 16; ++y)
    for (int z = 0; z < 16; ++z)
      for (int x = 0; x < 16; ++x)
        if (!((x == 0 || x == 15) && y == 3 && z == 3)) solid(s, x, y, z);
  const FaceLinks links = sectionFaceLinks(s);
  EXPECT_FALSE(linked(links, kWest, kEast));
}

}  // namespace
}  // namespace terrasol
