// The survey's worked example (§§1–3) as tests: the ray
// x_o = (−4.905, −0.67, 0.364), x_d = (0.981, 0.174, 0.0872) through the
// single sphere of eq. 5, Blinn's blend of eq. 12 and the soft objects of
// eqs. 23–24. The direction is used as given (not normalised), like the survey.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "zeroset/scene/load_scene.hpp"
#include "zeroset/trace/choose_method.hpp"
#include "zeroset/trace/root_finder.hpp"

namespace zeroset {
namespace {

const Ray survey_ray{{-4.905, -0.67, 0.364}, {0.981, 0.174, 0.0872}};

struct Subject {
    Scene scene;
    Tape tape;
    Span span;

    explicit Subject(const char* scene_file)
        : scene(load_scene(std::string(ZEROSET_SOURCE_DIR) + "/scenes/hart1993/" + scene_file)),
          tape(placed_objects(scene).at(0).object().surface),
          span(*placed_objects(scene).at(0).object().bounds.clip(survey_ray, 0.0, 1e9)) {}

    [[nodiscard]] RootFinderSettings settings() const {
        return settings_for_scale(placed_objects(scene).at(0).object().bounds.enclosing_box().diagonal());
    }

    std::vector<double> all_hits(Method method) {
        RayFunction h(tape);
        h.set_ray(survey_ray);
        auto finder = make_root_finder(method, tape, settings());
        std::vector<double> hits;
        TraceCounters counters;
        EXPECT_EQ(finder->all_hits(h, span, hits, counters), HitStatus::Ok) << method_name(method);
        return hits;
    }

