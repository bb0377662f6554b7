// The deformations' forward maps, frames and the builders of f∘D⁻¹.
#include "zeroset/expr/deform.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace zeroset {

namespace {

Vec3d unit(const Vec3d& v, const char* what) {
    const double n = length(v);
    if (!(n > 0.0) || !std::isfinite(n))
        throw std::invalid_argument(std::string(what) + " must be a nonzero finite vector");
    return v / n;
}

void check_finite(double v, const char* what) {
    if (!std::isfinite(v)) throw std::invalid_argument(std::string(what) + " must be finite");
}

/// M·p for the point p: the constant first, then only the nonzero terms.
ExprPoint apply(const Mat4& m, const ExprPoint& p) {
    ExprPoint r;
    for (int i = 0; i < 3; ++i) {
        Expr sum(m.m[i][3]);
        for (int j = 0; j < 3; ++j)
            if (m.m[i][j] != 0.0) sum = sum + (m.m[i][j] == 1.0 ? p[j] : m.m[i][j] == -1.0 ? -p[j] : m.m[i][j] * p[j]);
        r[i] = sum;
    }
    return r;
}

}  // namespace

Frame Frame::around(const Vec3d& axis) {
    const Vec3d a = unit(axis, "the axis");
    int largest = 0;
    for (int i = 1; i < 3; ++i)
        if (std::abs(a[i]) > std::abs(a[largest])) largest = i;
    Vec3d helper{};
    helper[(largest + 1) % 3] = 1.0;
    const Vec3d b = normalize(helper - a * dot(a, helper));
    return {{a, b, cross(a, b)}};
}

Frame Frame::spanned_by(const Vec3d& first, const Vec3d& second) {
    const Vec3d a = unit(first, "the first axis");
    const Vec3d s = unit(second, "the second axis");
    const Vec3d b = s - a * dot(a, s);
    if (!(length(b) > 1e-9)) throw std::invalid_argument("the two axes must not be parallel");
    const Vec3d t = normalize(b);
    return {{a, t, cross(a, t)}};
}

Taper::Taper(const Vec3d& axis, double rate_) : frame(Frame::around(axis)), rate(rate_) {
    check_finite(rate, "the taper rate");
}

Vec3d Taper::forward(const Vec3d& p) const {
    const double h = dot(p, frame.e[0]), r = 1.0 + rate * h;
    return frame.point<double>({h, r * dot(p, frame.e[1]), r * dot(p, frame.e[2])});
}

Twist::Twist(const Vec3d& axis, double rate_) : frame(Frame::around(axis)), rate(rate_) {
    check_finite(rate, "the twist rate");
}

Vec3d Twist::forward(const Vec3d& p) const {
    const double h = dot(p, frame.e[0]), c1 = dot(p, frame.e[1]), c2 = dot(p, frame.e[2]);
    const double c = std::cos(rate * h), s = std::sin(rate * h);
    return frame.point<double>({h, c1 * c - c2 * s, c1 * s + c2 * c});
}

Bend::Bend(const Vec3d& along, const Vec3d& toward, double rate_, double lo_, double hi_)
    : frame(Frame::spanned_by(along, toward)), rate(rate_), lo(lo_), hi(hi_) {
    check_finite(rate, "the bend rate");
    if (!(lo <= hi)) throw std::invalid_argument("the bent region must have lo <= hi");
}

Vec3d Bend::forward(const Vec3d& p) const {
    if (rate == 0.0) return p;
    const double u = dot(p, frame.e[0]), v = dot(p, frame.e[1]);
    const double clamped = std::clamp(u, lo, hi), rest = u - clamped;
    const double theta = rate * clamped, c = std::cos(theta), s = std::sin(theta);
    const double half = std::sin(0.5 * theta);
    // (1/rate − v) sin θ and (1 − cos θ)/rate = 2 sin²(θ/2)/rate, kept accurate for small rates.
    const double u1 = s / rate - v * s + rest * c;
    const double v1 = v * c + 2.0 * half * half / rate + rest * s;
    return frame.point<double>({u1, v1, dot(p, frame.e[2])});
}

Expr transform(const Expr& f, const Mat4& inverse) { return substitute(f, apply(inverse, coordinates())); }

Expr translate(const Expr& f, const Vec3d& offset) {
    const ExprPoint p = coordinates();
    return substitute(f, {p.x - offset.x, p.y - offset.y, p.z - offset.z});
}

Expr rotate_degrees(const Expr& f, const Vec3d& angles) {
    const Mat4 d = Mat4::rotate_xyz_degrees(angles);
    return transform(f, d.transpose());  // a rotation's inverse is its transpose, exactly
}

Expr rotate_about(const Expr& f, const Vec3d& axis, double degrees) {
    return transform(f, Mat4::rotate_degrees(unit(axis, "the rotation axis"), degrees).transpose());
}

Expr scale(const Expr& f, double s) {
    if (!(s > 0.0) || !std::isfinite(s)) throw std::invalid_argument("a uniform scale must be positive and finite");
    const ExprPoint p = coordinates();
    return s * substitute(f, {p.x / s, p.y / s, p.z / s});
}

Expr scale(const Expr& f, const Vec3d& s) {
    for (int i = 0; i < 3; ++i)
        if (!(s[i] != 0.0) || !std::isfinite(s[i]))
            throw std::invalid_argument("scale factors must be nonzero and finite");
    const ExprPoint p = coordinates();
    return substitute(f, {p.x / s.x, p.y / s.y, p.z / s.z});
}

Expr taper(const Expr& f, const Taper& taper) { return substitute(f, taper.inverse(coordinates())); }
Expr twist(const Expr& f, const Twist& twist) { return substitute(f, twist.inverse(coordinates())); }
Expr bend(const Expr& f, const Bend& bend) { return substitute(f, bend.inverse(coordinates())); }

}  // namespace zeroset
