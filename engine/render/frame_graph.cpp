#include "render/frame_graph.h"

#include <algorithm>

#include "core/assert.h"

namespace terrasol {

void FrameGraph::Builder::read(Resource r) {
  graph_.checkResource(r);
  PassNode& pass = graph_.passes_[static_cast<std::size_t>(pass_)];
  pass.reads.push_back(r);  // a resource until setup returns, then its version
}

void FrameGraph::Builder::write(Resource r) {
  graph_.checkResource(r);
  graph_.passes_[static_cast<std::size_t>(pass_)].writes.push_back(r);
}

void FrameGraph::Builder::skip(std::string why) {
  graph_.passes_[static_cast<std::size_t>(pass_)].skip = why.empty() ? "skipped" : std::move(why);
}

FrameGraph::Resource FrameGraph::import(std::string name) {
  const auto r = static_cast<Resource>(resources_.size());
  versions_.push_back({r, -1});
  resources_.push_back({std::move(name), true, {}, static_cast<int>(versions_.size()) - 1});
  return r;
}

FrameGraph::Resource FrameGraph::transient(std::string name, std::function<void()> realize) {
  const Resource r = import(std::move(name));
  resources_.back().imported = false;
  resources_.back().realize = std::move(realize);
  return r;
}

void FrameGraph::output(Resource r) {
  checkResource(r);
  outputs_.push_back(r);
}

bool FrameGraph::written(Resource r) const {
  checkResource(r);
  return versions_[static_cast<std::size_t>(resources_[static_cast<std::size_t>(r)].latest)].writer >= 0;
}

void FrameGraph::add(std::string name, const std::function<void(Builder&)>& setup,
                     std::function<void()> run) {
  TERRASOL_ASSERT(!ran_, "frame graph: pass " + name + " added after execute");
  const int index = static_cast<int>(passes_.size());
  passes_.push_back({std::move(name), std::move(run), {}, {}, {}, false});
  Builder builder(*this, index);
  setup(builder);
  PassNode& pass = passes_.back();
  if (!pass.skip.empty()) {
    pass.reads.clear();
    pass.writes.clear();
    return;
  }
  // Reads first: a pass that reads and writes a resource (blending onto it) reads the version before.
  for (int& r : pass.reads) {
    ResourceNode& resource = resources_[static_cast<std::size_t>(r)];
    TERRASOL_ASSERT(resource.imported || versions_[static_cast<std::size_t>(resource.latest)].writer >= 0,
                    "frame graph: " + pass.name + " reads " + resource.name + " before any pass writes it");
    r = resource.latest;
  }
  for (int& r : pass.writes) {
    versions_.push_back({r, index});
    resources_[static_cast<std::size_t>(r)].latest = static_cast<int>(versions_.size()) - 1;
    r = resources_[static_cast<std::size_t>(r)].latest;
  }
}

void FrameGraph::execute(const std::function<void(const std::string&)>& after, bool cull) {
  TERRASOL_ASSERT(!ran_, "frame graph: a graph is executed once");
  ran_ = true;
  // Backwards from the outputs: a pass is needed when it wrote a version that is needed.
  std::vector<bool> neededVersion(versions_.size(), false);
  for (const Resource r : outputs_)
    neededVersion[static_cast<std::size_t>(resources_[static_cast<std::size_t>(r)].latest)] = true;
  for (auto pass = passes_.rbegin(); pass != passes_.rend(); ++pass) {
    pass->needed = pass->skip.empty() &&
                   (!cull || std::any_of(pass->writes.begin(), pass->writes.end(),
                                         [&](int v) { return neededVersion[static_cast<std::size_t>(v)]; }));
    if (!pass->needed) continue;
    for (const int v : pass->reads) neededVersion[static_cast<std::size_t>(v)] = true;
  }

  std::vector<bool> realized(resources_.size(), false);
  for (const PassNode& pass : passes_) {
    // Every version a running pass reads was written by a pass that runs before it, or came in.
    for (const int v : pass.reads) {
      const int writer = versions_[static_cast<std::size_t>(v)].writer;
      TERRASOL_ASSERT(!pass.needed || writer < 0 || passes_[static_cast<std::size_t>(writer)].needed,
                      "frame graph: " + pass.name + " reads what a culled pass writes");
    }
    if (!pass.skip.empty()) {
      skipped_.push_back({pass.name, pass.skip});
      continue;
    }
    if (!pass.needed) {
      skipped_.push_back({pass.name, whyUnneeded(pass)});
      continue;
    }
    for (const auto* list : {&pass.reads, &pass.writes}) {
      for (const int v : *list) {
        const auto r = static_cast<std::size_t>(versions_[static_cast<std::size_t>(v)].resource);
        if (realized[r]) continue;
        realized[r] = true;
        if (resources_[r].realize) resources_[r].realize();
      }
    }
    if (pass.run) pass.run();
    executed_.push_back(pass.name);
    if (after) after(pass.name);
  }
}

void FrameGraph::checkResource(Resource r) const {
  TERRASOL_ASSERT(r >= 0 && static_cast<std::size_t>(r) < resources_.size(), "frame graph: unknown resource");
}

// A culled pass's first write: replaced by a later writer that ignores it, or read by no pass that runs.
std::string FrameGraph::whyUnneeded(const PassNode& pass) const {
  if (pass.writes.empty()) return "it writes nothing";
  const int written = pass.writes.front();
  const Resource resource = versions_[static_cast<std::size_t>(written)].resource;
  const std::string& name = resources_[static_cast<std::size_t>(resource)].name;
  const int index = static_cast<int>(&pass - passes_.data());
  for (std::size_t later = static_cast<std::size_t>(index) + 1; later < passes_.size(); ++later) {
    const PassNode& next = passes_[later];
    const bool rewrites = std::any_of(next.writes.begin(), next.writes.end(), [&](int v) {
      return versions_[static_cast<std::size_t>(v)].resource == resource;
    });
    const bool reads = std::find(next.reads.begin(), next.reads.end(), written) != next.reads.end();
    if (rewrites && !reads && next.needed) return next.name + " replaces its " + name;
    if (rewrites) break;
  }
  return "no pass that runs reads its " + name;
}

}  // namespace terrasol
