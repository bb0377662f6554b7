// make_ray_suite: writes the ray suite (tests/data/ray_suite.tsv) — rays over
// the surfaces of support/ray_suite_surfaces.hpp, each with its first hit
// from the MPFI oracle (support/mpfi_ray_oracle.hpp). Run offline, by hand,
// whenever the suite changes:
//   make_ray_suite tests/data/ray_suite.tsv
// Rays are made in two rounds. The first: random rays, and rays built
// analytically so their special case holds exactly in real arithmetic
// (tangent to a sphere or torus, a hair outside or inside it, through a
// singular point). The second derives rays from the hits the oracle found:
// spans ending a hair before or after the first root, and rays tangent to
// the surface at a hit, or offset a hair outward or inward along its normal.
// Everything is seeded, so the output is the same on every run.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "support/mpfi_ray_oracle.hpp"
#include "support/ray_suite.hpp"
#include "support/ray_suite_surfaces.hpp"
#include "zeroset/expr/evaluator.hpp"

namespace zeroset::test {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// Rays per surface and class.
constexpr int random_outside = 560;  // from outside the bounds, through a random point in them
constexpr int random_inside = 120;   // from a random point of empty space inside the bounds
constexpr int thin_rays = 300;       // aimed at a thin feature (thin surfaces only)
constexpr int exact_grazes = 110;    // tangent in exact arithmetic (spheres, tori)
constexpr int exact_offsets = 40;    // each of near_miss and shallow, for the exact families
constexpr int singular_rays = 16;    // through a singular point (the heart)
constexpr int near_end_rays = 50;    // each of near_t0 and near_t1
constexpr int past_end_rays = 30;    // the first root a hair past t1
constexpr int derived_grazes = 80;   // tangent at a hit, to double rounding
constexpr int derived_misses = 50;   // a hair outside a hit, along the normal
constexpr int derived_dips = 40;     // a hair inside a hit

struct Candidate {
    std::size_t surface;
    Ray ray;
    Span span;
    std::string ray_class;
};

struct Solved {
    Candidate candidate;
    std::vector<OracleRoot> roots;  // the first root and the next one, if any
    bool kept = false;              // the ray starts outside the solid and the oracle answered
};

/// Deterministic random numbers from raw generator bits (portable across libraries).
class Random {
public:
    explicit Random(std::uint64_t seed) : rng_(seed) {}
    double unit() { return static_cast<double>(rng_() >> 11) * 0x1p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    int integer(int lo, int hi) { return lo + static_cast<int>(rng_() % static_cast<std::uint64_t>(hi - lo + 1)); }
    bool coin() { return (rng_() & 1) != 0; }
    /// 10^u for u uniform in [lo, hi].
    double log_uniform(double lo, double hi) { return std::pow(10.0, uniform(lo, hi)); }
    Vec3d unit_vector() {
        const double z = uniform(-1.0, 1.0), phi = uniform(0.0, 2.0 * std::numbers::pi);
        const double s = std::sqrt(1.0 - z * z);
        return {s * std::cos(phi), s * std::sin(phi), z};
    }
    Vec3d in_box(const Box3& b) { return {uniform(b.lo.x, b.hi.x), uniform(b.lo.y, b.hi.y), uniform(b.lo.z, b.hi.z)}; }

private:
    std::mt19937_64 rng_;
};

/// v rounded to 6 decimals: short to write, and random rays need no more.
Vec3d short_decimal(const Vec3d& v) {
    const auto r = [](double c) { return std::round(c * 1e6) / 1e6; };
    return {r(v.x), r(v.y), r(v.z)};
}

/// True when o + k·d equals p exactly (checked at 300 bits, where it is exact).
bool reaches_exactly(const Ray& ray, double k, const Vec3d& p) {
    mpfr_t v;
    mpfr_init2(v, 300);
    bool exact = true;
    for (int axis = 0; axis < 3; ++axis) {
        mpfr_set_d(v, ray.dir[axis], MPFR_RNDN);
        mpfr_mul_d(v, v, k, MPFR_RNDN);
        mpfr_add_d(v, v, ray.origin[axis], MPFR_RNDN);
        exact = exact && mpfr_cmp_d(v, p[axis]) == 0;
    }
    mpfr_clear(v);
    return exact;
}

/// True when a − b == c exactly.
bool difference_is(double a, double b, double c) {
    mpfr_t v;
    mpfr_init2(v, 300);
    mpfr_set_d(v, a, MPFR_RNDN);
    mpfr_sub_d(v, v, b, MPFR_RNDN);
    const bool exact = mpfr_cmp_d(v, c) == 0;
    mpfr_clear(v);
    return exact;
}

class Builder {
public:
    Builder(std::size_t index, const SuiteSurface& surface)
        : index_(index), surface_(surface), rng_(0x5eed0000ULL + index), box_(surface.bounds.enclosing_box()) {}

