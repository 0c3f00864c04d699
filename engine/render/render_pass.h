#pragma once
// A pass of the deferred renderer: it owns its programs and state, declares each frame what it reads
// and writes (or why it has nothing to do), and records its GL work when the graph runs it.

#include <string>

#include "render/frame.h"
#include "render/frame_graph.h"

namespace terrasol {

class RenderPass {
 public:
  RenderPass() = default;
  RenderPass(const RenderPass&) = delete;
  RenderPass& operator=(const RenderPass&) = delete;
  virtual ~RenderPass() = default;

  virtual const char* name() const = 0;
  // Declares the frame's reads and writes on `builder`, or skips the pass with the reason.
  virtual void setup(FrameGraph::Builder& builder, Frame& frame) = 0;
  // The GL work; runs only when the graph keeps the pass.
  virtual void execute(Frame& frame) = 0;
};

inline void addPass(FrameGraph& graph, RenderPass& pass, Frame& frame) {
  graph.add(
      pass.name(), [&](FrameGraph::Builder& builder) { pass.setup(builder, frame); },
      [&] { pass.execute(frame); });
}

}  // namespace terrasol
