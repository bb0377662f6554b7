// Closed-form roots of degree ≤ 4; see closed_form.hpp for the care taken.
#include "zeroset/roots/closed_form.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "zeroset/math/power_of_two.hpp"

namespace zeroset {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

/// F(t) and F′(t) by Horner's rule.
void evaluate(const double* c, int n, double t, double& f, double& df) {
    f = c[n];
    df = 0.0;
    for (int i = n - 1; i >= 0; --i) {
        df = df * t + f;
        f = f * t + c[i];
    }
}

/// Up to two Newton steps, each kept only if it lowers |F| (so a multiple
/// root, where Newton is slow, is never made worse).
double polish(const double* c, int n, double t) {
    double f = 0.0, df = 0.0;
    evaluate(c, n, t, f, df);
    for (int step = 0; step < 2 && f != 0.0 && df != 0.0; ++step) {
        const double next = t - f / df;
        double f_next = 0.0, df_next = 0.0;
        evaluate(c, n, next, f_next, df_next);
        if (!std::isfinite(next) || !(std::fabs(f_next) < std::fabs(f))) break;
        t = next;
        f = f_next;
        df = df_next;
    }
    return t;
}

int solve_any(const double* c, int n, double* roots);

/// b² − 4ac with the rounding errors of both products added back (Kahan).
double discriminant(double a, double b, double c) {
    const double bb = b * b, ac4 = 4.0 * a * c;
    const double bb_err = std::fma(b, b, -bb), ac4_err = std::fma(4.0 * a, c, -ac4);
    return (bb - ac4) + (bb_err - ac4_err);
}

int quadratic_core(const double* c, double* roots) {
    const double disc = discriminant(c[2], c[1], c[0]);
    if (disc < 0.0) return 0;
    if (disc == 0.0) {
        roots[0] = -c[1] / (2.0 * c[2]);
        return 1;
    }
    const double q = -0.5 * (c[1] + std::copysign(std::sqrt(disc), c[1]));
    int k = 0;
    for (const double r : {q / c[2], c[0] / q})
        if (std::isfinite(r)) roots[k++] = r;
    return k;
}

int cubic_core(const double* c, double* roots) {
    const double a = c[2] / c[3], b = c[1] / c[3], d = c[0] / c[3];
    // t = y − a/3 gives y³ + p·y + q; Q = p/3, R = −q/2, D = Q³ + R².
    const double shift = a / 3.0;
    const double p = b - a * shift;
    const double q = (2.0 / 27.0) * a * a * a - b * shift + d;
    const double Q = p / 3.0, R = -0.5 * q;
    const double D = Q * Q * Q + R * R;
    // A D within its rounding error of 0 is a double root: keep it (a
    // grazing ray). The error comes from forming p and q, so scale by theirs.
    const double p_size = std::fabs(b) + std::fabs(a * shift);
    const double q_size = std::fabs((2.0 / 27.0) * a * a * a) + std::fabs(b * shift) + std::fabs(d);
    const double D_noise = 8.0 * eps * (Q * Q * p_size + std::fabs(R) * q_size);
    if (D < -D_noise) {  // three distinct real roots: the trigonometric form
        const double rho = std::sqrt(-Q);
        const double theta = std::acos(std::clamp(R / (rho * rho * rho), -1.0, 1.0));
        for (int k = 0; k < 3; ++k)
            roots[k] = 2.0 * rho * std::cos((theta + 2.0 * std::numbers::pi * k) / 3.0) - shift;
        return 3;
    }
    // Cardano: u³ = R + sign(R)·√D has no cancellation; v = −Q/u.
    const double u = std::cbrt(R + std::copysign(std::sqrt(std::max(D, 0.0)), R));
    if (u == 0.0) {
        roots[0] = -shift;  // triple root
        return 1;
    }
    roots[0] = u - Q / u - shift;
    if (D > D_noise) return 1;
    roots[1] = -0.5 * (u - Q / u) - shift;  // the double root
    return 2;
}

int quartic_core(const double* c, double* roots) {
    const double a = c[3] / c[4], b = c[2] / c[4], cc = c[1] / c[4], d = c[0] / c[4];
    // t = y − a/4 gives y⁴ + p·y² + q·y + r.
    const double shift = 0.25 * a, a2 = a * a;
    const double p = b - 0.375 * a2;
    const double q = cc - 0.5 * a * b + 0.125 * a2 * a;
    const double r = d - 0.25 * a * cc + 0.0625 * a2 * b - (3.0 / 256.0) * a2 * a2;
    const double q_noise = 4.0 * eps * (std::fabs(cc) + std::fabs(0.5 * a * b) + std::fabs(0.125 * a2 * a));
    int k = 0;
    if (std::fabs(q) <= q_noise) {  // biquadratic: z = y², z² + p·z + r = 0
        const std::array<double, 3> zq{r, p, 1.0};
        std::array<double, 2> z{};
        const int nz = solve_any(zq.data(), 2, z.data());
        for (int i = 0; i < nz; ++i) {
            if (z[i] < 0.0) continue;
            const double y = std::sqrt(z[i]);
            roots[k++] = -y - shift;
            if (y != 0.0) roots[k++] = y - shift;
        }
        return k;
    }
    // Ferrari: the resolvent 8m³ + 8p·m² + (2p² − 8r)·m − q² has a root m > 0
    // (it is −q² < 0 at 0); its largest makes y⁴ + p·y² + q·y + r =
    // (y² + s·y + p/2 + m − q/(2s))·(y² − s·y + p/2 + m + q/(2s)), s = √(2m).
    const std::array<double, 4> resolvent{-q * q, 2.0 * p * p - 8.0 * r, 8.0 * p, 8.0};
    std::array<double, 3> m_roots{};
    const int nm = solve_any(resolvent.data(), 3, m_roots.data());
    if (nm == 0 || !(m_roots[nm - 1] > 0.0)) return 0;
    const double m = m_roots[nm - 1], s = std::sqrt(2.0 * m);
    for (const double sign : {1.0, -1.0}) {
        const std::array<double, 3> factor{0.5 * p + m - sign * q / (2.0 * s), sign * s, 1.0};
        std::array<double, 2> y{};
        const int ny = solve_any(factor.data(), 2, y.data());
        for (int i = 0; i < ny; ++i) roots[k++] = y[i] - shift;
    }
    return k;
}

/// Real roots of c[0..n], n ≤ 4: scaled, degenerations removed, solved,
/// polished on the whole polynomial, sorted and made distinct.
int solve_any(const double* c, int n, double* roots) {
    std::array<double, max_closed_form_degree + 1> s{};
    double largest = 0.0;
    for (int i = 0; i <= n; ++i) largest = std::max(largest, std::fabs(c[i]));
    if (!(largest > 0.0) || !std::isfinite(largest)) return 0;
    const int e = binary_exponent(largest);
    for (int i = 0; i <= n; ++i) s[i] = times_power_of_two(c[i], -e);

    int m = n;
    for (; m > 0; --m) {
        double others = 0.0;
        for (int i = 0; i < m; ++i) others = std::max(others, std::fabs(s[i]));
        if (std::fabs(s[m]) > eps * others) break;
    }
    int k = 0;
    if (m == 0) return 0;
    if (s[0] == 0.0) {
        roots[0] = 0.0;
        k = 1 + solve_any(s.data() + 1, m - 1, roots + 1);
    } else if (m == 1) {
        roots[0] = -s[0] / s[1];
        k = 1;
    } else if (m == 2) {
        k = quadratic_core(s.data(), roots);
    } else if (m == 3) {
        k = cubic_core(s.data(), roots);
    } else {
        k = quartic_core(s.data(), roots);
    }
    for (int i = 0; i < k; ++i) roots[i] = polish(s.data(), n, roots[i]);
    std::sort(roots, roots + k);
    return static_cast<int>(std::unique(roots, roots + k) - roots);
}

}  // namespace

