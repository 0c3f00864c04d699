#pragma once
// A frame as a graph of passes (Filament's FrameGraph, small). Each pass declares, when it is added,
// the resources it reads and writes, or that it has nothing to do this frame (`skip`). Then `execute`
// culls every pass whose writes nothing needed reads, realizes the transient resources the surviving
// passes touch, and runs them in the order they were added. So "leave out what the scene does not
// need" is the graph's doing: a debug view that replaces the final image leaves the lighting, the
// translucent pass and the shadow map they read unrun, and the report says why.
//
// Resources are versioned: a write makes a new version, a read takes the latest one declared before
// it. A pass is needed when a needed pass reads a version it wrote, or it wrote the frame's output.
// Plain C++, no GL: a pass's GL work is its execute function.

#include <functional>
#include <string>
#include <vector>

namespace terrasol {

class FrameGraph {
 public:
  using Resource = int;

  struct Skipped {
    std::string pass, why;
  };

  class Builder {
   public:
    void read(Resource r);
    void write(Resource r);
    // Nothing to do this frame (its inputs are empty): the pass is left out, and so are its
    // declarations, so later readers see the version before it.
    void skip(std::string why);
    bool written(Resource r) const { return graph_.written(r); }

   private:
    friend class FrameGraph;
    Builder(FrameGraph& graph, int pass) : graph_(graph), pass_(pass) {}
    FrameGraph& graph_;
    int pass_;
  };

  // Lives beyond the frame (the window, a kept shadow map): reading it needs no writer this frame.
  Resource import(std::string name);
  // Whether a pass added so far (and not skipped) writes `r`.
  bool written(Resource r) const;
  // Made for the frame: `realize` runs before the first pass that touches it, and only if one runs.
  Resource transient(std::string name, std::function<void()> realize = {});
  // The frame's result: what every kept pass leads to.
  void output(Resource r);

  // Runs `setup` at once to declare the pass's reads and writes; `run` is called by execute.
  void add(std::string name, const std::function<void(Builder&)>& setup, std::function<void()> run);

  // Culls (unless `cull` is false: then every pass not skipped runs), realizes and runs; `after(name)`
  // follows each pass that ran (the pass timings).
  void execute(const std::function<void(const std::string&)>& after = {}, bool cull = true);

  // Valid after execute: the passes left out, in the order they were added, with the reason.
  const std::vector<Skipped>& skipped() const { return skipped_; }
  const std::vector<std::string>& executed() const { return executed_; }

 private:
  struct Version {
    Resource resource;
    int writer;  // the pass, or -1: the resource as it came into the frame
  };
  struct ResourceNode {
    std::string name;
    bool imported;
    std::function<void()> realize;
    int latest;  // the version the next read sees
  };
  struct PassNode {
    std::string name;
    std::function<void()> run;
    std::vector<int> reads, writes;  // versions
    std::string skip;                // non-empty: declared as having nothing to do
    bool needed = false;
  };
  std::string whyUnneeded(const PassNode& pass) const;
  void checkResource(Resource r) const;

  std::vector<ResourceNode> resources_;
  std::vector<Version> versions_;
  std::vector<PassNode> passes_;
  std::vector<Resource> outputs_;
  std::vector<Skipped> skipped_;
  std::vector<std::string> executed_;
  bool ran_ = false;  // execute is called once
};

}  // namespace terrasol
