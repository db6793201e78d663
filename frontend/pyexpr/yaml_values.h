// yaml_values.h - YAML text as pyexpr values, the way xacro.load_yaml reads it.
#pragma once

#include <string_view>

#include "frontend/pyexpr/evaluate.h"
#include "frontend/pyexpr/value.h"

namespace mdlc::pyexpr {

// PyYAML's yaml.safe_load: YAML 1.1 implicit types (bool words yes/no/on/off/
// true/false in PyYAML's spellings, ints with 0x/0b/leading-zero octal/
// underscores/sexagesimal, floats only as PyYAML's regex has them: '1e-3' is
// a str, '1.0e-3' a float), null/~/empty, timestamps as str. Quoted scalars
// are str. Maps and lists become dict and list values with attribute access
// (xacro wraps them). xacro's unit tags evaluate their scalar as a Python
// expression over StandardGlobals() and convert it with float(): !radians and
// !meters as is, !degrees through math.radians, !millimeters x0.001, !foot
// x0.3048, !inches x0.0254. Also !!str/!!int/!!float/!!bool/!!null and merge
// keys (<<). Errors name the line and column (1-based) in the text; the
// limits bound nesting (alias expansion counts) and the number of values.
Result<Value> LoadYaml(std::string_view text);
Result<Value> LoadYaml(std::string_view text, const Limits& limits);

}  // namespace mdlc::pyexpr
