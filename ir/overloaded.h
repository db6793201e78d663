// overloaded.h - one lambda per alternative for std::visit over the IR's
// payload variants (shapes, constraints, force elements).
#pragma once

namespace mdlc::ir {

template <typename... Fs>
struct Overloaded : Fs... {
  using Fs::operator()...;
};
template <typename... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

}  // namespace mdlc::ir
