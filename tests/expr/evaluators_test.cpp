// Every op of the op table through every evaluator — one suite run against all
// number types, as fidget does: the plain evaluators must agree with each
// other, Dual and Jet with finite differences, and the interval evaluators
// must enclose the sampled values, gradients and ray derivatives (the batch
// evaluator's backends: batch_evaluator_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "evaluator_cases.hpp"
#include "zeroset/expr/batch_evaluator.hpp"
#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/lipschitz.hpp"
#include "zeroset/expr/tape_pruner.hpp"
#include "zeroset/math/box3.hpp"

namespace zeroset {
namespace {

using namespace evaluator_cases;

/// How far p is from a kink or a jump, where finite differences do not
/// apply: the smallest |a| of abs, |a − b| of min/max, distance to an
/// integer of floor, to a pole of tan, to the cut of atan2 and to hypot's apex.
double kink_distance(const Tape& tape, const Vec3d& p) {
    std::vector<double> s(tape.slot_count());
    for (const auto& [slot, value] : tape.constants()) s[slot] = value;
    s[Tape::slot_x] = p.x;
    s[Tape::slot_y] = p.y;
    s[Tape::slot_z] = p.z;
    double distance = std::numeric_limits<double>::infinity();
    for (const Clause& c : tape.clauses()) {
        const double a = s[c.a];
        if (c.op == Op::Abs) distance = std::min(distance, std::abs(a));
        if (c.op == Op::Min || c.op == Op::Max) distance = std::min(distance, std::abs(a - s[c.b]));
        if (c.op == Op::Floor) distance = std::min(distance, std::abs(a - std::round(a)));
        if (c.op == Op::Tan)
            distance = std::min(distance, std::abs(std::remainder(a - std::numbers::pi / 2, std::numbers::pi)));
        if (c.op == Op::Atan2) distance = std::min(distance, s[c.b] < 0.0 ? std::abs(a) : std::hypot(a, s[c.b]));
        if (c.op == Op::Hypot) distance = std::min(distance, std::hypot(a, s[c.b]));
        s[c.out] = apply_op<double>(c.op, a, c.op == Op::Powi ? a : s[c.b], static_cast<int>(c.b));
    }
    return distance;
}

/// Every op of the table occurs in some case, so "every op" stays true as ops are added.
TEST(Evaluators, CasesCoverTheWholeOpTable) {
    std::set<Op> seen;
    for (const Case& c : cases()) {
        const Tape tape(c.f);
        for (const Clause& clause : tape.clauses()) seen.insert(clause.op);
        if (!tape.constants().empty()) seen.insert(Op::Const);
    }
    seen.insert({Op::VarX, Op::VarY, Op::VarZ});  // the slots 0..2
    for (int i = 0; i < op_count; ++i)
        EXPECT_TRUE(seen.contains(static_cast<Op>(i))) << "no case uses " << op_name(static_cast<Op>(i));
}

TEST(Evaluators, GradientMatchesFiniteDifferences) {
    Sampler sampler{std::mt19937_64(2)};
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const Tape tape(c.f);
        Evaluator<double> eval(tape);
        Evaluator<Dual<double>> eval_d(tape);
        int checked = 0;
        for (int i = 0; i < point_count; ++i) {
            const Vec3d p = sampler.point();
            const double v = eval(p.x, p.y, p.z);
            if (!std::isfinite(v) || kink_distance(tape, p) < 1e-3) continue;
            const Dual<double> d = evaluate_gradient(eval_d, p);
            ASSERT_TRUE(close(d.v, v, 1e-13)) << "value " << d.v << " vs " << v;
            for (int axis = 0; axis < 3; ++axis) {
                const double h = 1e-6;
                const auto central = [&](double step) {
                    Vec3d a = p, b = p;
                    a[axis] += step;
                    b[axis] -= step;
                    return (eval(a.x, a.y, a.z) - eval(b.x, b.y, b.z)) / (2 * step);
                };
                const double fd = central(h), fd2 = central(2 * h);
                if (!std::isfinite(fd) || !std::isfinite(fd2)) continue;
                // |fd − fd2| estimates fd's truncation error (large near a pole or a domain edge).
                const double tolerance =
                    1e-5 * (1.0 + std::abs(d.g[axis])) + 1e-15 * std::abs(v) / h + std::abs(fd - fd2);
                ASSERT_NEAR(d.g[axis], fd, tolerance)
                    << "∂/∂"
                    << "xyz"[axis] << " at (" << p.x << ", " << p.y << ", " << p.z << ")";
            }
            ++checked;
        }
        EXPECT_GT(checked, point_count / 4);
    }
}

TEST(Evaluators, JetMatchesFiniteDifferencesAlongRays) {
    Sampler sampler{std::mt19937_64(3)};
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const Tape tape(c.f);
        Evaluator<double> eval(tape);
        Evaluator<Dual<double>> eval_d(tape);
        Evaluator<Jet<double>> eval_j(tape);
        int checked = 0;
        for (int i = 0; i < point_count; ++i) {
            const Vec3d o = sampler.point();
            const Vec3d dir{sampler.uniform(-1, 1), sampler.uniform(-1, 1), sampler.uniform(-1, 1)};
            const double t = sampler.uniform(-0.1, 0.1);
            const auto H = [&](double s) {
                const Vec3d p = o + dir * s;
                return eval(p.x, p.y, p.z);
            };
            const double h = 1e-4;
            const double samples[] = {H(t - 2 * h), H(t - h), H(t), H(t + h), H(t + 2 * h)};
            if (!std::all_of(std::begin(samples), std::end(samples), [](double v) { return std::isfinite(v); }))
                continue;
            if (kink_distance(tape, o + dir * t) < 3e-2) continue;
            const Jet<double> j = evaluate_along_ray(eval_j, o, dir, t);
            const Dual<double> g = evaluate_gradient(eval_d, o + dir * t);
            // Central differences with steps h and 2h; their difference estimates the truncation error.
            const double d1 = (samples[3] - samples[1]) / (2 * h), d1_wide = (samples[4] - samples[0]) / (4 * h);
            const double d2 = (samples[3] - 2 * samples[2] + samples[1]) / (h * h);
            const double d2_wide = (samples[4] - 2 * samples[2] + samples[0]) / (4 * h * h);
            const std::string where = "t = " + std::to_string(t) + " on ray " + std::to_string(i);
            ASSERT_TRUE(close(j.v, samples[2], 1e-13)) << where << ": H " << j.v << " vs " << samples[2];
            ASSERT_TRUE(close(j.d1, dot(g.g, dir), 1e-12)) << where << ": H′ " << j.d1 << " vs ∇f·d " << dot(g.g, dir);
            ASSERT_NEAR(j.d1, d1, 1e-6 * (1.0 + std::abs(j.d1)) + 1e-15 * std::abs(j.v) / h + std::abs(d1 - d1_wide))
                << where;
            ASSERT_NEAR(j.d2, d2,
                        1e-4 * (1.0 + std::abs(j.d2)) + 1e-15 * std::abs(j.v) / (h * h) + std::abs(d2 - d2_wide))
                << where;
            ++checked;
        }
        EXPECT_GT(checked, point_count / 5);
    }
}

