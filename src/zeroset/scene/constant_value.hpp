// Turning expression Values into the plain constants a scene's settings
// need — a number or a vector that does not depend on x, y or z and is
// finite — with messages that say what is wrong and where.
#pragma once

#include <string>
#include <string_view>

#include "zeroset/math/vec3.hpp"
#include "zeroset/scene/token_stream.hpp"
#include "zeroset/scene/value.hpp"

namespace zeroset {

/// `value` as a constant number; otherwise fails at `where` with "<what> must be …".
double constant_number(const TokenStream& in, const Value& value, SourceLocation where, std::string_view what);

/// `value` as a constant vector; otherwise fails at `where` with "<what> must be …".
Vec3d constant_vector(const TokenStream& in, const Value& value, SourceLocation where, std::string_view what);

/// "(1, 0.5, -2)".
std::string format_vector(const Vec3d& v);

}  // namespace zeroset
