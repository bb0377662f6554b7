// Swept spheres along a ray: the stretches of s where the ray meets the
// spheres (roots of D), the stationary chords (roots of P), and the spans
// they bound — see swept_sphere.hpp for the derivation.
#include "zeroset/trace/swept_sphere.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "zeroset/math/polynomial.hpp"
#include "zeroset/roots/bernstein.hpp"
#include "zeroset/roots/descartes.hpp"

namespace zeroset {

namespace {

/// Sorts a few elements in place by `less` (std::sort on these small
/// fixed arrays draws GCC 12's false -Warray-bounds).
template <class T, class Less>
void sort_few(T* first, int count, Less less) {
    for (int i = 1; i < count; ++i)
        for (int j = i; j > 0 && less(first[j], first[j - 1]); --j) std::swap(first[j], first[j - 1]);
}

bool finite(const Vec3d& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

/// The power-basis coefficients of a Bézier curve of the given degree.
std::array<Vec3d, 4> power_basis(int degree, const std::array<Vec3d, 4>& p) {
    switch (degree) {
        case 1: return {p[0], p[1] - p[0], Vec3d{}, Vec3d{}};
        case 2: return {p[0], 2.0 * (p[1] - p[0]), p[0] - 2.0 * p[1] + p[2], Vec3d{}};
        default:
            return {p[0], 3.0 * (p[1] - p[0]), 3.0 * (p[0] - 2.0 * p[1] + p[2]),
                    p[3] - 3.0 * p[2] + 3.0 * p[1] - p[0]};
    }
}

/// x[axis] − c(s)[axis], a polynomial in s.
Polynomial offset_from_curve(const SweptSegment& segment, const Vec3d& x, int axis) {
    std::array<double, 4> k{};
    const int n = segment.power_degree();
    for (int i = 0; i <= n; ++i) k[i] = -segment.power()[i][axis];
    k[0] += x[axis];
    return Polynomial::from_coefficients(std::span<const double>(k.data(), static_cast<std::size_t>(n + 1)));
}

/// r(s), a polynomial in s.
Polynomial radius_polynomial(const SweptSegment& segment) {
    return Polynomial::line(segment.radius_from(), segment.radius_to() - segment.radius_from());
}

/// The real roots of c in [t0, t1], isolated by Descartes' rule of signs.
PolynomialRoots isolated_roots(const Polynomial& c, double t0, double t1, std::span<double> out) {
    return descartes_roots(c.coefficients(), t0, t1, out);
}

/// Where the ray, o + t·d with A = d·d, meets the sphere at s.
struct Chord {
    double discriminant;  // D(s); the ray misses the sphere where it is negative
    double noise;         // a bound on the rounding of D: 8 ulps of the terms it sums
    double t_in;          // valid when discriminant ≥ 0 (clamped to 0 by chord_at)
    double t_out;
};

Chord chord_at(const SweptSegment& segment, const Ray& ray, double a, double s) {
    const Vec3d w = ray.origin - segment.center(s);
    const double r = segment.radius(s);
    const double b = dot(ray.dir, w);
    const double c = dot(w, w) - r * r;
    const double d = b * b - a * c;
    // The stable pair of roots of a·t² + 2b·t + c: q/a and c/q with q = −(b ± √D).
    const double noise = 8.0 * std::numeric_limits<double>::epsilon() * (b * b + a * (dot(w, w) + r * r));
    // The plain formula: the ray is centred near the segment, so t is small
    // and needs no stable form — which, at a clamped D with b ≈ 0, would
    // divide rounding noise by rounding noise.
    const double root = std::sqrt(std::max(d, 0.0));
    return {d, noise, (-b - root) / a, (-b + root) / a};
}

/// The signs of t_in′ and t_out′ at s, as φ_in = 2 B′ t_in + C′ (t_in′ has
/// its sign) and φ_out = 2 B′ t_out + C′ (t_out′ has the opposite sign);
/// nothing where the ray misses the sphere at s.
std::optional<std::array<double, 2>> turning(const SweptSegment& segment, const Ray& ray, double a, double s) {
    const Chord ch = chord_at(segment, ray, a, s);
    if (!(ch.discriminant > 0.0)) return std::nullopt;
    const auto& k = segment.power();
    Vec3d tangent{};  // c′(s)
    for (int i = segment.power_degree(); i >= 1; --i) tangent = tangent * s + k[i] * static_cast<double>(i);
    const Vec3d w = ray.origin - segment.center(s);
    const double db = -dot(ray.dir, tangent);
    const double dc = -2.0 * dot(w, tangent) - 2.0 * segment.radius(s) * (segment.radius_to() - segment.radius_from());
    return std::array<double, 2>{2.0 * db * ch.t_in + dc, 2.0 * db * ch.t_out + dc};
}

/// The curve parameters where a stretch's span may end: its ends, roots and turns.
struct Candidates {
    static constexpr int capacity = 64;
    std::array<double, capacity> s{};
    int count = 0;

    void add(double v) {
        if (count < capacity) s[static_cast<std::size_t>(count++)] = v;
    }
    void add_roots(const Polynomial& p, double s0, double s1, int& evaluations) {
        if (p.degree() < 1) return;
        std::array<double, 12> roots{};
        const PolynomialRoots r = isolated_roots(p, s0, s1, std::span<double>(roots));
        evaluations += r.evaluations;
        for (int i = 0; i < r.count; ++i) add(roots[static_cast<std::size_t>(i)]);
    }
    void sort() { sort_few(s.data(), count, [](double x, double y) { return x < y; }); }
    /// Samples (u, v) for φ_in or φ_out turning from negative to positive,
    /// and adds where each turns, bisected.
    void add_turns(const SweptSegment& segment, const Ray& ray, double a, double u, double v, int& evaluations) {
        constexpr int samples = 8;
        for (int which = 0; which < 2; ++which) {
            double previous_s = 0.0;
            bool has_previous = false;
            for (int j = 1; j <= samples; ++j) {
                const double x = u + (v - u) * j / (samples + 1);
                const auto phi = turning(segment, ray, a, x);
                ++evaluations;
                if (!phi) continue;
                const double value = (*phi)[static_cast<std::size_t>(which)];
                if (has_previous && value > 0.0) {
                    // φ was negative at previous_s: bisect the turn.
                    double lo = previous_s, hi = x;
                    for (int step = 0; step < 60 && lo < hi; ++step) {
                        const double mid = 0.5 * (lo + hi);
                        if (mid <= lo || mid >= hi) break;
                        const auto m = turning(segment, ray, a, mid);
                        ++evaluations;
                        if (!m) break;
                        ((*m)[static_cast<std::size_t>(which)] > 0.0 ? hi : lo) = mid;
                    }
                    // A candidate must name a sphere the ray meets.
                    const double turn = 0.5 * (lo + hi);
                    if (chord_at(segment, ray, a, turn).discriminant >= 0.0) add(turn);
                }
                has_previous = value < 0.0;
                previous_s = x;
            }
        }
    }
};

/// A stretch [s0, s1] of s where D ≥ 0 (s0 = s1: the ray only touches).
struct Stretch {
    double s0, s1;
};

/// The stretches of [0, 1] where D ≥ 0, from D's roots there, in order.
int stretches(const SweptSegment& segment, const Ray& ray, double a, const Polynomial& d_poly,
              std::array<Stretch, max_sweep_spans>& out, int& evaluations) {
    std::array<double, 8> roots{};
    int n_roots = 0;
    if (d_poly.degree() >= 1) {
        const PolynomialRoots r = isolated_roots(d_poly, 0.0, 1.0, std::span<double>(roots.data(), 6));
        evaluations += r.evaluations;
        n_roots = r.count;
    }
    // Breakpoints 0, the roots, 1; D's sign on each piece between them.
    std::array<double, 8> at{};
    int n = 0;
    at[n++] = 0.0;
    for (int i = 0; i < n_roots; ++i)
        if (roots[i] > at[n - 1]) at[n++] = roots[i];
    if (at[n - 1] < 1.0) at[n++] = 1.0;
    std::array<bool, 8> positive{};
    for (int i = 0; i + 1 < n; ++i) {
        positive[i] = chord_at(segment, ray, a, 0.5 * (at[i] + at[i + 1])).discriminant > 0.0;
        ++evaluations;
    }
    std::array<Stretch, 16> all{};
    int found = 0;
    const auto add = [&](double s0, double s1) {
        if (found < static_cast<int>(all.size())) all[found++] = {s0, s1};
    };
    for (int i = 0; i + 1 < n; ++i)
        if (positive[i]) add(at[i], at[i + 1]);
    // A root between two negative pieces is a touch, if D there is 0 to
    // within its rounding (a solver may report a near miss as a root); so
    // is an end where D is 0.
    for (int i = 0; i < n; ++i) {
        const bool left = i > 0 && positive[i - 1], right = i + 1 < n && positive[i];
        if (left || right) continue;
        const Chord touch = chord_at(segment, ray, a, at[i]);
        ++evaluations;
        if (touch.discriminant >= -touch.noise) add(at[i], at[i]);
    }
    // In order of s, stretches that meet merged.
    sort_few(all.data(), found, [](const Stretch& x, const Stretch& y) { return x.s0 < y.s0; });
    int count = 0;
    for (int i = 0; i < found; ++i) {
        if (count > 0 && out[count - 1].s1 >= all[i].s0) out[count - 1].s1 = std::max(out[count - 1].s1, all[i].s1);
        else if (count < max_sweep_spans) out[count++] = all[i];
    }
    return count;
}

}  // namespace

SweptSegment::SweptSegment(int degree, const std::array<Vec3d, 4>& control, double radius_from, double radius_to)
    : degree_(degree), control_(control), r0_(radius_from), r1_(radius_to) {
    if (degree < 1 || degree > 3) throw std::invalid_argument("a swept segment's curve must be of degree 1, 2 or 3");
    for (int i = 0; i <= degree; ++i)
        if (!finite(control[i])) throw std::invalid_argument("a swept segment's control points must be finite");
    if (!std::isfinite(r0_) || !std::isfinite(r1_) || r0_ < 0.0 || r1_ < 0.0)
        throw std::invalid_argument("a swept sphere's radius must be finite and not negative");
    if (r0_ == 0.0 && r1_ == 0.0) throw std::invalid_argument("a swept sphere's radius must not be 0 at both ends");
    for (int i = degree + 1; i < 4; ++i) control_[i] = Vec3d{};
    // Squares of lengths (C, D, P) must stay far from overflow.
    const Box3 box = bounds();
    for (int axis = 0; axis < 3; ++axis)
        if (!(std::max(std::abs(box.lo[axis]), std::abs(box.hi[axis])) <= max_sweep_coordinate))
            throw std::invalid_argument("a swept segment must lie within 1e30 of the origin");
    power_ = power_basis(degree, control_);
    // Leading terms at rounding level (a cubic whose control points lie
    // evenly on a line) would make its polynomials' leading coefficients
    // noise: they are dropped, which moves the curve by as little.
    power_degree_ = degree;
    double scale = 0.0;
    for (int i = 1; i <= degree; ++i) scale = std::max(scale, length(power_[i]));
    while (power_degree_ > 1 && length(power_[power_degree_]) <= 64.0 * std::numeric_limits<double>::epsilon() * scale)
        power_[power_degree_--] = Vec3d{};
}

Vec3d SweptSegment::center(double s) const {
    Vec3d c = power_[power_degree_];
    for (int k = power_degree_ - 1; k >= 0; --k) c = c * s + power_[k];
    return c;
}

Box3 SweptSegment::bounds() const {
    Box3 box{control_[0], control_[0]};
    for (int i = 1; i <= degree_; ++i) {
        box.lo = min(box.lo, control_[i]);
        box.hi = max(box.hi, control_[i]);
    }
    const double r = std::max(r0_, r1_);
    box.lo -= Vec3d{r, r, r};
    box.hi += Vec3d{r, r, r};
    return box;
}

SweepSpans sweep_spans(const SweptSegment& segment, const Ray& in) {
    SweepSpans result;
    const double a = dot(in.dir, in.dir);
    if (!(a > 0.0) || !std::isfinite(a)) return result;
    // Centre the ray at its point nearest the segment's box, so that B and C
    // are small there and D = B² − A·C loses little to cancellation.
    const double t_c = dot(segment.bounds().center() - in.origin, in.dir) / a;
    const Ray ray{in.at(t_c), in.dir};

    // w(s) = o − c(s), B = d·w, C = w·w − r², as polynomials in s.
    const std::array<Polynomial, 3> w{offset_from_curve(segment, ray.origin, 0), offset_from_curve(segment, ray.origin, 1),
                                      offset_from_curve(segment, ray.origin, 2)};
    const Polynomial r = radius_polynomial(segment);
    const Polynomial b = Polynomial(ray.dir.x) * w[0] + Polynomial(ray.dir.y) * w[1] + Polynomial(ray.dir.z) * w[2];
    const Polynomial c = w[0] * w[0] + w[1] * w[1] + w[2] * w[2] - r * r;
    const Polynomial pa(a);
    const Polynomial d = b * b - pa * c;

    // Most rays that enter the segment's box miss its spheres: D's Bernstein
    // coefficients on [0, 1] bound it, so all of them negative (beyond the
    // conversion's rounding) prove D < 0 there without solving anything.
    double magnitude = 0.0;
    PolynomialScratch bernstein;
    to_bernstein(d.coefficients(), d.degree(), 0.0, 1.0, bernstein, magnitude);
    ++result.evaluations;
    const double noise = 4.0 * bernstein_noise(d.degree(), magnitude);
    if (std::all_of(bernstein.begin(), bernstein.begin() + d.degree() + 1, [&](double v) { return v < -noise; }))
        return result;

    std::array<Stretch, max_sweep_spans> found{};
    const int n_stretches = stretches(segment, ray, a, d, found, result.evaluations);
    if (n_stretches == 0) return result;

    // The stationary chords: P = A·C′² − 4·B·B′·C′ + 4·B′²·C.
    const Polynomial db = b.derivative(), dc = c.derivative();
    const Polynomial p = pa * dc * dc - Polynomial(4.0) * b * db * dc + Polynomial(4.0) * db * db * c;
    for (int k = 0; k < n_stretches; ++k) {
        const Stretch& st = found[k];
        Candidates s;
        s.add(st.s0);
        s.add(st.s1);
        if (st.s1 > st.s0) {
            // P's roots in the stretch; and B′'s (or C′'s, where B′ ≡ 0),
            // where φ_in and φ_out vanish together and P may not change sign.
            s.add_roots(p, st.s0, st.s1, result.evaluations);
            s.add_roots(db.degree() >= 1 || db[0] != 0.0 ? db : dc, st.s0, st.s1, result.evaluations);
            s.sort();
            // A safeguard for a root the solver lost to rounding (a thin
            // tube's P is tiny against its coefficients): t_in's least and
            // t_out's greatest lie where φ turns from negative to positive;
            // each gap between candidates is sampled for such a turn.
            const int before = s.count;
            for (int i = 0; i + 1 < before; ++i) s.add_turns(segment, ray, a, s.s[i], s.s[i + 1], result.evaluations);
        }
        SweepSpan span{};
        bool first = true;
        for (int i = 0; i < s.count; ++i) {
            const Chord ch = chord_at(segment, ray, a, s.s[i]);
            ++result.evaluations;
            if (first || ch.t_in < span.t_enter) span.t_enter = ch.t_in, span.s_enter = s.s[i];
            if (first || ch.t_out > span.t_exit) span.t_exit = ch.t_out, span.s_exit = s.s[i];
            first = false;
        }
        span.t_enter += t_c;
        span.t_exit += t_c;
        result.spans[result.count++] = span;
    }
    // The stretches' spans may overlap along the ray (the curve turns back): merge them.
    sort_few(result.spans.data(), result.count, [](const SweepSpan& x, const SweepSpan& y) { return x.t_enter < y.t_enter; });
    int merged = 0;
    for (int i = 0; i < result.count; ++i) {
        const SweepSpan& s = result.spans[i];
        if (merged > 0 && s.t_enter <= result.spans[merged - 1].t_exit) {
            SweepSpan& last = result.spans[merged - 1];
            if (s.t_exit > last.t_exit) last.t_exit = s.t_exit, last.s_exit = s.s_exit;
        } else {
            result.spans[merged++] = s;
        }
    }
    result.count = merged;
    return result;
}

double sphere_through(const SweptSegment& segment, const Vec3d& x) {
    // h(s) = |x − c(s)|² − r(s)² is least at an end or where h′(s) = 0.
    const Polynomial r = radius_polynomial(segment);
    Polynomial h = -(r * r);
    for (int axis = 0; axis < 3; ++axis) {
        const Polynomial w = offset_from_curve(segment, x, axis);
        h = h + w * w;
    }
    const auto value = [&](double s) {
        const Vec3d w = x - segment.center(s);
        return dot(w, w) - segment.radius(s) * segment.radius(s);
    };
    double best_s = 0.0, best = value(0.0);
    const auto consider = [&](double s) {
        if (const double v = value(s); v < best) best = v, best_s = s;
    };
    consider(1.0);
    const Polynomial dh = h.derivative();
    if (dh.degree() >= 1) {
        std::array<double, 6> roots{};
        const PolynomialRoots found = descartes_roots(dh.coefficients(), 0.0, 1.0, std::span<double>(roots));
        for (int i = 0; i < found.count; ++i) consider(roots[i]);
    }
    return best_s;
}

}  // namespace zeroset