/// A random sub-box of the domain, from tiny to the whole domain.
Box3 random_box(Sampler& s) {
    const double scale = std::pow(10.0, s.uniform(-6.0, 0.3));
    Vec3d lo, hi;
    for (int axis = 0; axis < 3; ++axis) {
        const double w = std::min(hi_bound - lo_bound, scale * s.uniform(0.1, 1.0));
        lo[axis] = s.uniform(lo_bound, hi_bound - w);
        hi[axis] = lo[axis] + w;
    }
    return {lo, hi};
}

/// v ∈ enclosure, up to the rounding error of the double evaluation of v.
testing::AssertionResult inside(const char* what, Interval enclosure, double v) {
    const double slack = 1e-10 * (1.0 + std::abs(v));
    if (enclosure.lo <= v + slack && v - slack <= enclosure.hi) return testing::AssertionSuccess();
    return testing::AssertionFailure() << what << " " << v << " outside [" << enclosure.lo << ", " << enclosure.hi
                                       << "]";
}

TEST(Evaluators, IntervalAndDualIntervalEncloseSamples) {
    Sampler sampler{std::mt19937_64(4)};
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const Tape tape(c.f);
        Evaluator<double> eval(tape);
        Evaluator<Dual<double>> eval_d(tape);
        Evaluator<Interval> eval_i(tape);
        Evaluator<Dual<Interval>> eval_di(tape);
        int checked = 0;
        for (int box_index = 0; box_index < 60; ++box_index) {
            const Box3 box = random_box(sampler);
            const Interval f = evaluate_box(eval_i, box.lo, box.hi);
            const Dual<Interval> fd = eval_di(Dual<Interval>::variable(Interval(box.lo.x, box.hi.x), 0),
                                              Dual<Interval>::variable(Interval(box.lo.y, box.hi.y), 1),
                                              Dual<Interval>::variable(Interval(box.lo.z, box.hi.z), 2));
            for (int k = 0; k < 24; ++k) {
                Vec3d p;
                for (int axis = 0; axis < 3; ++axis)  // corners first, then interior points
                    p[axis] = k < 8 ? ((k >> axis) & 1 ? box.hi[axis] : box.lo[axis])
                                    : sampler.uniform(box.lo[axis], box.hi[axis]);
                const double v = eval(p.x, p.y, p.z);
                if (!std::isfinite(v)) continue;
                const std::string where =
                    " at (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")";
                ASSERT_TRUE(inside("f", f, v)) << where;
                ASSERT_TRUE(inside("Dual<Interval> value", fd.v, v)) << where;
                if (kink_distance(tape, p) < 1e-9) continue;  // the gradient's branch is a convention there
                const Dual<double> g = evaluate_gradient(eval_d, p);
                for (int axis = 0; axis < 3; ++axis) {
                    if (!std::isfinite(g.g[axis])) continue;
                    ASSERT_TRUE(inside("∂f", fd.g[axis], g.g[axis])) << where << " axis " << axis;
                }
                ++checked;
            }
        }
        EXPECT_GT(checked, 200);
    }
}

