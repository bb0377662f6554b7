// Deformations at the function level (survey §9): the deformed surface is
// the zero set of f∘D⁻¹, so each builder substitutes D⁻¹ for the point.
// Affine maps (eq. 36) and Barr's taper, twist and bend ("Global and local
// deformations of solid primitives", SIGGRAPH 1984, §3), each about any axis.
//
// The non-linear ones are small structs: forward() is D on a point, and
// inverse() is D⁻¹, written once for any number type with the expression
// builders' names (double for tests, Expr for the function), so the map that
// is tested is the map that is used. Coordinates are taken in an orthonormal
// frame of the deformation's axes and terms with a zero coefficient are left
// out, so an axis-aligned deformation builds no ×0 clauses and no x − x
// (which would widen every interval enclosure). Only rigid motions keep a
// distance function exact; every other deformation leaves a valid implicit
// function whose Lipschitz bound the interval gradient finds (lipschitz.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <limits>

#include "zeroset/expr/substitute.hpp"
#include "zeroset/math/mat4.hpp"

namespace zeroset {

/// f∘M for the matrix M = D⁻¹ (survey eq. 36: what is stored is the inverse).
Expr transform(const Expr& f, const Mat4& inverse);
/// f moved by `offset`: f(p − offset).
Expr translate(const Expr& f, const Vec3d& offset);
/// f rotated about x, then y, then z, by angles in degrees (right-handed).
Expr rotate_degrees(const Expr& f, const Vec3d& angles);
/// f rotated by `degrees` about `axis` (nonzero) through the origin.
Expr rotate_about(const Expr& f, const Vec3d& axis, double degrees);
/// A uniform scale by s > 0 about the origin, s·f(p/s): an exact distance stays exact.
Expr scale(const Expr& f, double s);
/// A scale by s (nonzero components; negative ones mirror) about the origin,
/// f(p/s). Unless the components are equal this is no longer a distance.
Expr scale(const Expr& f, const Vec3d& s);

/// A right-handed orthonormal frame e[0], e[1], e[2] = e[0] × e[1].
struct Frame {
    std::array<Vec3d, 3> e;

    /// e[0] = the unit axis, e[1], e[2] completing it (for a coordinate axis:
    /// the next two coordinate axes in cyclic order, so z gives x, y).
    static Frame around(const Vec3d& axis);
    /// e[0] = the unit first axis, e[1] = the second made orthogonal to it.
    static Frame spanned_by(const Vec3d& first, const Vec3d& second);

    /// The coordinates p·e[k], without the zero terms.
    template <class T> [[nodiscard]] T coordinate(const Vec3<T>& p, int k) const {
        T r(0.0);
        bool any = false;
        for (int i = 0; i < 3; ++i) {
            if (e[k][i] == 0.0) continue;
            r = any ? r + scaled(e[k][i], p[i]) : scaled(e[k][i], p[i]);
            any = true;
        }
        return r;
    }
    /// The point Σ c[k]·e[k], without the zero terms.
    template <class T> [[nodiscard]] Vec3<T> point(const std::array<T, 3>& c) const {
        Vec3<T> r;
        for (int i = 0; i < 3; ++i) {
            bool any = false;
            for (int k = 0; k < 3; ++k) {
                if (e[k][i] == 0.0) continue;
                r[i] = any ? r[i] + scaled(e[k][i], c[k]) : scaled(e[k][i], c[k]);
                any = true;
            }
        }
        return r;
    }

private:
    template <class T> static T scaled(double c, const T& v) { return c == 1.0 ? v : c == -1.0 ? -v : T(c) * v; }
};

/// Barr's taper about the unit axis a: with h = p·a, the cross-section
/// perpendicular to a is scaled by r(h) = 1 + rate·h,
///   D(p) = h a + r(h) (p − h a),   D⁻¹(p) = h a + (p − h a) / r(h).
/// r must stay positive over the object's bounds (where r ≤ 0 the map folds
/// the cross-section through the axis and f∘D⁻¹ is meaningless).
struct Taper {
    Taper(const Vec3d& axis, double rate);
    Frame frame;  // e[0] = the axis
    double rate;

