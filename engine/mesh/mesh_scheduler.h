#pragma once
// Remeshing on worker threads. The main thread marks sections dirty (blocks or light changed), takes
// their snapshots (the World is main-thread only) and queues them; workers mesh; finished meshes come
// back whole, each the complete replacement of its section's old mesh, so nothing is ever drawn half
// updated. A section marked dirty again while its job runs gets a new job, and the older result is
// dropped when it arrives. A job that throws comes back as a MeshFailure naming its section; the
// section keeps its old mesh.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "mesh/mesher.h"
#include "mesh/section_mesh.h"

namespace terrasol {

// A section whose meshing threw, and what it threw.
struct MeshFailure {
  SectionPos pos;
  std::string what;
  // "meshing section (x, section, z) failed: what"
  std::string message() const;
};

class MeshScheduler {
 public:
  // Meshes a snapshot on a worker; tests swap in one that fails.
  using MeshFunction = std::function<SectionMesh(const SectionSnapshot&, const BlockMeshTable&)>;

  MeshScheduler(const BlockMeshTable& table, int threads, MeshFunction mesh = meshWithLinks);
  ~MeshScheduler();
  MeshScheduler(const MeshScheduler&) = delete;
  MeshScheduler& operator=(const MeshScheduler&) = delete;

  // Main thread.
  void markDirty(SectionPos section);
  // The block's section, and the neighbouring sections whose one-block halo holds it.
  void markBlockChanged(const BlockPos& pos);

  // Main thread, once a frame: snapshots up to `maxSnapshots` dirty sections and queues them, then
  // returns every mesh finished since the last call. Empty and buried sections come back as empty
  // meshes at once (their old mesh must go). A section whose meshing failed is left out (its old mesh
  // stays) and goes to takeFailures().
  std::vector<SectionMesh> update(const World& world, std::size_t maxSnapshots = 64);
  // Main thread: the failures update() collected since the last call.
  std::vector<MeshFailure> takeFailures() { return std::exchange(failures_, {}); }

  std::size_t dirty() const { return dirty_.size(); }
  std::size_t inFlight() const;

 private:
  struct Job {
    SectionSnapshot snapshot;
    std::uint64_t generation;
  };
  struct Done {
    SectionMesh mesh;
    std::uint64_t generation;
    std::optional<std::string> failure;  // what the mesh function threw
  };
  void work();
  static std::uint64_t key(SectionPos s);

  const BlockMeshTable& table_;
  MeshFunction mesh_;
  std::deque<SectionPos> dirty_;  // main thread, in the order they were marked
  std::unordered_set<std::uint64_t> dirtySet_;
  std::unordered_map<std::uint64_t, std::uint64_t> latest_;  // main thread: newest generation per section
  std::uint64_t nextGeneration_ = 1;
  std::vector<MeshFailure> failures_;  // main thread

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::unique_ptr<Job>> jobs_;
  std::vector<Done> done_;
  std::size_t working_ = 0;
  bool stop_ = false;
  std::vector<std::jthread> workers_;
};

}  // namespace terrasol