    std::vector<Candidate> first_round() {
        const SuiteFeatures& features = surface_.features;
        for (int i = 0; i < random_outside; ++i) random_from_outside();
        for (int i = 0; i < random_inside; ++i) random_from_inside();
        if (surface_.name == "thin_torus")
            for (int i = 0; i < thin_rays; ++i) through_thin_torus(features.tori.front());
        if (surface_.name == "thin_disk")
            for (int i = 0; i < thin_rays; ++i) through_thin_disk();
        if (!features.spheres.empty()) {
            for (int i = 0; i < exact_grazes; ++i) sphere_graze(features.spheres[i % features.spheres.size()]);
            for (int i = 0; i < 2 * exact_offsets; ++i)
                sphere_offset(features.spheres[i % features.spheres.size()], i % 2 == 0);
        }
        for (const TorusFeature& torus : features.tori) {
            for (int i = 0; i < exact_grazes; ++i) torus_graze(torus, i);
            for (int i = 0; i < 2 * exact_offsets; ++i) torus_offset(torus, i % 2 == 0);
        }
        for (int i = 0; i < singular_rays && !features.singular_points.empty(); ++i)
            through_singular_point(features.singular_points[i % features.singular_points.size()], i);
        if (surface_.name == "sphere" || surface_.name == "blinn" || surface_.name == "soft")
            add({{-4.91, -0.67, 0.364}, normalize(Vec3d{0.981, 0.174, 0.0872})}, "survey");  // the survey's Fig. 1 ray
        return std::exchange(out_, {});
    }

    /// Rays derived from the first round's simple hits, taken in turn.
    std::vector<Candidate> second_round(const std::vector<Solved>& solved) {
        std::vector<const Solved*> sources;
        for (const Solved& s : solved) {
            const std::string& c = s.candidate.ray_class;
            if (s.kept && s.candidate.surface == index_ && !s.roots.empty() && s.roots[0].kind == RootKind::Simple &&
                (c == "random" || c == "inside" || c == "thin"))
                sources.push_back(&s);
        }
        if (sources.empty()) return {};
        Evaluator<Dual<double>> gradient(tape_);
        std::size_t next = 0;
        const auto source = [&]() -> const Solved& { return *sources[next++ % sources.size()]; };
        for (int i = 0; i < near_end_rays; ++i) near_end(source(), Derived::NearT0);
        for (int i = 0; i < near_end_rays; ++i) near_end(source(), Derived::NearT1);
        for (int i = 0; i < past_end_rays; ++i) near_end(source(), Derived::PastT1);
        // A planar face makes a tangent ray lie in the surface: no graze there.
        if (surface_.name != "thin_disk")
            for (int i = 0; i < derived_grazes; ++i) at_hit(source(), gradient, Derived::Graze);
        for (int i = 0; i < derived_misses; ++i) at_hit(source(), gradient, Derived::NearMiss);
        for (int i = 0; i < derived_dips; ++i) at_hit(source(), gradient, Derived::Shallow);
        return std::exchange(out_, {});
    }

private:
    void add(const Ray& ray, const std::string& ray_class) {
        const auto span = surface_.bounds.clip(ray, 0.0, inf);
        if (span && span->t1 > span->t0) out_.push_back({index_, ray, *span, ray_class});
    }
    void add(const Ray& ray, Span span, const std::string& ray_class) {
        out_.push_back({index_, ray, span, ray_class});
    }

