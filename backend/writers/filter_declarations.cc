// filter_declarations.cc - collision filter declarations, the world taken out.
#include "backend/writers/filter_declarations.h"

#include <algorithm>
#include <set>

namespace mdlc::writers {

namespace {

bool IsWorld(BodyId body) { return body.index() == 0; }

/// Reports each body's filter with the world once, however many
/// declarations pair the two.
class WorldFilters {
 public:
  explicit WorldFilters(const std::function<void(BodyId)>& on_world) : on_world_(on_world) {}

  /// `bodies` without the world; when `paired_with_world` holds the world,
  /// each of `bodies` (but the world) loses its filter with it.
  std::vector<BodyId> Without(const std::vector<BodyId>& bodies,
                              const std::vector<BodyId>& paired_with_world) {
    const bool world =
        std::any_of(paired_with_world.begin(), paired_with_world.end(), IsWorld);
    std::vector<BodyId> out;
    out.reserve(bodies.size());
    for (BodyId b : bodies) {
      if (IsWorld(b)) continue;
      if (world) Report(b);
      out.push_back(b);
    }
    return out;
  }

 private:
  void Report(BodyId body) {
    if (body.index() >= reported_.size()) reported_.resize(body.index() + 1, false);
    if (reported_[body.index()]) return;
    reported_[body.index()] = true;
    on_world_(body);
  }

  const std::function<void(BodyId)>& on_world_;
  std::vector<bool> reported_;
};

/// True when some body of `a` and a different body of `b` make a pair.
bool PairsAny(const std::vector<BodyId>& a, const std::vector<BodyId>& b) {
  if (a.empty() || b.empty()) return false;
  return a.size() > 1 || b.size() > 1 || a[0] != b[0];
}

}  // namespace

std::vector<FilterDeclaration> DeclarationsWithoutWorld(
    const backend::CollisionFilters& filters, const std::function<void(BodyId)>& on_world) {
  // each distinct set once (a group that ignores itself is often a welded
  // composite too), and which sets each body is in
  std::vector<std::vector<BodyId>> sets;
  std::set<std::vector<BodyId>> seen;
  std::vector<std::vector<uint32_t>> sets_of;
  for (const std::vector<BodyId>& set : filters.sets()) {
    std::vector<BodyId> sorted = set;
    std::sort(sorted.begin(), sorted.end());
    if (!seen.insert(sorted).second) continue;
    for (BodyId b : set) {
      if (b.index() >= sets_of.size()) sets_of.resize(b.index() + 1);
      sets_of[b.index()].push_back(static_cast<uint32_t>(sets.size()));
    }
    sets.push_back(set);
  }
  // a pair within a set (a weld inside its composite) adds nothing
  auto in_one_set = [&](BodyId a, BodyId b) {
    if (a.index() >= sets_of.size() || b.index() >= sets_of.size()) return false;
    const std::vector<uint32_t>&sa = sets_of[a.index()], &sb = sets_of[b.index()];
    return std::find_first_of(sa.begin(), sa.end(), sb.begin(), sb.end()) != sa.end();
  };

  WorldFilters world(on_world);
  std::vector<FilterDeclaration> out;
  auto add_set = [&](const std::vector<BodyId>& set) {
    std::vector<BodyId> members = world.Without(set, set);
    if (members.size() >= 2) out.push_back({std::move(members), {}});
  };
  for (const auto& [a, b] : filters.pairs()) {
    if (!in_one_set(a, b)) add_set({a, b});
  }
  for (const std::vector<BodyId>& set : sets) add_set(set);
  for (const auto& [side_a, side_b] : filters.set_pairs()) {
    std::vector<BodyId> members = world.Without(side_a, side_b);
    std::vector<BodyId> ignored = world.Without(side_b, side_a);
    if (PairsAny(members, ignored)) out.push_back({std::move(members), std::move(ignored)});
  }
  return out;
}

}  // namespace mdlc::writers
