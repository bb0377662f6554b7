// `auto` → sphere tracing: it is guaranteed for every function the evaluator
// can bound, needs no smoothness (min/max/abs are fine, survey §7), prunes
// CSG tapes per segment, and was the fastest guaranteed method on the ray
// suite and the shipped scenes (docs/methods.md).
#include "zeroset/trace/choose_method.hpp"

namespace zeroset {

Method resolve_method(Method requested, const Tape& /*tape*/) {
    return requested == Method::Auto ? Method::Sphere : requested;
}

}  // namespace zeroset