TEST(Evaluators, JetIntervalEnclosesRaySamples) {
    Sampler sampler{std::mt19937_64(5)};
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const Tape tape(c.f);
        Evaluator<double> eval(tape);
        Evaluator<Jet<double>> eval_j(tape);
        Evaluator<Jet<Interval>> eval_ji(tape);
        int checked = 0;
        for (int ray_index = 0; ray_index < 60; ++ray_index) {
            // A segment from o (t = 0) to o + dir (t = 1), both inside the domain.
            const Vec3d o = sampler.point();
            const Vec3d dir = sampler.point() - o;
            double t0 = sampler.uniform(0, 1), t1 = sampler.uniform(0, 1);
            if (t0 > t1) std::swap(t0, t1);
            if (ray_index % 3 == 0) t1 = std::min(1.0, t0 + 1e-6);  // short segments too
            const Jet<Interval> J = evaluate_along_ray(eval_ji, o, dir, Interval(t0, t1));
            struct Sample {
                double t, h, h1;  // t, H(t), H′(t)
            };
            std::vector<Sample> seen;
            for (int k = 0; k < 16; ++k) {
                const double t = k == 0 ? t0 : k == 1 ? t1 : sampler.uniform(t0, t1);
                const Vec3d p = o + dir * t;
                if (!std::isfinite(eval(p.x, p.y, p.z)) || kink_distance(tape, p) < 1e-9) continue;
                const Jet<double> j = evaluate_along_ray(eval_j, o, dir, t);
                if (!std::isfinite(j.v) || !std::isfinite(j.d1) || !std::isfinite(j.d2)) continue;
                const std::string where = " at t = " + std::to_string(t) + " on ray " + std::to_string(ray_index);
                ASSERT_TRUE(inside("H", J.v, j.v)) << where;
                ASSERT_TRUE(inside("H′", J.d1, j.d1)) << where;
                ASSERT_TRUE(inside("H″", J.d2, j.d2)) << where;
                seen.push_back({t, j.v, j.d1});
                ++checked;
            }
            // What the root finders rely on: the enclosures bound the variation
            // over the whole segment — |ΔH| ≤ max|H′|·Δt (Fig. 9, sphere tracing)
            // and |ΔH′| ≤ max|H″|·Δt (Lip H′ for the LG method, Fig. 11), even
            // where abs/min/max switch branches inside the segment.
            for (const Sample& r : seen)
                for (const Sample& s : seen) {
                    const double dt = std::abs(s.t - r.t);
                    if (dt == 0.0) continue;
                    const double tolerance =
                        1e-9 * (1.0 + std::abs(r.h) + std::abs(s.h) + std::abs(r.h1) + std::abs(s.h1));
                    ASSERT_LE(std::abs(s.h - r.h), J.d1.magnitude() * dt + tolerance)
                        << "H between t = " << r.t << " and " << s.t << " on ray " << ray_index;
                    ASSERT_LE(std::abs(s.h1 - r.h1), J.d2.magnitude() * dt + tolerance)
                        << "H′ between t = " << r.t << " and " << s.t << " on ray " << ray_index << ": H′ = " << r.h1
                        << ", " << s.h1 << "; max|H″| = " << J.d2.magnitude();
                }
        }
        EXPECT_GT(checked, 150);
    }
}

