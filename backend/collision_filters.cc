// collision_filters.cc - adjacency, weld composites and filter groups -> pairs.
#include "backend/collision_filters.h"

#include <algorithm>
#include <numeric>
#include <optional>

#include "backend/ref_check.h"

namespace mdlc::backend {

namespace {

using BodyPair = std::pair<uint32_t, uint32_t>;

/// Union-find over body indices, for weld composites.
class DisjointSets {
 public:
  explicit DisjointSets(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  uint32_t Find(uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void Union(uint32_t a, uint32_t b) {
    a = Find(a);
    b = Find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<uint32_t> parent_;
};

/// Collects candidate pairs; keeps only pairs of distinct proximity bodies.
class PairCollector {
 public:
  explicit PairCollector(std::vector<bool> has_proximity)
      : has_proximity_(std::move(has_proximity)) {}

  void Add(uint32_t a, uint32_t b) {
    if (a != b && has_proximity_[a] && has_proximity_[b]) pairs_.emplace_back(a, b);
  }
  bool HasProximity(uint32_t b) const { return has_proximity_[b]; }

  /// Orders each pair and the list by scoped body name; drops duplicates.
  std::vector<std::pair<BodyId, BodyId>> Finish(const Plant& plant) {
    // a scene of free bodies filters nothing: no names to build and sort
    if (pairs_.empty()) return {};
    // rank of each body in a pair by scoped name, so the sort compares
    // integers; names are built for those bodies only, as the plant keeps
    // them unscoped (issue 16). Ranks among these bodies order the pairs as
    // ranks among all bodies would.
    std::vector<bool> in_pair(plant.bodies.size(), false);
    for (const BodyPair& p : pairs_) in_pair[p.first] = in_pair[p.second] = true;
    std::vector<uint32_t> by_name;
    std::vector<std::string> names(plant.bodies.size());
    for (uint32_t b = 0; b < plant.bodies.size(); ++b) {
      if (!in_pair[b]) continue;
      by_name.push_back(b);
      names[b] = plant.ScopedName(plant.bodies[b]);
    }
    std::stable_sort(by_name.begin(), by_name.end(),
                     [&](uint32_t a, uint32_t b) { return names[a] < names[b]; });
    std::vector<uint32_t> rank(plant.bodies.size());
    for (uint32_t r = 0; r < by_name.size(); ++r) rank[by_name[r]] = r;

    for (BodyPair& p : pairs_) {
      p = {std::min(rank[p.first], rank[p.second]), std::max(rank[p.first], rank[p.second])};
    }
    std::sort(pairs_.begin(), pairs_.end());
    pairs_.erase(std::unique(pairs_.begin(), pairs_.end()), pairs_.end());

    std::vector<std::pair<BodyId, BodyId>> out;
    out.reserve(pairs_.size());
    for (const BodyPair& p : pairs_) {
      out.emplace_back(BodyId(by_name[p.first]), BodyId(by_name[p.second]));
    }
    return out;
  }

 private:
  std::vector<bool> has_proximity_;
  std::vector<BodyPair> pairs_;
};

void AddAdjacentPairs(const Plant& plant, PairCollector& pairs) {
  for (const PlantJoint& joint : plant.joints) {
    if (plant.body(joint.parent).is_world) continue;
    if (joint.type == ir::JointType::QuaternionFloating) continue;
    pairs.Add(joint.parent.value, joint.child.value);
  }
}

void AddWeldedPairs(const Plant& plant, PairCollector& pairs) {
  // the sets are made at the first weld: without welds every body is a
  // composite of its own, which makes no pair
  std::optional<DisjointSets> sets;
  for (const PlantJoint& joint : plant.joints) {
    if (joint.type != ir::JointType::Weld) continue;
    if (!sets) sets.emplace(plant.bodies.size());
    sets->Union(joint.parent.value, joint.child.value);
  }
  if (!sets) return;
  // proximity bodies by composite (one list, not a list per body, as most
  // bodies are composites of their own), then every pair within each
  std::vector<BodyPair> by_composite;  // (composite, body)
  for (uint32_t b = 0; b < plant.bodies.size(); ++b) {
    if (pairs.HasProximity(b)) by_composite.emplace_back(sets->Find(b), b);
  }
  std::sort(by_composite.begin(), by_composite.end());
  for (size_t begin = 0, end = 0; begin < by_composite.size(); begin = end) {
    while (end < by_composite.size() && by_composite[end].first == by_composite[begin].first) {
      ++end;
    }
    for (size_t i = begin; i < end; ++i) {
      for (size_t k = i + 1; k < end; ++k) pairs.Add(by_composite[i].second, by_composite[k].second);
    }
  }
}

/// Checks every reference of the filter groups; false after reporting.
bool CheckGroups(const ir::Module& module, DiagnosticEngine& diags) {
  bool ok = true;
  const size_t num_groups = module.filter_groups.size();
  for (const ir::CollisionFilterGroup& group : module.filter_groups) {
    for (const auto& ref : group.members) {
      ok &= CheckRef(module, ref, module.bodies.size(), "body", group.loc, diags);
    }
    for (const auto& ref : group.member_groups) {
      ok &= CheckRef(module, ref, num_groups, "collision filter group", group.loc, diags);
    }
    for (const auto& ref : group.ignored_groups) {
      ok &= CheckRef(module, ref, num_groups, "collision filter group", group.loc, diags);
    }
  }
  return ok;
}

/// Every group's bodies, member groups included transitively (iterative DFS).
std::vector<std::vector<uint32_t>> GroupBodies(const ir::Module& module) {
  const size_t num_groups = module.filter_groups.size();
  std::vector<std::vector<uint32_t>> bodies(num_groups);
  std::vector<size_t> group_seen(num_groups, SIZE_MAX), body_seen(module.bodies.size(), SIZE_MAX);
  std::vector<size_t> stack;
  for (size_t g = 0; g < num_groups; ++g) {
    stack.assign(1, g);
    group_seen[g] = g;
    while (!stack.empty()) {
      const ir::CollisionFilterGroup& group = module.filter_groups[stack.back()];
      stack.pop_back();
      for (const auto& ref : group.members) {
        if (body_seen[ref.id.index()] == g) continue;
        body_seen[ref.id.index()] = g;
        bodies[g].push_back(ref.id.value);
      }
      for (const auto& ref : group.member_groups) {
        if (group_seen[ref.id.index()] == g) continue;
        group_seen[ref.id.index()] = g;
        stack.push_back(ref.id.index());
      }
    }
  }
  return bodies;
}

void AddGroupPairs(const ir::Module& module, PairCollector& pairs) {
  const std::vector<std::vector<uint32_t>> bodies = GroupBodies(module);
  for (size_t g = 0; g < module.filter_groups.size(); ++g) {
    for (const auto& ignored : module.filter_groups[g].ignored_groups) {
      for (uint32_t a : bodies[g]) {
        for (uint32_t b : bodies[ignored.id.index()]) pairs.Add(a, b);
      }
    }
  }
}

}  // namespace

std::optional<std::vector<std::pair<BodyId, BodyId>>> ComputeCollisionFilters(
    const ir::Module& module, const Plant& plant, const std::vector<SceneGeometry>& geometries,
    DiagnosticEngine& diags) {
  if (!CheckGroups(module, diags)) return std::nullopt;

  std::vector<bool> has_proximity(plant.bodies.size(), false);
  for (const SceneGeometry& g : geometries) {
    if (g.roles & ir::kProximityRole) has_proximity[g.body.index()] = true;
  }
  PairCollector pairs(std::move(has_proximity));
  AddAdjacentPairs(plant, pairs);
  AddWeldedPairs(plant, pairs);
  AddGroupPairs(module, pairs);
  return pairs.Finish(plant);
}

}  // namespace mdlc::backend