    [[nodiscard]] double half_diagonal() const { return 0.5 * box_.diagonal(); }

    void random_from_outside() {
        const Vec3d origin = short_decimal(box_.center() + rng_.unit_vector() * (1.5 * half_diagonal()));
        add({origin, normalize(rng_.in_box(box_) - origin)}, "random");
    }

    void random_from_inside() {
        Evaluator<double> f(tape_);
        for (int attempt = 0; attempt < 1000; ++attempt) {
            const Vec3d origin = short_decimal(rng_.in_box(box_));
            if (f(origin.x, origin.y, origin.z) > 1e-3) {  // clearly in empty space
                add({origin, rng_.unit_vector()}, "inside");
                return;
            }
        }
    }

    /// A ray from outside through `target`, in a random direction.
    void aim_at(const Vec3d& target, const Vec3d& dir, const std::string& ray_class) {
        add({short_decimal(target - dir * (1.5 * half_diagonal())), dir}, ray_class);
    }

    void through_thin_torus(const TorusFeature& torus) {
        const double phi = rng_.uniform(0.0, 2.0 * std::numbers::pi);
        const double radial = torus.major + rng_.uniform(-0.5, 0.5) * torus.minor;
        const Vec3d target{radial * std::cos(phi), radial * std::sin(phi), rng_.uniform(-0.5, 0.5) * torus.minor};
        aim_at(target, rng_.unit_vector(), "thin");
    }

    /// A ray through the disk of ray_suite_surfaces.cpp (unit radius, normal (2, 1, 2)/3).
    void through_thin_disk() {
        const Vec3d n = normalize(Vec3d{2, 1, 2});
        const Vec3d u = normalize(Vec3d{1, 0, -1});
        const Vec3d v = cross(n, u);
        const double radius = 0.95 * std::sqrt(rng_.unit()), phi = rng_.uniform(0.0, 2.0 * std::numbers::pi);
        const Vec3d target = u * (radius * std::cos(phi)) + v * (radius * std::sin(phi));
        // Half of the rays come in at a glancing angle, within ~6° of the disk's plane.
        Vec3d dir = rng_.unit_vector();
        if (rng_.coin()) dir = normalize(u * std::cos(phi) + v * std::sin(phi) + n * rng_.uniform(-0.1, 0.1));
        aim_at(target, dir, "thin");
    }

    /// A ray in the tangent plane x[a] = c[a] ± r through the touching point,
    /// exact: the in-plane direction has a 12-bit component and the origin is
    /// checked to reach the point exactly.
    void sphere_graze(const SphereFeature& s) {
        for (int attempt = 0; attempt < 1000; ++attempt) {
            const int a = rng_.integer(0, 2);
            const double side = rng_.coin() ? 1.0 : -1.0;
            Vec3d p = s.center;
            p[a] = s.center[a] + side * s.radius;
            if (!difference_is(p[a], s.center[a], side * s.radius)) continue;
            const int u = (a + rng_.integer(1, 2)) % 3, w = 3 - a - u;
            Vec3d d{0, 0, 0};
            d[u] = rng_.integer(-3900, 3900) / 4096.0;
            d[w] = (rng_.coin() ? 1.0 : -1.0) * std::sqrt(1.0 - d[u] * d[u]);
            const double k = std::ldexp(1.0, rng_.integer(-2, 2));
            const Ray ray{p - d * k, d};
            if (!reaches_exactly(ray, k, p)) continue;
            add(ray, "graze");
            return;
        }
        throw std::runtime_error("no exact sphere graze found for " + surface_.name);
    }

    /// A ray in the plane x[a] = c[a] ± (r + ε) (near_miss) or ± (r − ε) (shallow).
    void sphere_offset(const SphereFeature& s, bool outside) {
        const int a = rng_.integer(0, 2);
        const double side = rng_.coin() ? 1.0 : -1.0;
        const double eps = surface_.scale() * rng_.log_uniform(-12.0, -3.0);
        Vec3d p = s.center;
        p[a] = s.center[a] + side * (outside ? s.radius + eps : s.radius - eps);
        Vec3d d = rng_.unit_vector();
        d[a] = 0.0;
        d = normalize(d);
        add({p - d * (rng_.uniform(0.5, 1.5) * half_diagonal()), d}, outside ? "near_miss" : "shallow");
    }

