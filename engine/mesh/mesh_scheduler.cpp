#include "mesh/mesh_scheduler.h"

#include <algorithm>
#include <exception>
#include <string>

#include "core/thread_priority.h"

namespace terrasol {

std::string MeshFailure::message() const {
  return "meshing section (" + std::to_string(pos.x) + ", " + std::to_string(pos.section) + ", " +
         std::to_string(pos.z) + ") failed: " + what;
}

MeshScheduler::MeshScheduler(const BlockMeshTable& table, int threads, MeshFunction mesh)
    : table_(table), mesh_(std::move(mesh)) {
  for (int i = 0; i < std::max(threads, 1); ++i)
    workers_.emplace_back([this] {
      lowerThisThreadsPriority();
      work();
    });
}

MeshScheduler::~MeshScheduler() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  workers_.clear();
}

std::uint64_t MeshScheduler::key(SectionPos s) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(s.x)) << 32 ^
          static_cast<std::uint32_t>(s.z)) *
             32 +
         static_cast<std::uint64_t>(s.section);
}

void MeshScheduler::markDirty(SectionPos section) {
  if (section.section < 0 || section.section >= kSectionCount) return;
  if (dirtySet_.insert(key(section)).second) dirty_.push_back(section);
}

void MeshScheduler::markBlockChanged(const BlockPos& p) {
  const int lx = localOf(p.x), ly = localOf(p.y), lz = localOf(p.z);
  for (int dz = lz == 0 ? -1 : 0; dz <= (lz == kLastCell ? 1 : 0); ++dz)
    for (int dy = ly == 0 ? -1 : 0; dy <= (ly == kLastCell ? 1 : 0); ++dy)
      for (int dx = lx == 0 ? -1 : 0; dx <= (lx == kLastCell ? 1 : 0); ++dx) {
        markDirty({chunkOf(p.x) + dx, sectionOf(p.y) + dy, chunkOf(p.z) + dz});
      }
}

std::vector<SectionMesh> MeshScheduler::update(const World& world, std::size_t maxSnapshots) {
  std::vector<SectionMesh> ready;
  std::size_t taken = 0;
  while (!dirty_.empty() && taken < maxSnapshots) {
    const SectionPos pos = dirty_.front();
    dirty_.pop_front();
    dirtySet_.erase(key(pos));
    const std::uint64_t generation = nextGeneration_++;
    latest_[key(pos)] = generation;
    auto job = std::make_unique<Job>();
    const CaptureResult captured = captureSection(world, pos, job->snapshot);
    if (captured != CaptureResult::Captured) {
      latest_.erase(key(pos));  // any older job still running is dropped when it arrives
      ready.push_back(uncapturedMesh(pos, captured));  // nothing visible: the old mesh goes
      continue;
    }
    ++taken;
    job->generation = generation;
    {
      std::lock_guard lock(mutex_);
      jobs_.push_back(std::move(job));
    }
    wake_.notify_one();
  }
  std::vector<Done> done;
  {
    std::lock_guard lock(mutex_);
    done.swap(done_);
  }
  for (auto& d : done) {
    const auto it = latest_.find(key(d.mesh.pos));
    if (it == latest_.end() || it->second != d.generation) continue;  // a newer job replaces it
    latest_.erase(it);
    if (d.failure) {
      failures_.push_back({d.mesh.pos, std::move(*d.failure)});
      continue;
    }
    ready.push_back(std::move(d.mesh));
  }
  return ready;
}

std::size_t MeshScheduler::inFlight() const {
  std::lock_guard lock(mutex_);
  return jobs_.size() + working_ + done_.size();
}

void MeshScheduler::work() {
  for (;;) {
    std::unique_ptr<Job> job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stop_ || !jobs_.empty(); });
      if (stop_) return;
      job = std::move(jobs_.front());
      jobs_.pop_front();
      ++working_;
    }
    Done done{SectionMesh{job->snapshot.pos, {}}, job->generation, std::nullopt};
    // Carried to the main thread, whose update() names the section: thrown here, it would end the
    // process from a worker.
    try {
      done.mesh = mesh_(job->snapshot, table_);
    } catch (const std::exception& e) {
      done.failure = e.what();
    } catch (...) {
      done.failure = "an exception that is not a std::exception";
    }
    std::lock_guard lock(mutex_);
    done_.push_back(std::move(done));
    --working_;
  }
}

}  // namespace terrasol
