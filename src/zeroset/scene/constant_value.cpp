// Constant checks for settings. Expr folds every operation on constants, so a
// value that depends on none of x, y, z is always a single Const node (a
// number Value keeps it as a double).
#include "zeroset/scene/constant_value.hpp"

#include <cmath>

#include "zeroset/scene/wording.hpp"

namespace zeroset {

double constant_number(const TokenStream& in, const Value& value, SourceLocation where, std::string_view what) {
    const std::string subject(what);
    if (value.is_vector()) in.fail(where, subject + " must be a number, but found a vector");
    if (!value.is_constant())
        in.fail(where, subject + " must be a constant number, but it depends on " + variables_of(value.number()));
    const double c = value.constant();
    if (!std::isfinite(c)) in.fail(where, subject + " must be finite, but it is " + format_number(c));
    return c;
}

Vec3d constant_vector(const TokenStream& in, const Value& value, SourceLocation where, std::string_view what) {
    const std::string subject(what);
    if (!value.is_vector()) in.fail(where, subject + " must be a vector (a, b, c), but found a number");
    const ExprVector& v = value.vector();
    Vec3d result;
    for (int i = 0; i < 3; ++i) {
        const Expr& e = v[static_cast<std::size_t>(i)];
        if (!e.is_constant())
            in.fail(where, subject + " must be a constant vector, but it depends on " + variables_of(v));
        if (!std::isfinite(e.value()))
            in.fail(where, subject + " must be finite, but component " + std::to_string(i + 1) + " is " +
                               format_number(e.value()));
        result[i] = e.value();
    }
    return result;
}

std::string format_vector(const Vec3d& v) {
    return "(" + format_number(v.x) + ", " + format_number(v.y) + ", " + format_number(v.z) + ")";
}

}  // namespace zeroset