TEST(Evaluators, PointIntervalsAgreeWithDoubles) {
    // Degenerate boxes and segments: the enclosures are tight around the double values.
    Sampler sampler{std::mt19937_64(6)};
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const Tape tape(c.f);
        Evaluator<double> eval(tape);
        Evaluator<Interval> eval_i(tape);
        for (int i = 0; i < 50; ++i) {
            const Vec3d p = sampler.point();
            const double v = eval(p.x, p.y, p.z);
            if (!std::isfinite(v)) continue;
            const Interval f = evaluate_box(eval_i, p, p);
            ASSERT_TRUE(inside("f", f, v));
            ASSERT_LE(f.width(), 1e-12 * (1.0 + std::abs(v))) << "[" << f.lo << ", " << f.hi << "]";
        }
    }
}

// Domain edges: the interval evaluators clip to where f is defined.
TEST(Evaluators, DomainEdges) {
    const Tape root(sqrt(X));
    Evaluator<Interval> f(root);
    const Interval a = f(Interval(-1, 4), Interval(0.0), Interval(0.0));
    EXPECT_EQ(a.lo, 0.0);
    EXPECT_GE(a.hi, 2.0);
    EXPECT_LE(a.hi, 2.0 + 1e-15);
    EXPECT_TRUE(f(Interval(-2, -1), Interval(0.0), Interval(0.0)).is_empty());

    // Undefined everywhere stays undefined through later ops, even min/max.
    const Tape later(min(sqrt(X) + Y, Z));
    Evaluator<Interval> g(later);
    EXPECT_TRUE(g(Interval(-2, -1), Interval(0, 1), Interval(0, 1)).is_empty());

    const Tape logarithm(log(X));
    Evaluator<Interval> h(logarithm);
    EXPECT_EQ(h(Interval(0, 1), Interval(0.0), Interval(0.0)).lo, -std::numeric_limits<double>::infinity());
    EXPECT_TRUE(h(Interval(-3, -1), Interval(0.0), Interval(0.0)).is_empty());

    // At the edge of sqrt's domain the gradient is unbounded; the enclosure says so.
    Evaluator<Dual<Interval>> d(root);
    const Dual<Interval> r = d(Dual<Interval>::variable(Interval(0, 1), 0), Dual<Interval>(0.0), Dual<Interval>(0.0));
    EXPECT_EQ(r.g.x.hi, std::numeric_limits<double>::infinity());
    EXPECT_GE(r.g.x.lo, 0.0);

    // 1/x over a box touching 0 reaches +∞ only on one side.
    const Tape reciprocal(1.0 / X);
    Evaluator<Interval> q(reciprocal);
    const Interval above = q(Interval(0, 2), Interval(0.0), Interval(0.0));
    EXPECT_LE(above.lo, 0.5);
    EXPECT_GE(above.lo, 0.5 - 1e-15);
    EXPECT_EQ(above.hi, std::numeric_limits<double>::infinity());
    const Interval both = q(Interval(-1, 2), Interval(0.0), Interval(0.0));
    EXPECT_EQ(both.lo, -std::numeric_limits<double>::infinity());
    EXPECT_EQ(both.hi, std::numeric_limits<double>::infinity());

    // The Jet along a ray crossing x = 0 encloses H′ on the defined part.
    Evaluator<Jet<Interval>> j(root);
    const Jet<Interval> s = evaluate_along_ray(j, {-1, 0, 0}, {1, 0, 0}, Interval(0.5, 2));
    EXPECT_EQ(s.v.lo, 0.0);
    EXPECT_GE(s.v.hi, 1.0);
    EXPECT_EQ(s.d1.hi, std::numeric_limits<double>::infinity());

    // Plain evaluation outside the domain gives NaN, not a crash.
    Evaluator<double> e(root);
    EXPECT_TRUE(std::isnan(e(-1, 0, 0)));
    Evaluator<Dual<double>> ed(root);
    EXPECT_TRUE(std::isnan(evaluate_gradient(ed, {-1, 0, 0}).v));
}

