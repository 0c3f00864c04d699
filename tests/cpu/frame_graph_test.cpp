#include "render/frame_graph.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace terrasol {
namespace {

// The renderer's shape: shadow -> geometry -> lighting -> translucent -> final | debug -> outline.
struct Pipeline {
  FrameGraph graph;
  std::vector<std::string> ran;
  int gbufferRealized = 0;
  FrameGraph::Resource gbuffer = graph.transient("gbuffer", [this] { ++gbufferRealized; });
  FrameGraph::Resource scene = graph.transient("scene");
  FrameGraph::Resource shadowMap = graph.import("shadow_map");
  FrameGraph::Resource target = graph.import("target");

  void add(const std::string& name, std::vector<FrameGraph::Resource> reads,
           std::vector<FrameGraph::Resource> writes, std::string skip = {}) {
    graph.add(
        name,
        [&](FrameGraph::Builder& b) {
          if (!skip.empty()) return b.skip(skip);
          for (auto r : reads) b.read(r);
          for (auto r : writes) b.write(r);
        },
        [this, name] { ran.push_back(name); });
  }
  void build(bool debugView, bool translucent, bool sunUp) {
    add("shadow", {}, {shadowMap}, sunUp ? "" : "neither sun nor moon is above the horizon");
    add("geometry", {}, {gbuffer});
    add("lighting", {gbuffer, shadowMap}, {scene});
    add("translucent", {gbuffer, shadowMap, scene}, {scene},
        translucent ? "" : "no translucent geometry in view");
    add("final", {scene}, {target});
    add("debug_view", {gbuffer}, {target}, debugView ? "" : "no debug view is chosen");
    graph.output(target);
  }
  std::string why(const std::string& pass) const {
    for (const auto& s : graph.skipped()) {
      if (s.pass == pass) return s.why;
    }
    return "(ran)";
  }
};

TEST(FrameGraphTest, EveryPassThatLeadsToTheOutputRunsInTheOrderAdded) {
  Pipeline p;
  p.build(false, true, true);
  p.graph.execute();
  EXPECT_EQ(p.ran, (std::vector<std::string>{"shadow", "geometry", "lighting", "translucent", "final"}));
  EXPECT_EQ(p.graph.executed(), p.ran);
  ASSERT_EQ(p.graph.skipped().size(), 1u);
  EXPECT_EQ(p.why("debug_view"), "no debug view is chosen");
}

TEST(FrameGraphTest, APassWithEmptyInputsIsLeftOutWithItsReason) {
  Pipeline p;
  p.build(false, false, false);
  p.graph.execute();
  EXPECT_EQ(p.ran, (std::vector<std::string>{"geometry", "lighting", "final"}));
  EXPECT_EQ(p.why("shadow"), "neither sun nor moon is above the horizon");
  EXPECT_EQ(p.why("translucent"), "no translucent geometry in view");
}

TEST(FrameGraphTest, PassesWhoseOutputNothingReadsAreCulledBackToTheirInputs) {
  Pipeline p;
  p.build(true, true, true);  // a debug view replaces the final image
  p.graph.execute();
  EXPECT_EQ(p.ran, (std::vector<std::string>{"geometry", "debug_view"}));
  EXPECT_EQ(p.why("final"), "debug_view replaces its target");
  EXPECT_EQ(p.why("translucent"), "no pass that runs reads its scene");
  EXPECT_EQ(p.why("lighting"), "no pass that runs reads its scene");
  EXPECT_EQ(p.why("shadow"), "no pass that runs reads its shadow_map");
}

TEST(FrameGraphTest, APassDrawingOverTheOutputKeepsWhatItReads) {
  Pipeline p;
  p.build(false, false, true);
  p.add("outline", {p.gbuffer, p.target}, {p.target});
  p.graph.output(p.target);
  p.graph.execute();
  EXPECT_EQ(p.ran, (std::vector<std::string>{"shadow", "geometry", "lighting", "final", "outline"}));
}

TEST(FrameGraphTest, TransientsAreRealizedOnceAndOnlyWhenARunningPassTouchesThem) {
  Pipeline p;
  p.build(false, false, true);
  p.graph.execute();
  EXPECT_EQ(p.gbufferRealized, 1);

  FrameGraph graph;
  int realized = 0;
  const auto unused = graph.transient("unused", [&] { ++realized; });
  const auto target = graph.import("target");
  graph.add(
      "orphan", [&](FrameGraph::Builder& b) { b.write(unused); }, [] {});
  graph.add(
      "final", [&](FrameGraph::Builder& b) { b.write(target); }, [] {});
  graph.output(target);
  graph.execute();
  EXPECT_EQ(realized, 0) << "the only writer was culled";
  EXPECT_EQ(graph.executed(), std::vector<std::string>{"final"});
}

TEST(FrameGraphDeathTest, ReadingATransientNoPassWroteIsAnError) {
  FrameGraph graph;
  const auto scene = graph.transient("scene");
  EXPECT_DEATH(graph.add(
                   "final", [&](FrameGraph::Builder& b) { b.read(scene); }, [] {}),
               "assertion failed: .*final reads scene before any pass writes it");
  const auto kept = graph.import("kept");
  EXPECT_NO_THROW(graph.add(
      "reader", [&](FrameGraph::Builder& b) { b.read(kept); }, [] {}))
      << "an imported resource lives beyond the frame";
}

TEST(FrameGraphDeathTest, AGraphRunsOnceAndNamesOnlyItsResources) {
  FrameGraph graph;
  const auto target = graph.import("target");
  EXPECT_DEATH(graph.output(target + 1), "unknown resource");
  graph.add(
      "final", [&](FrameGraph::Builder& b) { b.write(target); }, [] {});
  graph.output(target);
  graph.execute();
  EXPECT_DEATH(graph.execute(), "executed once");
  EXPECT_DEATH(graph.add(
                   "late", [&](FrameGraph::Builder& b) { b.write(target); }, [] {}),
               "late added after execute");
}

}  // namespace
}  // namespace terrasol
