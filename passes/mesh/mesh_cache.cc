#include "passes/mesh/mesh_cache.h"

#include <algorithm>
#include <set>
#include <thread>

#include "passes/mesh/child_reader.h"
#include "passes/mesh/in_process_reader.h"
#include "passes/mesh/reader_location.h"

namespace mdlc::mesh {

MeshCache::MeshCache(const Limits& limits, MeshReading reading, const MeshAxes& axes) {
  if (reading == MeshReading::kChildProcess) {
    MeshReaderLocation found = FindMeshReader();
    reader_ = std::move(found.path);
    reader_missing_ = std::move(found.why_none);
  }
  if (reader_.empty()) {
    loader_ = [limits, axes](const std::string& path) {
      return LoadMeshInProcess(path, limits, axes);
    };
  } else {
    loader_ = [limits, axes, reader = reader_](const std::string& path) {
      return LoadMeshInChild(reader, path, limits, axes);
    };
  }
}

std::shared_ptr<MeshCache::Entry> MeshCache::EntryFor(const std::string& path) {
  std::lock_guard lock(mutex_);
  auto& entry = entries_[path];
  if (!entry) entry = std::make_shared<Entry>();
  return entry;
}

MeshOrError MeshCache::Get(const std::string& path) {
  std::shared_ptr<Entry> entry = EntryFor(path);
  // other threads asking for the same file wait here for the one reader
  std::call_once(entry->once, [&] {
    entry->result = loader_(path);
    ++files_read_;
  });
  return entry->result;
}

void MeshCache::Prefetch(const std::vector<std::string>& paths) {
  const std::set<std::string> unique(paths.begin(), paths.end());
  const std::vector<std::string> todo(unique.begin(), unique.end());
  const size_t threads =
      std::min<size_t>(todo.size(), std::max(1u, std::thread::hardware_concurrency()));
  if (threads <= 1) {
    for (const std::string& p : todo) Get(p);
    return;
  }
  std::atomic<size_t> next{0};
  auto work = [&] {
    for (size_t i = next++; i < todo.size(); i = next++) Get(todo[i]);
  };
  std::vector<std::thread> pool;
  for (size_t t = 0; t < threads; ++t) pool.emplace_back(work);
  for (std::thread& t : pool) t.join();
}

}  // namespace mdlc::mesh