// Across a jump of floor, tan or atan2 no finite slope bounds f: the
// Lipschitz bound over a box holding one is infinite, elsewhere finite; hypot
// keeps a norm's bound finite even at its apex, where √ alone cannot.
TEST(Evaluators, LipschitzBoundsAcrossJumpsAndAtTheApex) {
    const auto bound = [](const Expr& f, const Box3& box) {
        const Tape tape(f);
        Evaluator<Dual<Interval>> eval(tape);
        return lipschitz_bound(eval, box).constant;
    };
    constexpr double inf = std::numeric_limits<double>::infinity();
    const Box3 across{{0.9, -0.1, -0.1}, {1.1, 0.1, 0.1}}, clear{{0.2, 0.2, 0.2}, {0.8, 0.8, 0.8}};
    EXPECT_EQ(bound(floor(X) + Y, across), inf);
    EXPECT_LT(bound(floor(X) + Y, clear), 1.0 + 1e-12);
    EXPECT_EQ(bound(tan(X + 0.6), across), inf);  // π/2 − 0.6 ∈ [0.9, 1.1]
    EXPECT_TRUE(std::isfinite(bound(tan(X + 0.6), clear)));
    EXPECT_EQ(bound(atan2(Y, X - 1.5), across), inf);  // the cut y = 0, x < 1.5
    EXPECT_LT(bound(atan2(Y, X - 1.5), clear), 4.0);
    const Box3 apex{{-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}};
    EXPECT_LE(bound(hypot(hypot(X, Y), Z), apex), std::sqrt(3.0) * (1 + 1e-12));
    // Written out as √(x² + y² + z²), the builder makes it the same hypots.
    EXPECT_LE(bound(sqrt(square(X) + square(Y) + square(Z)), apex), std::sqrt(3.0) * (1 + 1e-12));
    EXPECT_EQ(bound(sqrt(abs(X)), apex), inf);  // a real infinite slope
    // And the point gradient of a norm at its apex is a subgradient, not 0/0.
    const Tape norm(hypot(hypot(X, Y), Z));
    Evaluator<Dual<double>> eval(norm);
    EXPECT_EQ(evaluate_gradient(eval, {0, 0, 0}).g, (Vec3d{0, 0, 0}));
}

TEST(Evaluators, PowiWithLargeAndNegativeExponents) {
    // The exponent is an immediate in the clause, not a slot: it may exceed the slot count.
    for (const int n : {3, 7, 40, 201, -1, -5, -40}) {
        const Tape tape(powi(X, n));
        ASSERT_LT(tape.slot_count(), 10u);
        Evaluator<double> e(tape);
        Evaluator<Interval> ei(tape);
        Evaluator<Jet<double>> ej(tape);
        const double v = e(1.01, 0, 0);
        EXPECT_NEAR(v, std::pow(1.01, n), 1e-13 * std::pow(1.01, n)) << n;
        EXPECT_TRUE(inside("powi", ei(Interval(1.01), Interval(0.0), Interval(0.0)), v)) << n;
        const Jet<double> jet = evaluate_along_ray(ej, {1.01, 0, 0}, {1, 0, 0}, 0.0);
        EXPECT_NEAR(jet.d1, n * std::pow(1.01, n - 1), 1e-12 * std::abs(jet.d1)) << n;
        EXPECT_NEAR(jet.d2, n * (n - 1) * std::pow(1.01, n - 2), 1e-12 * std::abs(jet.d2)) << n;
        BatchEvaluator<float> b(tape);
        const float x = 1.01f, zero = 0.0f;
        float out = 0.0f;
        b.evaluate({&x, 1}, {&zero, 1}, {&zero, 1}, {&out, 1});
        EXPECT_NEAR(out, std::pow(1.01f, static_cast<float>(n)), 1e-5 * std::abs(v)) << n;
    }
}

}  // namespace
}  // namespace zeroset