int solve_linear(const double* c, double roots[1]) { return solve_any(c, 1, roots); }
int solve_quadratic(const double* c, double roots[2]) { return solve_any(c, 2, roots); }
int solve_cubic(const double* c, double roots[3]) { return solve_any(c, 3, roots); }
int solve_quartic(const double* c, double roots[4]) { return solve_any(c, 4, roots); }

int solve_closed_form(std::span<const double> c, std::span<double, max_closed_form_degree> roots) {
    if (c.empty() || c.size() > max_closed_form_degree + 1) return 0;
    return solve_any(c.data(), static_cast<int>(c.size()) - 1, roots.data());
}

int closed_form_roots_in(std::span<const double> c, double t0, double t1,
                         std::span<double, max_closed_form_degree> roots) {
    const int n = solve_closed_form(c, roots);
    int k = 0;
    for (int i = 0; i < n; ++i)
        if (t0 <= roots[i] && roots[i] <= t1) roots[k++] = roots[i];
    return k;
}

std::optional<double> closed_form_first_root(std::span<const double> c, double t0, double t1) {
    std::array<double, max_closed_form_degree> roots{};
    if (closed_form_roots_in(c, t0, t1, roots) == 0) return std::nullopt;
    return roots[0];
}

}  // namespace zeroset
