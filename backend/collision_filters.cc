// collision_filters.cc - adjacency, weld composites and filter groups -> the
// declarations of CollisionFilters, and its queries.
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

/// Collects the declarations, keeping only bodies with proximity geometry.
class FilterBuilder {
 public:
  explicit FilterBuilder(std::vector<bool> has_proximity)
      : has_proximity_(std::move(has_proximity)) {}

  bool HasProximity(uint32_t b) const { return has_proximity_[b]; }
  void AddPair(uint32_t a, uint32_t b) {
    if (a != b && has_proximity_[a] && has_proximity_[b]) pairs_.emplace_back(BodyId(a), BodyId(b));
  }
  /// Every pair within `bodies` (none repeated).
  void AddSet(const std::vector<uint32_t>& bodies) {
    std::vector<BodyId> kept = Kept(bodies);
    if (kept.size() >= 2) sets_.push_back(std::move(kept));
  }
  /// Every body of `a` with every body of `b`.
  void AddSetPair(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b) {
    std::vector<BodyId> kept_a = Kept(a), kept_b = Kept(b);
    if (!kept_a.empty() && !kept_b.empty()) set_pairs_.emplace_back(std::move(kept_a), std::move(kept_b));
  }
  CollisionFilters Finish() {
    return CollisionFilters(std::move(pairs_), std::move(sets_), std::move(set_pairs_));
  }

 private:
  std::vector<BodyId> Kept(const std::vector<uint32_t>& bodies) const {
    std::vector<BodyId> out;
    for (uint32_t b : bodies) {
      if (has_proximity_[b]) out.emplace_back(b);
    }
    return out;
  }

  std::vector<bool> has_proximity_;
  CollisionFilters::BodyPairs pairs_;
  CollisionFilters::BodySets sets_;
  CollisionFilters::BodySetPairs set_pairs_;
};

void AddAdjacentPairs(const Plant& plant, FilterBuilder& filters) {
  for (const PlantJoint& joint : plant.joints) {
    if (plant.body(joint.parent).is_world) continue;
    if (joint.type == ir::JointType::QuaternionFloating) continue;
    filters.AddPair(joint.parent.value, joint.child.value);
  }
}

