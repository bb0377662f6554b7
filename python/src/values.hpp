// Python objects as scene-language values and back: a number or an Expr is
// a number, a sequence of three of them a vector (returned as a tuple).
#pragma once

#include <string>

#include "bindings.hpp"
#include "zeroset/scene/value.hpp"

namespace zeroset::python {

/// Throws TypeError naming `what` for anything else.
Value to_value(py::handle item, const std::string& what);
py::object from_value(const Value& value);

}  // namespace zeroset::python