    HitResult first_hit(Method method) {
        RayFunction h(tape);
        h.set_ray(survey_ray);
        TraceCounters counters;
        return make_root_finder(method, tape, settings())->first_hit(h, span, counters);
    }
};

/// Sign changes of H found by dense sampling, each refined by bisection —
/// an independent check of the methods' roots.
std::vector<double> sampled_roots(Subject& s, int samples = 200000) {
    RayFunction h(s.tape);
    h.set_ray(survey_ray);
    TraceCounters counters;
    std::vector<double> roots;
    const double step = (s.span.t1 - s.span.t0) / samples;
    double a = s.span.t0, fa = h.value(a, counters);
    for (int i = 1; i <= samples; ++i) {
        double b = s.span.t0 + i * step, fb = h.value(b, counters);
        if ((fa <= 0.0) != (fb <= 0.0)) {
            double lo = a, hi = b, flo = fa;
            for (int k = 0; k < 200 && lo < hi; ++k) {
                const double mid = 0.5 * (lo + hi);
                if (mid <= lo || mid >= hi) break;
                const double fm = h.value(mid, counters);
                if ((fm <= 0.0) == (flo <= 0.0)) {
                    lo = mid;
                    flo = fm;
                } else {
                    hi = mid;
                }
            }
            roots.push_back(hi);
        }
        a = b;
        fa = fb;
    }
    return roots;
}

constexpr Method guaranteed[] = {Method::Interval, Method::Lg, Method::Sphere};

TEST(WorkedExample, SphereGivesTheSurveysQuadratic) {
    Subject s("sphere.zs");
    RayFunction h(s.tape);
    h.set_ray(survey_ray);
    TraceCounters counters;
    // F(t) = a t² + b t + c: read the coefficients off F(0), F′(0), F″(0).
    const Jet<double> at0 = h.jet(0.0, counters);
    const double a = at0.d2 / 2, b = at0.d1, c = at0.v;
    EXPECT_NEAR(a, 1.0, 0.0005);                   // "t²"
    EXPECT_NEAR(b, -12.1, 0.05);                   // "− 12.1t"
    EXPECT_NEAR(c, 36.9, 0.05);                    // "+ 36.9" (eq. 11)
    EXPECT_EQ(std::round(b * 10) / 10, -12.1);     // to the survey's rounding
    EXPECT_EQ(std::round(c * 10) / 10, 36.9);
    // The exact roots of the exact quadratic.
    const double disc = std::sqrt(b * b - 4 * a * c);
    const double q = -0.5 * (b - disc);
    const double r1 = c / q, r2 = q / a;
    for (const Method m : guaranteed) {
        const std::vector<double> hits = s.all_hits(m);
        ASSERT_EQ(hits.size(), 2u) << method_name(m);
        EXPECT_NEAR(hits[0], r1, 1e-12) << method_name(m);
        EXPECT_NEAR(hits[1], r2, 1e-12) << method_name(m);
        const HitResult first = s.first_hit(m);
        ASSERT_TRUE(first.t) << method_name(m);
        EXPECT_NEAR(*first.t, r1, 1e-12) << method_name(m);
    }
    // The bracketing methods find both roots too (the sampling resolves them)…
    for (const Method m : {Method::RegulaFalsi, Method::Bisection}) {
        const std::vector<double> hits = s.all_hits(m);
        ASSERT_EQ(hits.size(), 2u) << method_name(m);
        EXPECT_NEAR(hits[0], r1, 1e-12) << method_name(m);
        EXPECT_NEAR(hits[1], r2, 1e-12) << method_name(m);
    }
    // The polynomial method, with every solver, finds them from F(t)'s exact coefficients.
    for (const PolynomialSolver solver : all_polynomial_solvers()) {
        RayFunction along(s.tape);
        along.set_ray(survey_ray);
        RootFinderSettings settings = s.settings();
        settings.polynomial_solver = solver;
        std::vector<double> hits;
        TraceCounters spent;
        make_root_finder(Method::Polynomial, s.tape, settings)->all_hits(along, s.span, hits, spent);
        ASSERT_EQ(hits.size(), 2u) << polynomial_solver_name(solver);
        EXPECT_NEAR(hits[0], r1, 1e-12) << polynomial_solver_name(solver);
        EXPECT_NEAR(hits[1], r2, 1e-12) << polynomial_solver_name(solver);
    }
    // …and Newton finds each one from a start near it.
    for (const double root : {r1, r2}) {
        RayFunction along(s.tape);
        along.set_ray(survey_ray);
        RootFinderSettings settings = s.settings();
        settings.newton_start = root + (root == r1 ? -0.1 : 0.1);
        TraceCounters spent;
        const HitResult r = make_root_finder(Method::Newton, s.tape, settings)->first_hit(along, s.span, spent);
        ASSERT_TRUE(r.t) << hit_status_name(r.status);
        EXPECT_NEAR(*r.t, root, 1e-12);
    }
}

TEST(WorkedExample, BlinnBlendHasFourRootsAndEveryGuaranteedMethodFindsThem) {
    Subject s("blinn_blobs.zs");
    const std::vector<double> reference = sampled_roots(s);
    ASSERT_EQ(reference.size(), 4u);  // Figure 3: the ray crosses the blend four times
    for (const Method m : guaranteed) {
        const std::vector<double> hits = s.all_hits(m);
        ASSERT_EQ(hits.size(), 4u) << method_name(m);
        for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(hits[i], reference[i], 1e-9) << method_name(m) << " root " << i;
        const HitResult first = s.first_hit(m);
        ASSERT_TRUE(first.t);
        EXPECT_NEAR(*first.t, reference[0], 1e-9) << method_name(m);
    }
}

TEST(WorkedExample, NewtonFromThreePointFiveToFourBehavesAsFigureFourSays) {
    Subject s("blinn_blobs.zs");
    const std::vector<double> roots = sampled_roots(s);
    ASSERT_EQ(roots.size(), 4u);
    // Fig. 4's caption: from t0 = 3.5 the first root, 3.6 the third, 3.7
    // diverges (it shoots back to −5), 3.8 the fourth, 3.9 diverges (a peak),
    // 4.0 the second.
    struct Case {
        double t0;
        int root;  // index into roots, or −1 for divergence
    };
    for (const Case c : {Case{3.5, 0}, Case{3.6, 2}, Case{3.7, -1}, Case{3.8, 3}, Case{3.9, -1}, Case{4.0, 1}}) {
        RayFunction h(s.tape);
        h.set_ray(survey_ray);
        MethodLog log;
        RootFinderSettings settings = s.settings();
        settings.newton_start = c.t0;
        settings.log = &log;
        TraceCounters counters;
        // Newton runs on the whole ray here, as in the survey's figure.
        const HitResult r = make_root_finder(Method::Newton, s.tape, settings)->first_hit(h, {-10.0, 20.0}, counters);
        if (c.root < 0) {
            EXPECT_EQ(r.status, HitStatus::Diverged) << "t0 = " << c.t0;
        } else {
            ASSERT_TRUE(r.t) << "t0 = " << c.t0 << " status " << hit_status_name(r.status);
            EXPECT_NEAR(*r.t, roots[static_cast<std::size_t>(c.root)], 1e-12) << "t0 = " << c.t0;
        }
        EXPECT_EQ(log.newton_iterates.front(), c.t0);
        EXPECT_LE(counters.evaluations(), 64u);  // bounded: it never loops
    }
}

TEST(WorkedExample, SoftObjectsRootsAreFoundByEveryGuaranteedMethod) {
    Subject s("soft_objects.zs");
    const std::vector<double> reference = sampled_roots(s);
    ASSERT_GE(reference.size(), 2u);
    for (const Method m : guaranteed) {
        const std::vector<double> hits = s.all_hits(m);
        ASSERT_EQ(hits.size(), reference.size()) << method_name(m);
        for (std::size_t i = 0; i < hits.size(); ++i)
            EXPECT_NEAR(hits[i], reference[i], 1e-9) << method_name(m) << " root " << i;
    }
}

}  // namespace
}  // namespace zeroset