void AddWeldedSets(const Plant& plant, FilterBuilder& filters) {
  // without welds every body is a composite of its own, which makes no pair
  if (std::none_of(plant.joints.begin(), plant.joints.end(),
                   [](const PlantJoint& j) { return j.type == ir::JointType::Weld; })) {
    return;
  }
  const std::vector<uint32_t> composite_of = WeldedComposites(plant);
  // proximity bodies by composite (one list, not a list per body, as most
  // bodies are composites of their own), then one set per composite
  std::vector<BodyPair> by_composite;  // (composite, body)
  for (uint32_t b = 0; b < plant.bodies.size(); ++b) {
    if (filters.HasProximity(b)) by_composite.emplace_back(composite_of[b], b);
  }
  std::sort(by_composite.begin(), by_composite.end());
  std::vector<uint32_t> composite;
  for (size_t begin = 0, end = 0; begin < by_composite.size(); begin = end) {
    composite.clear();
    while (end < by_composite.size() && by_composite[end].first == by_composite[begin].first) {
      composite.push_back(by_composite[end++].second);
    }
    filters.AddSet(composite);
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

void AddGroupDeclarations(const ir::Module& module, FilterBuilder& filters) {
  const std::vector<std::vector<uint32_t>> bodies = GroupBodies(module);
  for (size_t g = 0; g < module.filter_groups.size(); ++g) {
    for (const auto& ignored : module.filter_groups[g].ignored_groups) {
      const size_t h = ignored.id.index();
      if (h == g) {
        filters.AddSet(bodies[g]);
      } else {
        filters.AddSetPair(bodies[g], bodies[h]);
      }
    }
  }
}

}  // namespace

std::optional<CollisionFilters> ComputeCollisionFilters(
    const ir::Module& module, const Plant& plant, const std::vector<SceneGeometry>& geometries,
    DiagnosticEngine& diags) {
  if (!CheckGroups(module, diags)) return std::nullopt;

  std::vector<bool> has_proximity(plant.bodies.size(), false);
  for (const SceneGeometry& g : geometries) {
    if (g.roles & ir::kProximityRole) has_proximity[g.body.index()] = true;
  }
  FilterBuilder filters(std::move(has_proximity));
  AddAdjacentPairs(plant, filters);
  AddWeldedSets(plant, filters);
  AddGroupDeclarations(module, filters);
  return filters.Finish();
}

std::vector<uint32_t> WeldedComposites(const Plant& plant) {
  DisjointSets sets(plant.bodies.size());
  for (const PlantJoint& joint : plant.joints) {
    if (joint.type == ir::JointType::Weld) sets.Union(joint.parent.value, joint.child.value);
  }
  std::vector<uint32_t> composite(plant.bodies.size());
  for (uint32_t b = 0; b < composite.size(); ++b) composite[b] = sets.Find(b);
  return composite;
}

// ------------------------------------------------------ CollisionFilters

CollisionFilters::CollisionFilters(BodyPairs pairs, BodySets sets, BodySetPairs set_pairs)
    : pairs_(std::move(pairs)), sets_(std::move(sets)), set_pairs_(std::move(set_pairs)) {
  for (auto& [a, b] : pairs_) {
    if (b < a) std::swap(a, b);
  }
  std::sort(pairs_.begin(), pairs_.end());
  pairs_.erase(std::unique(pairs_.begin(), pairs_.end()), pairs_.end());
  for (size_t s = 0; s < sets_.size(); ++s) {
    for (BodyId b : sets_[s]) tags_.emplace_back(b.value, Tag(s, 0));
  }
  for (size_t p = 0; p < set_pairs_.size(); ++p) {
    for (BodyId a : set_pairs_[p].first) tags_.emplace_back(a.value, Tag(p, 1));
    for (BodyId b : set_pairs_[p].second) tags_.emplace_back(b.value, Tag(p, 2));
  }
  std::sort(tags_.begin(), tags_.end());
  tags_.erase(std::unique(tags_.begin(), tags_.end()), tags_.end());
}

bool CollisionFilters::HasTag(BodyId body, uint64_t tag) const {
  return std::binary_search(tags_.begin(), tags_.end(), std::pair{body.value, tag});
}

bool CollisionFilters::Filtered(BodyId a, BodyId b) const {
  if (a == b) return false;
  if (std::binary_search(pairs_.begin(), pairs_.end(), std::pair{std::min(a, b), std::max(a, b)})) {
    return true;
  }
  // each declaration `a` is part of, and the part `b` would need in it
  auto it = std::lower_bound(tags_.begin(), tags_.end(), std::pair{a.value, uint64_t{0}});
  for (; it != tags_.end() && it->first == a.value; ++it) {
    const uint64_t tag = it->second;
    const uint64_t kind = tag % 3;
    const uint64_t wanted = kind == 0 ? tag : kind == 1 ? tag + 1 : tag - 1;
    if (HasTag(b, wanted)) return true;
  }
  return false;
}

CollisionFilters::BodyPairs CollisionFilters::Pairs(const Plant& plant) const {
  std::vector<BodyPair> pairs;
  for (const auto& [a, b] : pairs_) pairs.emplace_back(a.value, b.value);
  for (const std::vector<BodyId>& set : sets_) {
    for (size_t i = 0; i < set.size(); ++i) {
      for (size_t k = i + 1; k < set.size(); ++k) pairs.emplace_back(set[i].value, set[k].value);
    }
  }
  for (const auto& [side_a, side_b] : set_pairs_) {
    for (BodyId a : side_a) {
      for (BodyId b : side_b) {
        if (a != b) pairs.emplace_back(a.value, b.value);
      }
    }
  }
  // a scene of free bodies filters nothing: no names to build and sort
  if (pairs.empty()) return {};
  // rank of each body in a pair by scoped name, so the sort compares
  // integers; names are built for those bodies only, as the plant keeps
  // them unscoped (issue 16). Ranks among these bodies order the pairs as
  // ranks among all bodies would.
  std::vector<bool> in_pair(plant.bodies.size(), false);
  for (const BodyPair& p : pairs) in_pair[p.first] = in_pair[p.second] = true;
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

  for (BodyPair& p : pairs) {
    p = {std::min(rank[p.first], rank[p.second]), std::max(rank[p.first], rank[p.second])};
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());

  std::vector<std::pair<BodyId, BodyId>> out;
  out.reserve(pairs.size());
  for (const BodyPair& p : pairs) out.emplace_back(BodyId(by_name[p.first]), BodyId(by_name[p.second]));
  return out;
}

}  // namespace mdlc::backend
