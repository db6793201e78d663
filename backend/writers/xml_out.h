// xml_out.h - indented XML output for the writers (at most 32 levels of
// indentation, so deep nesting stays linear in size), on libxml2's text writer
// (which escapes attribute values and text). Numbers are written in their
// shortest form that reads back to the same double, so a written model
// compiles to the same values bit for bit.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <string_view>

namespace mdlc::writers {

/// "1.5", "-0", "inf": the shortest text that reads back as `value`.
std::string NumberText(double value);
/// Space-separated NumberText of each coefficient.
std::string VectorText(const Eigen::Ref<const Eigen::VectorXd>& values);

class XmlOut {
 public:
  XmlOut();
  ~XmlOut();
  XmlOut(const XmlOut&) = delete;
  XmlOut& operator=(const XmlOut&) = delete;

  XmlOut& Open(std::string_view tag);
  XmlOut& Attr(std::string_view name, std::string_view value);
  XmlOut& Attr(std::string_view name, double value) { return Attr(name, NumberText(value)); }
  XmlOut& Attr(std::string_view name, const Eigen::Vector3d& value) {
    return Attr(name, VectorText(value));
  }
  XmlOut& Text(std::string_view text);
  XmlOut& Close();
  /// A comment on a line of its own (round-trip metadata, lossy notes).
  XmlOut& Comment(std::string_view text);
  /// Closes what is open and returns the document.
  std::string Finish();

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace mdlc::writers
