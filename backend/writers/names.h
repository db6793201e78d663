// names.h - how the URDF and MJCF writers name what they write. Each format
// holds one model, so several model instances become one, each name prefixed
// with its instance ("arm/link1"; a nested instance "arm::hand" gives
// "arm/hand/link1"), and "::", a scope separator to mdlc's and Drake's
// readers, becomes "/". The round-trip tests name the written entities with
// the same functions.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "backend/plant.h"
#include "ir/diagnostics.h"
#include "ir/module.h"

namespace mdlc::writers {

/// "a::b" -> "a/b".
std::string Unscoped(std::string name);
/// "outer::inner" + "link" -> "outer/inner/link".
std::string Prefixed(std::string_view instance, std::string_view name);

/// The names a one-model format gives a plant's entities.
class FlatNames {
 public:
  explicit FlatNames(const backend::Plant& plant);

  /// True when the plant's bodies are in more than one model instance.
  bool prefix_instances() const { return prefix_instances_; }
  /// The model's name: its one instance's, "world" without bodies, "scene"
  /// for several instances.
  const std::string& model_name() const { return model_name_; }
  /// The written name of entity `name` of instance `model` (the world and
  /// default instances are never prefixed).
  std::string Named(ModelId model, std::string_view name) const;
  /// The written name for a plant's scoped name "instance::name" (a
  /// bushing names its frames so).
  std::string NamedScoped(const std::string& scoped) const;
  /// With several instances, the -Wlossy warning that they become one
  /// `what` ("URDF robot"), at the first instance's source.
  void ReportFlattening(const ir::Module& module, std::string_view what,
                        DiagnosticEngine& diags) const;

  /// Round-trip metadata (ir/syntax/original_name_comment.h): the comment
  /// naming entity `name` of instance `model`, which mdlc's reader will read
  /// back as `read_back` in an instance named model_name(); nullopt when
  /// that is its scoped name already.
  std::optional<std::string> OriginalNameComment(ModelId model, std::string_view name,
                                                 std::string_view read_back) const;

 private:
  const backend::Plant& plant_;
  bool prefix_instances_ = false;
  size_t instance_count_ = 0;
  size_t first_instance_ = 0;
  std::string model_name_;
};

}  // namespace mdlc::writers
