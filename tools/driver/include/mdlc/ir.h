// mdlc/ir.h - the compiler's intermediate representation behind a Result:
// opt-in, for tools that print or walk the IR (the mdlc command line, tests).
//
// The IR module is the compiler's internal data, whose shape changes with
// the compiler; the plant (Result::plant()) is the stable product. So
// mdlc/mdlc.h neither includes nor names it, and the way to it is this free
// function, which only a program that includes this header can call: a
// member of Result returning a forward-declared ir::Module would be callable
// everywhere and usable nowhere, and would tie mdlc.h to the IR's names.
#pragma once

#include "ir/module.h"
#include "mdlc/mdlc.h"

namespace mdlc {

/// The IR after the passes (as far as they got when !result.ok()); it lives
/// as long as the Result.
const ir::Module& IrModule(const Result& result);

}  // namespace mdlc
