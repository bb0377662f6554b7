// The polynomial solvers of §3.4 (Sturm, Descartes/Bernstein, Laguerre) and
// Yuksel's derivative-splitting solver, on the same polynomials with known
// roots: random ones built from their roots, the survey's quadratic (eq. 11
// with the digits of Figure 2's example), clusters, double roots, roots at
// the ends of the range, no roots, and a Wilkinson-like degree 16.
#include <gtest/gtest.h>

#include "root_test_support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "zeroset/roots/descartes.hpp"
#include "zeroset/roots/fast_polynomial.hpp"
#include "zeroset/roots/laguerre.hpp"
#include "zeroset/roots/polynomial_roots.hpp"
#include "zeroset/roots/sturm.hpp"

namespace zeroset {
namespace {

using Solve = PolynomialRoots (*)(std::span<const double>, double, double, std::span<double>);

struct Solver {
    std::string name;
    Solve solve;
    bool guaranteed;
};

std::vector<Solver> solvers() {
    return {{"sturm", sturm_roots, true},
            {"descartes", descartes_roots, true},
            {"fast", fast_polynomial_roots, true},
            {"laguerre", laguerre_roots, false}};
}

using test::from_roots;

std::vector<double> solve(const Solver& s, const std::vector<double>& c, double t0, double t1) {
    std::array<double, max_polynomial_degree> out{};
    const PolynomialRoots r = s.solve(c, t0, t1, out);
    EXPECT_GT(r.evaluations, 0);
    return {out.begin(), out.begin() + r.count};
}

double relative(double a, double b) { return std::abs(a - b) / std::max(1.0, std::abs(b)); }

/// Every expected root is matched, in order, within tolerance (relative).
void expect_roots(const std::vector<double>& got, std::vector<double> expected, double tolerance) {
    std::sort(expected.begin(), expected.end());
    ASSERT_EQ(got.size(), expected.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        EXPECT_LE(relative(got[i], expected[i]), tolerance) << "root " << i << ": " << got[i] << " vs " << expected[i];
    }
}

TEST(PolynomialSolvers, RandomWellSeparatedRoots) {
    std::mt19937_64 rng(20240611);
    std::uniform_real_distribution<double> root(-2.0, 2.0);
    for (const Solver& s : solvers()) {
        SCOPED_TRACE(s.name);
        for (int degree = 2; degree <= 10; ++degree) {
            for (int trial = 0; trial < 20; ++trial) {
                std::vector<double> roots;
                while (static_cast<int>(roots.size()) < degree) {
                    const double r = root(rng);
                    // Keep roots 0.05 apart so that each is well conditioned.
                    if (std::all_of(roots.begin(), roots.end(), [r](double q) { return std::abs(q - r) > 0.05; })) {
                        roots.push_back(r);
                    }
                }
                std::vector<double> inside;
                for (const double r : roots) {
                    if (r >= -1.0 && r <= 1.5) inside.push_back(r);
                }
                SCOPED_TRACE(degree);
                expect_roots(solve(s, from_roots(roots, 0.5 + trial), -1.0, 1.5), inside,
                             s.guaranteed ? 1e-10 : 1e-8);
            }
        }
    }
}

TEST(PolynomialSolvers, SurveyQuadratic) {
    const std::vector<double> c{36.852421, -12.1476884, 1.00024084};
    for (const Solver& s : solvers()) {
        SCOPED_TRACE(s.name);
        expect_roots(solve(s, c, 0.0, 10.0), {5.898392516686843, 6.246370938482615}, 1e-13);
        const FirstPolynomialRoot first = first_root_with(s.solve, c, 0.0, 10.0);
        EXPECT_TRUE(first.found);
        EXPECT_LE(relative(first.t, 5.898392516686843), 1e-13);
    }
}

TEST(PolynomialSolvers, ClusteredRootsAreBothFound) {
    // Roots 1e-6 apart: each is determined to about 1e-10 by the coefficients.
    const std::vector<double> roots{0.3, 0.3 + 1e-6, 0.7};
    for (const Solver& s : solvers()) {
        SCOPED_TRACE(s.name);
        if (s.guaranteed) expect_roots(solve(s, from_roots(roots), 0.0, 1.0), roots, 1e-9);
    }
}

TEST(PolynomialSolvers, DoubleRootsAreReported) {
    const std::vector<std::vector<double>> cases{{0.4, 0.4}, {0.25, 0.6, 0.6}, {-0.5, 0.3, 0.3, 0.9, 1.2}};
    for (const Solver& s : solvers()) {
        SCOPED_TRACE(s.name);
        for (const auto& roots : cases) {
            const std::vector<double> got = solve(s, from_roots(roots), -1.0, 1.0);
            // Each distinct root in range is within 1e-7 of a reported one.
            for (const double r : roots) {
                if (r > 1.0) continue;
                const bool found = std::any_of(got.begin(), got.end(), [r](double t) { return relative(t, r) <= 1e-7; });
                EXPECT_TRUE(found) << r;
            }
            for (const double t : got) {
                const bool known = std::any_of(roots.begin(), roots.end(), [t](double r) { return relative(t, r) <= 1e-7; });
                EXPECT_TRUE(known) << t;
            }
        }
    }
}

// Leading coefficients at rounding level — what cancellation leaves of
// terms that are 0 in exact arithmetic, as in a swept sphere's P (its
// degree 10 is 6 for a curve on one axis). Dividing by such a coefficient
// turned a Sturm sequence into noise and lost the root.
TEST(PolynomialSolvers, LeadingCoefficientsAtRoundingLevelDoNotHideARoot) {
    // P for the cubic with control x = (0, 2, −1, 1), radius 0.1 → 0.4, and
    // the ray o = (−2.7581…, −0.2937…, 0.1228…), d = (2.0320…, 0, 0).
    const std::vector<double> swept{54.322731117938019,     -578.66267123156649,    2204.1311703792744,
                                    -3428.8569898327114,    1268.5137291590218,     1783.6590630281717,
                                    -1337.7442972715944,    -7.4505805969238281e-09, -1.862645149230957e-09,
                                    9.3132257461547852e-10, -2.3283064365386963e-10};
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (const Solver& s : solvers()) {
        if (!s.guaranteed) continue;
        SCOPED_TRACE(s.name);
        expect_roots(solve(s, swept, 0.0, 1.0), {0.78554751558}, 1e-9);
        for (int trial = 0; trial < 200; ++trial) {
            const std::vector<double> roots{0.1 + 0.2 * u(rng), 0.4 + 0.2 * u(rng), 0.7 + 0.2 * u(rng)};
            std::vector<double> c = from_roots(roots);
            double largest = 0.0;
            for (const double k : c) largest = std::max(largest, std::abs(k));
            for (int extra = 0; extra < 4; ++extra) c.push_back((u(rng) - 0.5) * 1e-12 * largest);
            SCOPED_TRACE(trial);
            expect_roots(solve(s, c, 0.0, 1.0), roots, 1e-9);
        }
    }
}

// What counts as negligible depends on the range, within bounds: a short
// range near 0 is weighed as [−1, 1] (its own reach would drop the t² that
// decides the root), and a range so wide that reachⁱ overflows drops nothing.
TEST(PolynomialSolvers, NegligibleTermsAreWeighedSafelyOverTheRange) {
    for (const Solver& s : solvers()) {
        if (!s.guaranteed) continue;
        SCOPED_TRACE(s.name);
        // t³ + 10⁶t² − 10⁻⁷ on [0, 10⁻⁵]: one root, √(10⁻¹³) to 10⁻¹³ relative.
        const std::vector<double> near_zero = solve(s, {-1e-7, 0.0, 1e6, 1.0}, 0.0, 1e-5);
        ASSERT_EQ(near_zero.size(), 1u);
        EXPECT_NEAR(near_zero[0], std::sqrt(1e-13), 1e-18);
    }
    // Degree 20, roots ±1 … ±10, scaled by 10⁻¹⁵⁰, on [0, 10¹⁷]: 10¹⁷ to the
    // 20th overflows.
    std::vector<double> roots;
    for (int k = 1; k <= 10; ++k) roots.insert(roots.end(), {double(k), double(-k)});
    std::vector<double> wide = from_roots(roots);
    for (double& c : wide) c *= 1e-150;
    std::array<double, max_polynomial_degree> out{};
    const PolynomialRoots r = sturm_roots(wide, 0.0, 1e17, out);
    ASSERT_EQ(r.count, 10);
    for (int k = 0; k < 10; ++k) EXPECT_NEAR(out[static_cast<std::size_t>(k)], k + 1.0, 1e-9);
}

// A remainder that is small beside the dividend but exact — nothing
// cancelled to make it — is no rounding residue: t² − 10⁻¹³'s Sturm
// remainder is −10⁻¹³, and taking it for 0 (a test by the dividend's size
// alone) lost the root. Each solver finds it, and a double root whose
// remainder is cancellation's residue still counts once.
TEST(PolynomialSolvers, SmallExactRemaindersAreNotTakenForZero) {
    for (const Solver& s : solvers()) {
        if (!s.guaranteed) continue;
        SCOPED_TRACE(s.name);
        for (const double c : {1e-13, 1e-20, 1e-40}) {
            SCOPED_TRACE(c);
            const std::vector<double> got = solve(s, {-c, 0.0, 1.0}, 0.0, 1.0);
            ASSERT_EQ(got.size(), 1u);
            EXPECT_LE(std::abs(got[0] - std::sqrt(c)) / std::sqrt(c), 1e-9);
        }
        // (t − 0.1)², its coefficients rounded: one root.
        expect_roots(solve(s, from_roots({0.1, 0.1}), 0.0, 1.0), {0.1}, 1e-7);
    }
}

// The other side of that test: a remainder coefficient's running magnitude
// grows faster than the members from one division to the next, so by the
// fourth or fifth remainder a real one lies within the tolerance of it. Taken
// for 0 by the magnitude alone, these lost roots (found in review, the roots
// checked with mpmath): a quintic's only real root beside two complex pairs,
// a septic's first root, and two of four roots 10⁻⁴ apart.
TEST(PolynomialSolvers, RealRemaindersAreNotTakenForZeroLateInTheSequence) {
    const std::vector<double> quintic{-0.028910686951351777, 0.29343767180386549, -1.1917585306299552,
                                      2.4209239096303903,    -2.4597440793154139, 1.0};
    const std::vector<double> septic{-0.0232089571195233, 0.289092110800718, -1.52501839410201, 4.41363092000654,
                                     -7.56414298096366,   7.67229392491531,  -4.26232373537651, 1.0};
    const std::vector<double> cluster{0.0081028825620291754, -0.10802886343581351, 0.54009633749077435,
                                      -1.2001071816834064, 1.0};
    // Near complex pairs and in the cluster, double rounding of p moves the
    // roots by ~10⁻⁸: they are resolved to that. Descartes reports a cluster
    // it cannot split as one root; Sturm counts the four.
    for (const Solver& s : solvers()) {
        if (!s.guaranteed) continue;
        SCOPED_TRACE(s.name);
        expect_roots(solve(s, quintic, 0.0, 1.0), {0.495682602016177}, 1e-7);
        expect_roots(solve(s, septic, 0.0, 1.5), {0.440228763634143, 0.562371906175788, 0.947490108606517}, 1e-7);
    }
    std::array<double, max_polynomial_degree> out{};
    const PolynomialRoots r = sturm_roots(cluster, 0.0, 1.5, out);
    expect_roots({out.begin(), out.begin() + r.count},
                 {0.299728774372998, 0.299837538489226, 0.300177402502325, 0.300363466318858}, 1e-6);
}

TEST(PolynomialSolvers, RootsAtTheEndsOfTheRange) {
    const std::vector<double> roots{0.25, 0.5, 1.0};
    for (const Solver& s : solvers()) {
        SCOPED_TRACE(s.name);
        expect_roots(solve(s, from_roots(roots), 0.25, 1.0), roots, 1e-12);
        const FirstPolynomialRoot first = first_root_with(s.solve, from_roots(roots), 0.25, 1.0);
        EXPECT_TRUE(first.found);
        EXPECT_LE(relative(first.t, 0.25), 1e-15);
    }
}

TEST(PolynomialSolvers, NoRoots) {
    for (const Solver& s : solvers()) {
        SCOPED_TRACE(s.name);
        // (t² + 1)(t − 3): one real root, outside [−2, 2].
        EXPECT_TRUE(solve(s, {-3.0, 1.0, -3.0, 1.0}, -2.0, 2.0).empty());
        // A near miss: (t − 0.5)² + 1e-4.
        EXPECT_TRUE(solve(s, {0.2501, -1.0, 1.0}, 0.0, 1.0).empty());
        EXPECT_FALSE(first_root_with(s.solve, std::vector<double>{1.0, 0.0, 1.0}, -5.0, 5.0).found);
        // Constants, and zero leading coefficients that are dropped.
        std::array<double, 4> out{};
        EXPECT_EQ(s.solve(std::vector<double>{2.0}, -1.0, 1.0, out).count, 0);
        EXPECT_EQ(s.solve(std::vector<double>{-0.5, 1.0, 0.0, 0.0}, 0.0, 1.0, out).count, 1);
        EXPECT_DOUBLE_EQ(out[0], 0.5);
    }
}

TEST(PolynomialSolvers, WilkinsonLikeDegree16OnASubrange) {
    // Π(t − k/16), k = 1 … 16: ill-conditioned in the monomial basis (the
    // middle roots move by ~1e-9 under rounding of the coefficients).
    std::vector<double> roots;
    for (int k = 1; k <= 16; ++k) roots.push_back(k / 16.0);
    const std::vector<double> c = from_roots(roots);
    std::vector<double> inside;
    for (const double r : roots) {
        if (r > 0.2 && r < 0.8) inside.push_back(r);
    }
    for (const Solver& s : solvers()) {
        SCOPED_TRACE(s.name);
        if (s.guaranteed) expect_roots(solve(s, c, 0.2, 0.8), inside, 1e-6);
    }
}

TEST(PolynomialSolvers, FirstRootIsTheSmallest) {
    const std::vector<double> c = from_roots({0.9, 0.1, 0.5, 3.0});
    for (const Solver& s : solvers()) {
        SCOPED_TRACE(s.name);
        const FirstPolynomialRoot r = first_root_with(s.solve, c, 0.0, 1.0);
        EXPECT_TRUE(r.found);
        EXPECT_LE(relative(r.t, 0.1), 1e-12);
    }
}

TEST(PolynomialSolvers, FirstRootAgreesWithAllRoots) {
    // Asking for one root stops the guaranteed solvers early; the answer
    // must still be the smallest of all the roots.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> root(0.0, 1.0);
    for (const Solver& s : solvers()) {
        SCOPED_TRACE(s.name);
        for (int trial = 0; trial < 200; ++trial) {
            std::vector<double> roots(static_cast<std::size_t>(2 + trial % 7));
            for (double& r : roots) r = root(rng);
            const std::vector<double> c = from_roots(roots, 1.0 + trial);
            const std::vector<double> all = solve(s, c, 0.1, 0.9);
            const FirstPolynomialRoot first = first_root_with(s.solve, c, 0.1, 0.9);
            EXPECT_EQ(first.found, !all.empty());
            if (!all.empty()) {
                EXPECT_EQ(first.t, all.front());
            }
        }
    }
}

TEST(PolynomialSolvers, RejectsBadInput) {
    const std::vector<double> too_high(40, 1.0);
    std::array<double, 4> out{};
    for (const Solver& s : solvers()) {
        EXPECT_THROW(s.solve(too_high, 0.0, 1.0, out), std::invalid_argument);
        EXPECT_THROW(s.solve(std::vector<double>{1.0, 1.0}, 1.0, 0.0, out), std::invalid_argument);
    }
}

TEST(Horner, ValueAndDerivativeInOnePass) {
    const std::vector<double> c{1.0, -3.0, 0.0, 2.0};  // 2t³ − 3t + 1
    const ValueAndDerivative v = horner(c, 1.5);
    EXPECT_DOUBLE_EQ(v.value, 2.0 * 3.375 - 4.5 + 1.0);
    EXPECT_DOUBLE_EQ(v.derivative, 6.0 * 2.25 - 3.0);
}

}  // namespace
}  // namespace zeroset
