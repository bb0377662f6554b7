// The survey's own examples (§1–2): the ray through the blended spheres of
// Figure 1, the sphere's quadratic F(t) (eqs. 10–11) and Blinn's H(t)
// (eq. 15) with Newton's method from the six starts of Figure 4. Oracles:
// the survey's text, and mpmath at 40 digits for the roots of the same
// functions with the same double-precision parameters.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "root_test_support.hpp"
#include "zeroset/roots/bisection.hpp"
#include "zeroset/roots/newton.hpp"
#include "zeroset/roots/refine.hpp"
#include "zeroset/roots/sign_change_brackets.hpp"

namespace zeroset {
namespace {

// The ray of eq. 9: r(t) = (−4.905 + 0.981t, −0.67 + 0.174t, 0.364 + 0.0872t).
constexpr std::array<double, 3> origin{-4.905, -0.67, 0.364};
constexpr std::array<double, 3> direction{0.981, 0.174, 0.0872};

/// F(t) for the unit sphere at (cx, 0, 0) along the ray (eq. 10), and F′ (eq. 16).
ValueAndDerivative sphere_along_ray(double t, double cx) {
    const double x = origin[0] + direction[0] * t - cx;
    const double y = origin[1] + direction[1] * t;
    const double z = origin[2] + direction[2] * t;
    return {x * x + y * y + z * z - 1.0, 2.0 * (x * direction[0] + y * direction[1] + z * direction[2])};
}

/// Blinn's blend H(t) = 1 − e^−F − e^−G (eq. 15) and H′ (eq. 18).
ValueAndDerivative blinn_h(double t) {
    const ValueAndDerivative f = sphere_along_ray(t, 1.2);
    const ValueAndDerivative g = sphere_along_ray(t, -1.2);
    const double ef = std::exp(-f.value);
    const double eg = std::exp(-g.value);
    return {1.0 - ef - eg, ef * f.derivative + eg * g.derivative};
}

// The four roots of H along the ray (mpmath, 40 digits): the ray enters the
// right-hand blob, leaves it, enters the left-hand one and leaves.
constexpr std::array<double, 4> blinn_roots{2.99572987604150975036693634236, 4.50208527955189601239819931444,
                                            5.85301893826924481698695413985, 6.2540237055958464468759363917};

std::vector<double> refined_roots(double t0, double t1, int samples) {
    std::vector<double> roots;
    for (const Bracket& b : sign_change_brackets([](double t) { return blinn_h(t).value; }, t0, t1, samples).brackets) {
        const BracketResult r = refine_root(blinn_h, b.lo, b.hi);
        EXPECT_EQ(r.status, BracketStatus::Converged);
        roots.push_back(r.t);
    }
    return roots;
}

TEST(SurveyExamples, BlinnBlobsHaveFourRootsAlongTheRay) {
    const std::vector<double> roots = refined_roots(0.0, 10.0, 101);
    ASSERT_EQ(roots.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(roots[i], blinn_roots[i], 1e-15 * blinn_roots[i]) << i;
        // Bisection, sharing nothing with refine_root but the bracket, agrees.
        const double width = 0.05;
        const BracketResult b = bisection([](double t) { return blinn_h(t).value; }, blinn_roots[i] - width,
                                          blinn_roots[i] + width);
        EXPECT_LE(test::ulps_between(b.t, roots[i]), 2) << i;
    }
}

TEST(SurveyExamples, NewtonFromTheStartsOfFigure4) {
    // "At t₀ = 3.5 Newton's method converges on the first ray intersection. At
    // t₀ = 3.6 the method converges to the third ray intersection. At t₀ = 3.7
    // the method shoots back to −5 where the slope is nearly zero, causing
    // divergence. At t₀ = 3.8 the method converges on the fourth ray
    // intersection. At t₀ = 3.9 the method is unlucky, finding a curve peak
    // causing it to diverge. At t₀ = 4.0 the method converges to the second."
    NewtonOptions options;
    options.domain = Interval(-10.0, 20.0);  // well beyond the plotted span
    const auto run = [&](double t0, std::vector<double>* iterates = nullptr) {
        NewtonOptions o = options;
        o.iterates = iterates;
        return newton(blinn_h, t0, o);
    };
    const std::array<std::pair<double, int>, 4> converging{{{3.5, 0}, {3.6, 2}, {3.8, 3}, {4.0, 1}}};
    for (const auto& [t0, root] : converging) {
        SCOPED_TRACE(t0);
        const NewtonResult r = run(t0);
        EXPECT_EQ(r.status, NewtonStatus::Converged);
        EXPECT_NEAR(r.t, blinn_roots[static_cast<std::size_t>(root)], 4e-15 * r.t);
        EXPECT_LE(r.evaluations, 10);
    }
    std::vector<double> iterates;
    const NewtonResult shoots = run(3.7, &iterates);
    EXPECT_EQ(shoots.status, NewtonStatus::Diverged);
    ASSERT_GE(iterates.size(), 2u);
    EXPECT_NEAR(iterates[1], -5.0, 0.1);  // "shoots back to −5"
    EXPECT_LT(std::abs(blinn_h(iterates[1]).derivative), 1e-20);  // "where the slope is nearly zero"

    iterates.clear();
    const NewtonResult peak = run(3.9, &iterates);
    EXPECT_EQ(peak.status, NewtonStatus::Diverged);
    ASSERT_GE(iterates.size(), 2u);
    // The first step lands on the hump of H between the two blobs (its top
    // is at t ≈ 5.0596), where H′ is nearly 0 and the next step flies off.
    EXPECT_GT(iterates[1], blinn_roots[1]);
    EXPECT_LT(iterates[1], blinn_roots[2]);
    EXPECT_LT(std::abs(blinn_h(iterates[1]).derivative), 0.01);
    EXPECT_GT(std::abs(iterates.back() - iterates[1]), 100.0);
}

TEST(SurveyExamples, PrintedQuadraticOfEquation11HasNoRealRoot) {
    // Eq. 11 prints F(t) = t² − 12.1t + 36.9, rounded from eq. 10. Its
    // discriminant is 12.1² − 4·36.9 = −1.19: the rounded parabola misses the
    // axis (minimum 0.2975 at t = 6.05), though the ray does hit the sphere.
    const auto f11 = [](double t) { return ValueAndDerivative{t * t - 12.1 * t + 36.9, 2.0 * t - 12.1}; };
    EXPECT_TRUE(sign_change_brackets([&](double t) { return f11(t).value; }, 0.0, 12.0, 1201).brackets.empty());
    EXPECT_NEAR(f11(6.05).value, 0.2975, 1e-12);
    EXPECT_EQ(refine_root(f11, 0.0, 12.0).status, BracketStatus::NoSignChange);
    NewtonOptions options;
    options.domain = Interval(0.0, 12.0);
    EXPECT_NE(newton(f11, 3.5, options).status, NewtonStatus::Converged);
}

TEST(SurveyExamples, SphereQuadraticOfEquation10HasTwoRoots) {
    // Expanded exactly, eq. 10 is 1.00024084t² − 12.1476884t + 36.852421:
    // the ray enters the sphere at 5.8984 and leaves at 6.2464 (mpmath).
    const auto f10 = [](double t) { return sphere_along_ray(t, 1.2); };
    std::vector<double> roots;
    for (const Bracket& b : sign_change_brackets([&](double t) { return f10(t).value; }, 0.0, 12.0, 121).brackets) {
        roots.push_back(refine_root(f10, b.lo, b.hi).t);
    }
    ASSERT_EQ(roots.size(), 2u);
    EXPECT_NEAR(roots[0], 5.89839251668682620807624044159, 1e-15 * roots[0]);
    EXPECT_NEAR(roots[1], 6.24637093848263142758484109493, 1e-15 * roots[1]);
}

}  // namespace
}  // namespace zeroset