    [[nodiscard]] Vec3d forward(const Vec3d& p) const;
    template <class T> [[nodiscard]] Vec3<T> inverse(const Vec3<T>& p) const {
        if (rate == 0.0) return p;
        const T h = frame.coordinate(p, 0);
        const T shrink = T(1.0) / (T(1.0) + T(rate) * h);
        return frame.point<T>({h, frame.coordinate(p, 1) * shrink, frame.coordinate(p, 2) * shrink});
    }
};

/// Barr's twist about the unit axis a: the rotation about a by the angle
/// rate·h, h = p·a (radians per unit length, right-handed). A rotation about
/// a keeps h, so D⁻¹ is the rotation by −rate·h.
struct Twist {
    Twist(const Vec3d& axis, double rate);
    Frame frame;  // e[0] = the axis
    double rate;

    [[nodiscard]] Vec3d forward(const Vec3d& p) const;
    template <class T> [[nodiscard]] Vec3<T> inverse(const Vec3<T>& p) const {
        if (rate == 0.0) return p;
        const T h = frame.coordinate(p, 0), c1 = frame.coordinate(p, 1), c2 = frame.coordinate(p, 2);
        const T angle = -(T(rate) * h);
        const T c = cos(angle), s = sin(angle);
        return frame.point<T>({h, c1 * c - c2 * s, c1 * s + c2 * c});
    }
};

/// Barr's bend: the axis `along` (unit a) is bent into a circular arc of
/// curvature `rate` (1/radius, radians per unit length) towards `toward`
/// (t, made orthogonal to a), about the centre of curvature t/rate; the
/// direction a × t is unchanged. With u = p·a, v = p·t, û = clamp(u, lo, hi)
/// and θ = rate·û,
///   D:  u' = (1/rate − v) sin θ + (u − û) cos θ,
///       v' = v cos θ + (1 − cos θ)/rate + (u − û) sin θ
/// — the bent region lo ≤ u ≤ hi (unlimited by default) is wound onto the
/// arc, and beyond it the object continues straight (rigidly), tangent to
/// the arc at its ends; u = 0 stays in place (translate f to bend elsewhere).
/// D⁻¹ in closed form: θ = clamp(atan2(rate·u', 1 − rate·v'), rate·lo, rate·hi)
/// and (u, v) is (u', v') rotated by −θ, moved along the arc:
///   u = u' cos θ + v' sin θ + (θ − sin θ)/rate,
///   v = v' cos θ − u' sin θ + 2 sin²(θ/2)/rate
/// (written so, it stays accurate for small rates). It inverts D where
/// 1 − rate·v > 0 (the near side of the centre of curvature) and the bent
/// part spans |rate·u| < π; the straight continuation needs |rate·lo| and
/// |rate·hi| ≤ π/2. rate = 0 is the identity.
struct Bend {
    static constexpr double unlimited = std::numeric_limits<double>::infinity();
    Bend(const Vec3d& along, const Vec3d& toward, double rate, double lo = -unlimited, double hi = unlimited);
    Frame frame;  // e[0] = along, e[1] = toward
    double rate;
    double lo, hi;

    [[nodiscard]] Vec3d forward(const Vec3d& p) const;
    template <class T> [[nodiscard]] Vec3<T> inverse(const Vec3<T>& p) const {
        if (rate == 0.0) return p;
        const T u = frame.coordinate(p, 0), v = frame.coordinate(p, 1);
        T theta = atan2(T(rate) * u, T(1.0) - T(rate) * v);
        const double theta_lo = std::min(rate * lo, rate * hi), theta_hi = std::max(rate * lo, rate * hi);
        if (theta_lo > -unlimited) theta = max(theta, T(theta_lo));
        if (theta_hi < unlimited) theta = min(theta, T(theta_hi));
        const T c = cos(theta), s = sin(theta), half = sin(T(0.5) * theta);
        return frame.point<T>({u * c + v * s + (theta - s) / T(rate),
                               v * c - u * s + T(2.0) * square(half) / T(rate), frame.coordinate(p, 2)});
    }
};

/// f tapered, twisted or bent: f∘D⁻¹ (see the structs above).
Expr taper(const Expr& f, const Taper& taper);
Expr twist(const Expr& f, const Twist& twist);
Expr bend(const Expr& f, const Bend& bend);

}  // namespace zeroset
