// unique_names.h - one namespace of a written file (a model's links and
// joints, an MJCF model's geoms), where a name already taken gets the first
// free numeric suffix: "a", "a_1", "a_2", ...
#pragma once

#include <string>
#include <unordered_map>
#include <unordered_set>

namespace mdlc::writers {

/// The names taken in one namespace. Names are never released, so every
/// suffix below where a base's last search ended is still taken: each base
/// remembers that point, and N clashes of one name cost N lookups, where
/// counting from 1 each time cost N^2 / 2 (10,000 links' collisions all
/// named "collision", written as MJCF geoms, took 15 s).
class UniqueNames {
 public:
  /// Takes `name`; false if it was taken already.
  bool Take(const std::string& name) { return taken_.insert(name).second; }
  bool contains(const std::string& name) const { return taken_.count(name) != 0; }
  /// Takes and returns the first free of "base_1", "base_2", ...
  std::string TakeSuffixed(const std::string& base);
  /// Takes and returns `name` if it is free, else TakeSuffixed(name).
  std::string TakeUnique(const std::string& name) {
    return Take(name) ? name : TakeSuffixed(name);
  }

 private:
  std::unordered_set<std::string> taken_;
  std::unordered_map<std::string, int> next_suffix_;  // by base
};

}  // namespace mdlc::writers
