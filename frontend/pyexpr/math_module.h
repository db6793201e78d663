// math_module.h - Python 3.11's math module for pyexpr.
#pragma once

#include "frontend/pyexpr/value.h"

namespace mdlc::pyexpr {

// Adds every public name of Python 3.11's math module (pi e tau inf nan
// and the functions) to the table. Domain errors are kValue, results out of
// the float range kOverflow, as Python raises them.
void AddMathModule(NameTable& table);

}  // namespace mdlc::pyexpr
