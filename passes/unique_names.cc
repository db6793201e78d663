// unique_names.cc - the unique-names pass: every name the compiler made is
// unique where Drake requires names to be unique.
//
// Frontends and passes name what the file leaves unnamed or what they insert
// (MJCF's `body<N>`, the bodies between stacked joints `NAME<k>`, `geom<i>`,
// `camera<i>`, `motor<N>`, welds `P_welds_to_C`, floating joints named after
// their body) the way Drake's parsers do. Such a name can already belong to
// an entity the file named: a body `vertebra_C1` with two joints makes
// `vertebra_C10`, which the file may also have. Drake would fail on the
// duplicate; mdlc keeps the file's name and gives the made one the first free
// `NAME_<n>` (n = 1, 2, ...), with a note at the entity.
//
// Names made from a body's made name follow it when it is renamed, so that
// they still name it: the bodies between its stacked joints (`body110` renamed
// `body110_1` has `body110_10`, `body110_11`, not `body1100`, the name of
// another unnamed body's intermediates), a joint named `<parent>-<child>`
// and the floating joint named after it. (Welds `P_welds_to_C` keep the name
// they were made with.)
//
// Scopes, as Drake's: bodies, frames, joints, actuators and cameras are
// unique within their model instance; a geometry within its body and role.
// Names the file gives are never changed here (duplicates among them are the
// frontends' errors). Runs after the last pass that adds entities
// (build-kinematic-tree); afterwards the verifier's Named level holds.
#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include <absl/container/flat_hash_set.h>

#include "passes/pass_registry.h"

namespace mdlc::passes {
namespace {

// one name in one scope (a model instance, or a body and role)
struct ScopedSymbol {
  uint64_t scope;
  uint32_t symbol;
  bool operator==(const ScopedSymbol&) const = default;
  template <typename H>
  friend H AbslHashValue(H h, const ScopedSymbol& s) {
    return H::combine(std::move(h), s.scope, s.symbol);
  }
};
using TakenNames = absl::flat_hash_set<ScopedSymbol>;

// The scopes an entity's name must be unique in: its model instance; for a
// geometry, its body once per role it has.
template <typename Entity>
ir::NameScopeList ScopesOf(const Entity& e) {
  return {{e.model.value}, 1};
}
template <>
ir::NameScopeList ScopesOf(const ir::Geometry& g) {
  return ir::NameScopes(g);
}

class UniqueNamesPass : public Pass {
 public:
  std::string_view name() const override { return "unique-names"; }
  std::string_view description() const override {
    return "Give every compiler-made name that is taken the next free name";
  }
  ir::VerifyLevel level_after() const override { return ir::VerifyLevel::Named; }
  bool Run(PassContext& ctx) override {
    ir::Module& m = ctx.module;
    const std::vector<Symbol> body_names_before = BodyNames(m);
    Uniquify(ctx, m.bodies, "body");
    FollowRenamedBodies(m, body_names_before);
    FollowRenamedJointEnds(m, body_names_before);
    Uniquify(ctx, m.frames, "frame");
    Uniquify(ctx, m.joints, "joint");
    Uniquify(ctx, m.actuators, "actuator");
    Uniquify(ctx, m.cameras, "camera");
    Uniquify(ctx, m.geometries, "geometry");
    return true;
  }

 private:
  static std::vector<Symbol> BodyNames(const ir::Module& m) {
    std::vector<Symbol> names;
    names.reserve(m.bodies.size());
    for (const ir::Body& b : m.bodies) names.push_back(b.name);
    return names;
  }
  // A floating joint the compiler added is named after its body (Drake's
  // rule): when the body was renamed, so is the joint
  static void FollowRenamedBodies(ir::Module& m, const std::vector<Symbol>& before) {
    for (ir::Joint& j : m.joints) {
      if (!j.unnamed || j.type != ir::JointType::QuaternionFloating || !j.child.resolved()) continue;
      const size_t child = j.child.id.index();
      if (m.bodies[child].name != before[child] && j.name == before[child]) {
        j.name = m.bodies[child].name;
      }
    }
  }

