// Shared by the roots tests: a wrapper that counts calls (to check the
// evaluation counts the routines report), a distance in ulps, and a set of
// functions with known roots (oracles from mpmath at 40 digits, or exact).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "zeroset/roots/root_function.hpp"

namespace zeroset::test {

/// Counts the calls made to f.
template <class F>
struct Counted {
    F f;
    int calls = 0;
    auto operator()(double t) {
        ++calls;
        return f(t);
    }
};
template <class F>
Counted<F> counted(F f) {
    return Counted<F>{f};
}

/// How many doubles apart a and b are (0 when equal; ±0 are equal).
inline std::int64_t ulps_between(double a, double b) {
    const auto ordered = [](double x) {
        const auto i = std::bit_cast<std::int64_t>(x);
        return i < 0 ? std::numeric_limits<std::int64_t>::min() - i : i;
    };
    const std::int64_t d = ordered(a) - ordered(b);
    return d < 0 ? -d : d;
}

/// A function with one sign change in [a, b], its derivative and its root.
struct KnownRoot {
    std::string name;
    double (*h)(double);
    double (*dh)(double);
    double a, b;
    double root;  // the root rounded to double
    bool simple = true;  // false: H′ vanishes at the root or H is nearly that flat
    [[nodiscard]] ValueAndDerivative both(double t) const { return {h(t), dh(t)}; }
};

inline std::vector<KnownRoot> known_roots() {
    return {
        {"sqrt2", [](double t) { return t * t - 2.0; }, [](double t) { return 2.0 * t; }, 0.0, 2.0,
         std::numbers::sqrt2},
        {"dottie", [](double t) { return std::cos(t) - t; }, [](double t) { return -std::sin(t) - 1.0; }, 0.0, 1.0,
         0.7390851332151606416553120876738734040134},
        {"wallis_cubic", [](double t) { return t * t * t - 2.0 * t - 5.0; },
         [](double t) { return 3.0 * t * t - 2.0; }, 2.0, 3.0, 2.094551481542326591482386540579302963857},
        {"exp_ln2", [](double t) { return std::exp(t) - 2.0; }, [](double t) { return std::exp(t); }, -1.0, 3.0,
         std::numbers::ln2},
        {"sin_pi", [](double t) { return std::sin(t); }, [](double t) { return std::cos(t); }, 3.0, 4.0,
         std::numbers::pi},
        {"log_one", [](double t) { return std::log(t); }, [](double t) { return 1.0 / t; }, 0.5, 10.0, 1.0},
        {"steep_tanh", [](double t) { return std::tanh(50.0 * (t - 0.7)); },
         [](double t) { return 50.0 / std::pow(std::cosh(50.0 * (t - 0.7)), 2.0); }, 0.0, 1.0, 0.7},
        {"tiny_values", [](double t) { return 1e-300 * (t - 0.3); }, [](double) { return 1e-300; }, 0.0, 1.0, 0.3},
        {"huge_values", [](double t) { return 1e300 * (0.3 - t); }, [](double) { return -1e300; }, 0.0, 1.0, 0.3},
        {"flat_ninth_power", [](double t) { return std::pow(t - 0.1, 9.0); },
         [](double t) { return 9.0 * std::pow(t - 0.1, 8.0); }, 0.0, 2.0, 0.1, false},
        {"triple_root", [](double t) { return (t - 0.1) * (t - 0.1) * (t - 0.1); },
         [](double t) { return 3.0 * (t - 0.1) * (t - 0.1); }, -1.0, 1.0, 0.1, false},
        {"signed_double_root", [](double t) { return (t - 0.1) * std::abs(t - 0.1); },
         [](double t) { return 2.0 * std::abs(t - 0.1); }, -1.0, 1.0, 0.1, false},
        {"near_double_root", [](double t) { return t * t - 1e-20; }, [](double t) { return 2.0 * t; }, 0.0, 1.0,
         9.99999999999999972576635727105e-11, false},
        {"convex_tenth_power", [](double t) { return std::pow(t, 10.0) - 0.5; },
         [](double t) { return 10.0 * std::pow(t, 9.0); }, 0.0, 1.5, 0.9330329915368074159813432661499421670272},
    };
}

/// Ascending coefficients of scale·Π(t − rᵢ).
inline std::vector<double> from_roots(const std::vector<double>& roots, double scale = 1.0) {
    std::vector<double> c{scale};
    for (const double r : roots) {
        std::vector<double> next(c.size() + 1, 0.0);
        for (std::size_t i = 0; i < c.size(); ++i) {
            next[i + 1] += c[i];
            next[i] -= r * c[i];
        }
        c = next;
    }
    return c;
}

}  // namespace zeroset::test
