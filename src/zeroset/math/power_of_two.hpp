// Exponents and scaling by powers of two without a library call. std::ilogb
// and std::ldexp are calls into libm (about 10 ns each); the sphere clip of
// bounds.hpp makes eleven per ray, 5 % of a sample quartic's trace. On normal
// numbers the exponent is read from the bits and a product with an exact
// power of two is the same scaling — rounded, where the result is subnormal,
// exactly as ldexp rounds it — so these give the library's results; anything
// else takes the library's path.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace zeroset {

/// std::ilogb(v): the exponent e with 2^e ≤ |v| < 2^(e+1).
inline int binary_exponent(double v) {
    const auto biased = static_cast<int>((std::bit_cast<std::uint64_t>(v) >> 52) & 0x7ffu);
    if (biased == 0 || biased == 0x7ff) return std::ilogb(v);  // zero, subnormal, ∞, NaN
    return biased - 1023;
}

/// std::ldexp(v, e) = v·2^e.
inline double times_power_of_two(double v, int e) {
    if (e < -1022 || e > 1023) return std::ldexp(v, e);  // 2^e itself is not a normal double
    return v * std::bit_cast<double>(static_cast<std::uint64_t>(e + 1023) << 52);
}

}  // namespace zeroset
