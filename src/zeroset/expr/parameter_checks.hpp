// The checks of a shape's or a blend's constant parameters, with the
// messages the scene reader shows at the call ("the radius must be
// positive, but it is -1").
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

#include "zeroset/math/vec3.hpp"

namespace zeroset::parameter_checks {

/// v in the shortest form that reads back to it.
inline std::string shown(double v) {
    std::array<char, 32> buffer{};
    const auto end = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v).ptr;
    return {buffer.data(), end};
}

/// Throws std::invalid_argument unless 0 < v < ∞.
inline void require_positive(double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v))
        throw std::invalid_argument(std::string(name) + " must be positive, but it is " + shown(v));
}

/// Throws std::invalid_argument unless every component is in (0, ∞).
inline void require_positive(const Vec3d& v, const char* name) {
    for (int i = 0; i < 3; ++i)
        if (!(v[i] > 0.0) || !std::isfinite(v[i]))
            throw std::invalid_argument(std::string(name) + " must be positive in every component, but component " +
                                        std::to_string(i + 1) + " is " + shown(v[i]));
}

}  // namespace zeroset::parameter_checks
