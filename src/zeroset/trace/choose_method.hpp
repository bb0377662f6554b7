// The rule behind `method auto`: the fastest method that is guaranteed
// correct for the object (see docs/methods.md for the measurements behind it).
#pragma once

#include "zeroset/expr/tape.hpp"
#include "zeroset/trace/method.hpp"

namespace zeroset {

/// The method `auto` stands for on this tape; any other method is returned as is.
Method resolve_method(Method requested, const Tape& tape);

}  // namespace zeroset