    /// Rays touching the torus exactly: in the plane z = ±r across the circle
    /// ρ = R (a double root at each crossing), along the outer equator, and
    /// tangent to the circle ρ = R in the plane z = ±r (a fourth-order contact).
    void torus_graze(const TorusFeature& t, int i) {
        const double far = 1.5 * half_diagonal();
        if (i < 8) {  // axis-aligned: along the outer equator, or tangent to the circle ρ = R at z = ±r
            const bool circle = (i & 4) != 0;
            const double offset = ((i & 1) != 0 ? -1.0 : 1.0) * (circle ? t.major : t.major + t.minor);
            const double z = circle ? (rng_.coin() ? t.minor : -t.minor) : 0.0;
            add((i & 2) != 0 ? Ray{{-far, offset, z}, {1, 0, 0}} : Ray{{offset, -far, z}, {0, 1, 0}}, "graze");
            return;
        }
        const double phi = rng_.uniform(0.0, 2.0 * std::numbers::pi);
        const double b = t.major * rng_.uniform(-0.95, 0.95);  // the line's distance from the axis
        const Vec3d d{std::cos(phi), std::sin(phi), 0.0};
        const double z = rng_.coin() ? t.minor : -t.minor;
        add({{-b * d.y - far * d.x, b * d.x - far * d.y, z}, d}, "graze");
    }

    /// Rays in the plane z = ±(r + ε) (near_miss) or ±(r − ε) (shallow).
    void torus_offset(const TorusFeature& t, bool outside) {
        const double eps = std::min(0.5 * t.minor, surface_.scale() * rng_.log_uniform(-12.0, -3.0));
        const double z = (rng_.coin() ? 1.0 : -1.0) * (outside ? t.minor + eps : t.minor - eps);
        const double phi = rng_.uniform(0.0, 2.0 * std::numbers::pi);
        const double b = t.major * rng_.uniform(-0.95, 0.95);
        const Vec3d d{std::cos(phi), std::sin(phi), 0.0};
        const double far = 1.5 * half_diagonal();
        add({{-b * d.y - far * d.x, b * d.x - far * d.y, z}, d}, outside ? "near_miss" : "shallow");
    }

    /// Rays through a singular point p exactly: along the z-axis from
    /// outside, or with 12-bit x and z components (so p − k·d is exact).
    void through_singular_point(const Vec3d& p, int i) {
        if (i < 2) {
            const double side = p.z > 0 ? 1.0 : -1.0;
            add({{p.x, p.y, p.z + 2.0 * side}, {0, 0, -side}}, "singular");
            return;
        }
        for (int attempt = 0; attempt < 1000; ++attempt) {
            Vec3d d{rng_.integer(-2800, 2800) / 4096.0, 0.0, rng_.integer(-2800, 2800) / 4096.0};
            d.y = (rng_.coin() ? 1.0 : -1.0) * std::sqrt(1.0 - d.x * d.x - d.z * d.z);
            const double k = std::ldexp(1.0, rng_.integer(0, 1));
            const Ray ray{p - d * k, d};
            if (!reaches_exactly(ray, k, p)) continue;
            add(ray, "singular");
            return;
        }
        throw std::runtime_error("no exact singular ray found for " + surface_.name);
    }

    enum class Derived { NearT0, NearT1, PastT1, Graze, NearMiss, Shallow };

    /// The source's span cut a hair (1e-13 … 1e-9 × scale) before or after its first root.
    void near_end(const Solved& source, Derived what) {
        const Ray& ray = source.candidate.ray;
        const Span span = source.candidate.span;
        const double t = source.roots[0].t;
        const double delta = surface_.scale() * rng_.log_uniform(-13.0, -9.0);
        if (what == Derived::NearT0 && t - delta > span.t0) add(ray, {t - delta, span.t1}, "near_t0");
        if (what == Derived::NearT1 && t + delta < span.t1) add(ray, {span.t0, t + delta}, "near_t1");
        if (what == Derived::PastT1 && t - delta > span.t0) add(ray, {span.t0, t - delta}, "past_t1");
    }

