// The ray suite's surfaces: the survey's examples (eqs. 5, 12, 23–24), a
// torus, thin features, CSG, and algebraic surfaces of degree 4 and 6.
#include "support/ray_suite_surfaces.hpp"

#include <stdexcept>

namespace zeroset::test {

namespace {

Bounds box(Vec3d lo, Vec3d hi) { return Bounds::make_box({lo, hi}); }

/// |p − c|² − r²: negative inside the sphere (the survey's eqs. 5–6).
Expr sphere(const SphereFeature& s) {
    const Vec3d c = s.center;
    return square(var_x() - c.x) + square(var_y() - c.y) + square(var_z() - c.z) - s.radius * s.radius;
}

/// Wyvill's soft-object kernel C(r²) (eq. 23, R = 2), 0 from r² = 4 on.
Expr soft_kernel(const Expr& r2) {
    const Expr s = min(r2, Expr(4.0));
    return -powi(s, 3) / 144.0 + 17.0 / 144.0 * square(s) - 11.0 / 18.0 * s + 1.0;
}

/// The torus around the z-axis as a distance: |(ρ − R, z)| − r.
Expr torus(const TorusFeature& t) {
    const Expr rho = sqrt(square(var_x()) + square(var_y()));
    return sqrt(square(rho - t.major) + square(var_z())) - t.minor;
}

std::vector<SuiteSurface> make_surfaces() {
    const Expr x = var_x(), y = var_y(), z = var_z();
    const SphereFeature right{{1.2, 0, 0}, 1.0}, left{{-1.2, 0, 0}, 1.0};
    const Expr f = sphere(right);             // eq. 5
    const Expr g = sphere(left);              // eq. 6
    const Expr r2f = f + 1.0, r2g = g + 1.0;  // squared distances to the centres
    const TorusFeature fat{1.0, 0.375}, thin{1.0, 0x1p-10};
    const SphereFeature a{{-0.5, 0, 0}, 0.75}, b{{0.5, 0.25, 0}, 0.625}, c{{0.75, 0.25, 0.5}, 0.375};
    const Expr plane = (2.0 * x + y + 2.0 * z) / 3.0;
    const Expr gyroid = sin(2.0 * x) * cos(2.0 * y) + sin(2.0 * y) * cos(2.0 * z) + sin(2.0 * z) * cos(2.0 * x);
    const Expr heart_base = square(x) + 2.25 * square(y) + square(z) - 1.0;

    std::vector<SuiteSurface> s;
    s.push_back({"sphere",
                 "the survey's unit sphere at (1.2, 0, 0), eq. 5",
                 f,
                 box({0.0, -1.25, -1.25}, {2.5, 1.25, 1.25}),
                 {{right}, {}, {}}});
    s.push_back({"blinn",
                 "Blinn's blend of the spheres at ±1.2, h = 1 − e^−f − e^−g (eq. 12)",
                 1.0 - exp(-f) - exp(-g),
                 box({-3.5, -2.5, -2.5}, {3.5, 2.5, 2.5}),
                 {}});
    s.push_back({"soft",
                 "Wyvill soft objects at ±1.2, h = 1 − 2C(r²) − 2C(r²) (eqs. 23–24, R = 2, magic 1/2)",
                 1.0 - 2.0 * soft_kernel(r2f) - 2.0 * soft_kernel(r2g),
                 box({-3.0, -2.0, -2.0}, {3.0, 2.0, 2.0}),
                 {}});
    s.push_back({"torus",
                 "torus R = 1, r = 0.375 around z, as a distance",
                 torus(fat),
                 box({-1.5, -1.5, -0.5}, {1.5, 1.5, 0.5}),
                 {{}, {fat}, {}}});
    s.push_back({"thin_torus",
                 "torus R = 1, r = 2^-10 (a thin feature)",
                 torus(thin),
                 box({-1.125, -1.125, -0.125}, {1.125, 1.125, 0.125}),
                 {{}, {thin}, {}}});
    s.push_back({"thin_disk",
                 "unit disk of half-thickness 2^-11, normal (2, 1, 2)/3 (a thin feature)",
                 max(abs(plane) - 0x1p-11, sphere({{0, 0, 0}, 1.0})),
                 box({-1.125, -1.125, -1.125}, {1.125, 1.125, 1.125}),
                 {}});
    s.push_back({"csg",
                 "A ∪ (B − C) for spheres A, B, C (min/max)",
                 min(sphere(a), max(sphere(b), -sphere(c))),
                 box({-1.5, -1.0, -1.0}, {1.5, 1.25, 1.0}),
                 {{a, b}, {}, {}}});
    s.push_back({"tanglecube",
                 "x⁴ − 5x² + y⁴ − 5y² + z⁴ − 5z² + 11.8 (quartic)",
                 powi(x, 4) - 5.0 * square(x) + powi(y, 4) - 5.0 * square(y) + powi(z, 4) - 5.0 * square(z) + 11.8,
                 box({-2.5, -2.5, -2.5}, {2.5, 2.5, 2.5}),
                 {}});
    s.push_back({"gyroid",
                 "gyroid sin 2x cos 2y + sin 2y cos 2z + sin 2z cos 2x in a ball of radius √3",
                 max(gyroid, square(x) + square(y) + square(z) - 3.0),
                 box({-2.0, -2.0, -2.0}, {2.0, 2.0, 2.0}),
                 {}});
    s.push_back({"heart",
                 "Taubin's heart (x² + 9/4 y² + z² − 1)³ − x²z³ − 9/80 y²z³ (sextic, singular at (0, 0, ±1))",
                 powi(heart_base, 3) - square(x) * powi(z, 3) - 9.0 / 80.0 * square(y) * powi(z, 3),
                 box({-1.5, -1.0, -1.25}, {1.5, 1.0, 1.5}),
                 {{}, {}, {{0, 0, 1}, {0, 0, -1}}}});
    return s;
}

}  // namespace

const std::vector<SuiteSurface>& ray_suite_surfaces() {
    static const std::vector<SuiteSurface> surfaces = make_surfaces();
    return surfaces;
}

const SuiteSurface& ray_suite_surface(std::string_view name) {
    for (const SuiteSurface& s : ray_suite_surfaces())
        if (s.name == name) return s;
    throw std::out_of_range("no ray-suite surface called '" + std::string(name) + "'");
}

}  // namespace zeroset::test