  // A joint the compiler named `<parent>-<child>` (MJCF-022) is named after
  // its bodies' new names when either was renamed
  static void FollowRenamedJointEnds(ir::Module& m, const std::vector<Symbol>& before) {
    for (ir::Joint& j : m.joints) {
      if (!j.unnamed || !j.parent.resolved() || !j.child.resolved()) continue;
      const size_t parent = j.parent.id.index(), child = j.child.id.index();
      if (m.bodies[parent].name == before[parent] && m.bodies[child].name == before[child]) {
        continue;
      }
      if (m.Text(j.name) == fmt::format("{}-{}", m.Text(before[parent]), m.Text(before[child]))) {
        j.name = m.Intern(fmt::format("{}-{}", m.Text(m.bodies[parent].name),
                                      m.Text(m.bodies[child].name)));
      }
    }
  }

  // The bodies between a body's stacked joints, `<body><k>` (MJCF-023), come
  // right after it in the table: while `owner` is a body renamed from `made`
  // to `renamed`, the next ones of those names are named after `renamed`
  struct RenamedOwner {
    size_t next;  // the table index the next intermediate body would have
    int k;
    std::string made, renamed;
  };
  static bool FollowOwner(ir::Module& m, std::optional<RenamedOwner>& owner, size_t index,
                          ir::Body& body) {
    if (owner && owner->next == index &&
        m.Text(body.name) == fmt::format("{}{}", owner->made, owner->k)) {
      body.name = m.Intern(fmt::format("{}{}", owner->renamed, owner->k));
      ++owner->next;
      ++owner->k;
      return true;
    }
    owner.reset();
    return false;
  }

  template <typename Entity>
  void Uniquify(PassContext& ctx, std::vector<Entity>& table, std::string_view what) {
    // only names mdlc made can change: a table without any needs no set
    // (in most models every body, frame and geometry is named in the file)
    if (std::none_of(table.begin(), table.end(), [](const Entity& e) { return e.unnamed; })) {
      return;
    }
    ir::Module& m = ctx.module;
    TakenNames taken;
    auto is_free = [&](const Entity& e, Symbol name) {
      for (uint64_t scope : ScopesOf(e)) {
        if (taken.count({scope, name.value})) return false;
      }
      return true;
    };
    auto take = [&](const Entity& e) {
      for (uint64_t scope : ScopesOf(e)) taken.insert({scope, e.name.value});
    };
    // the file's names first, whatever their order: they never change
    for (const Entity& e : table) {
      if (!e.unnamed) take(e);
    }
    // one MJCF <geom> is registered twice (visual and collision), in a row:
    // its rename is noted once
    std::optional<std::pair<Loc, Symbol>> last_note;
    std::optional<RenamedOwner> owner;  // bodies only
    for (size_t i = 0; i < table.size(); ++i) {
      Entity& e = table[i];
      if (!e.unnamed) continue;
      bool follows = false;
      if constexpr (std::is_same_v<Entity, ir::Body>) follows = FollowOwner(m, owner, i, e);
      if (!is_free(e, e.name)) {
        const std::string made(m.Text(e.name));
        Symbol renamed;
        for (int n = 1;; ++n) {
          renamed = m.Intern(fmt::format("{}_{}", made, n));
          if (is_free(e, renamed)) break;
        }
        if (last_note != std::pair{e.loc, renamed}) {
          ctx.diags.Report(DiagKind::SynthesizedNameTaken, e.loc,
                           fmt::format("the {} name '{}' that mdlc made is already used in "
                                       "model instance '{}'; this {} is named '{}'",
                                       what, made, m.ModelName(e.model), what,
                                       m.Text(renamed)));
          last_note = std::pair{e.loc, renamed};
        }
        if constexpr (std::is_same_v<Entity, ir::Body>) {
          if (!follows) owner = RenamedOwner{i + 1, 0, made, std::string(m.Text(renamed))};
        }
        e.name = renamed;
      }
      take(e);
    }
  }
};

}  // namespace

std::unique_ptr<Pass> CreateUniqueNamesPass() { return std::make_unique<UniqueNamesPass>(); }

}  // namespace mdlc::passes