    /// A ray tangent to the surface at the source's hit point (to double
    /// rounding), or passing 1e-10 … 1e-4 × scale outside or inside it along
    /// the normal.
    void at_hit(const Solved& source, Evaluator<Dual<double>>& gradient, Derived what) {
        const Vec3d p = source.candidate.ray.at(source.roots[0].t);
        const Dual<double> g = evaluate_gradient(gradient, p);
        const double g_length = length(g.g);
        if (!(g_length > 0.0) || !std::isfinite(g_length)) return;
        const Vec3d normal = g.g / g_length;
        const Vec3d tangent = cross(normal, rng_.unit_vector());
        if (length(tangent) < 0.1) return;
        const Vec3d d = normalize(tangent);
        const double back = rng_.uniform(0.5, 1.2) * half_diagonal();
        const double eps = surface_.scale() * rng_.log_uniform(-10.0, -4.0);
        if (what == Derived::Graze) add({p - d * back, d}, "graze_approx");
        if (what == Derived::NearMiss) add({p + normal * eps - d * back, d}, "near_miss");
        if (what == Derived::Shallow) add({p - normal * eps - d * back, d}, "shallow");
    }

    std::size_t index_;
    const SuiteSurface& surface_;
    Random rng_;
    Box3 box_;
    Tape tape_{surface_.f};
    std::vector<Candidate> out_;
};

/// Solves every candidate with the oracle on `threads` threads (one oracle
/// per surface per thread); returns the number of evaluations of H spent.
std::uint64_t solve(std::vector<Solved>& work, unsigned threads) {
    const auto& surfaces = ray_suite_surfaces();
    std::atomic<std::size_t> next{0};
    std::atomic<int> failures{0};
    std::atomic<std::uint64_t> evaluations{0};
    const auto worker = [&] {
        std::vector<std::unique_ptr<MpfiRayOracle>> oracles(surfaces.size());
        for (std::size_t i = next++; i < work.size(); i = next++) {
            Solved& s = work[i];
            const Candidate& c = s.candidate;
            auto& oracle = oracles[c.surface];
            if (!oracle) oracle = std::make_unique<MpfiRayOracle>(surfaces[c.surface].f, surfaces[c.surface].scale());
            if (oracle->sign(c.ray, c.span.t0) != 1) continue;  // starts inside or on the surface
            try {
                s.roots = oracle->all_roots(c.ray, c.span, 2);
                s.kept = true;
            } catch (const std::runtime_error&) {
                ++failures;
            }
        }
        for (const auto& oracle : oracles)
            if (oracle) evaluations += oracle->evaluations();
    };
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    if (failures > 0) std::fprintf(stderr, "make_ray_suite: %d rays dropped (oracle budget)\n", failures.load());
    return evaluations;
}

std::vector<Solved> to_work(const std::vector<Candidate>& candidates) {
    std::vector<Solved> work;
    for (const Candidate& c : candidates) work.push_back({c, {}, false});
    return work;
}

SuiteRay to_suite_ray(const Solved& s) {
    const SuiteSurface& surface = ray_suite_surfaces()[s.candidate.surface];
    SuiteRay r;
    r.surface = surface.name;
    r.ray = s.candidate.ray;
    r.span = s.candidate.span;
    r.scale = surface.scale();
    r.ray_class = s.candidate.ray_class;
    if (!s.roots.empty()) {
        const OracleRoot& first = s.roots[0];
        r.t_ref = first.t;
        r.kind = first.kind == RootKind::Simple     ? RefKind::Simple
                 : first.kind == RootKind::Multiple ? RefKind::Multiple
                                                    : RefKind::Tangent;
        r.slope = first.slope;
        if (s.roots.size() > 1) r.t_next = s.roots[1].t;
    }
    return r;
}

int run(const std::filesystem::path& output, unsigned threads) {
    const auto start = std::chrono::steady_clock::now();
    const auto& surfaces = ray_suite_surfaces();
    std::vector<Builder> builders;
    builders.reserve(surfaces.size());
    for (std::size_t i = 0; i < surfaces.size(); ++i) builders.emplace_back(i, surfaces[i]);

    std::vector<Candidate> first;
    for (Builder& b : builders)
        for (Candidate& c : b.first_round()) first.push_back(std::move(c));
    std::vector<Solved> solved = to_work(first);
    std::uint64_t evaluations = solve(solved, threads);

    std::vector<Candidate> second;
    for (Builder& b : builders)
        for (Candidate& c : b.second_round(solved)) second.push_back(std::move(c));
    std::vector<Solved> derived = to_work(second);
    evaluations += solve(derived, threads);
    solved.insert(solved.end(), derived.begin(), derived.end());

    // Rows grouped by surface, in the order they were made.
    std::vector<SuiteRay> rows;
    std::map<std::string, std::map<std::string, int>> counts;  // surface → kind/class → rays
    for (std::size_t surface = 0; surface < surfaces.size(); ++surface) {
        for (const Solved& s : solved) {
            if (!s.kept || s.candidate.surface != surface) continue;
            rows.push_back(to_suite_ray(s));
            ++counts[rows.back().surface][std::string(ref_kind_name(rows.back().kind))];
            ++counts[rows.back().surface]["class " + rows.back().ray_class];
        }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const std::filesystem::path partial = output.string() + ".partial";
    {
        std::ofstream out(partial);
        out << "# zeroset ray suite: rays with rigorous first-hit references, for the ray-intersection tests.\n"
               "# Made by tests/tools/make_ray_suite.cpp (do not edit by hand); described in tests/data/README.md.\n"
               "# Oracle: MPFI at 200 bits (tests/support/mpfi_ray_oracle.hpp); simple roots are enclosed to\n"
               "# 1e-30 x scale, and bisection goes down to 1e-13 x scale where H' may vanish.\n"
               "# One ray per line, tab-separated: surface (tests/support/ray_suite_surfaces.cpp); origin ox oy oz;\n"
               "# unit direction dx dy dz; span t0 t1 (the query: the first root of f(o + t d) in [t0, t1]);\n"
               "# t_ref (that root, 17 significant digits, or none); kind (simple | multiple | tangent | none);\n"
               "# scale (the bounds' diagonal); class (how the ray was made); slope (|H'(t_ref)| for a simple\n"
               "# root, else 0); t_next (the next root in [t0, t1], or none).\n"
               "# Surfaces:\n";
        for (const SuiteSurface& s : surfaces) out << "#   " << s.name << ": " << s.description << '\n';
        char line[160];
        std::snprintf(line, sizeof line, "# %zu rays, %.2g evaluations of H, generated in %.1f s on %u threads.\n",
                      rows.size(), static_cast<double>(evaluations), seconds, threads);
        out << line << ray_suite_columns() << '\n';
        for (const SuiteRay& r : rows) out << format_suite_ray(r) << '\n';
        if (!out) throw std::runtime_error("cannot write " + partial.string());
    }
    std::filesystem::rename(partial, output);

    for (const auto& [surface, tally] : counts) {
        std::fprintf(stderr, "%-11s", surface.c_str());
        for (const auto& [what, n] : tally) std::fprintf(stderr, " %s=%d", what.c_str(), n);
        std::fprintf(stderr, "\n");
    }
    std::fprintf(stderr, "make_ray_suite: %zu rays, %.2g evaluations of H, %.1f s\n", rows.size(),
                 static_cast<double>(evaluations), seconds);
    return 0;
}

}  // namespace
}  // namespace zeroset::test

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: make_ray_suite OUTPUT.tsv [THREADS]\n");
        return 2;
    }
    try {
        const unsigned threads = argc == 3 ? static_cast<unsigned>(std::stoul(argv[2])) : 2U;
        return zeroset::test::run(argv[1], std::max(1U, threads));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_ray_suite: %s\n", e.what());
        return 1;
    }
}
