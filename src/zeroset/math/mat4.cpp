// Mat4 arithmetic; the inverse uses Gauss–Jordan elimination with partial pivoting.
#include "zeroset/math/mat4.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <utility>

namespace zeroset {

Mat4 Mat4::identity() {
    Mat4 r;
    for (int i = 0; i < 4; ++i) r.m[i][i] = 1.0;
    return r;
}

Mat4 Mat4::translate(const Vec3d& t) {
    Mat4 r = identity();
    r.m[0][3] = t.x;
    r.m[1][3] = t.y;
    r.m[2][3] = t.z;
    return r;
}

Mat4 Mat4::scale(const Vec3d& s) {
    Mat4 r = identity();
    r.m[0][0] = s.x;
    r.m[1][1] = s.y;
    r.m[2][2] = s.z;
    return r;
}

namespace {

/// Rodrigues' rotation about the axis, from the angle's cosine and sine.
Mat4 rotation(const Vec3d& axis, double c, double s) {
    const Vec3d a = normalize(axis);
    const double k = 1.0 - c;
    Mat4 r = Mat4::identity();
    r.m[0] = {c + a.x * a.x * k, a.x * a.y * k - a.z * s, a.x * a.z * k + a.y * s, 0.0};
    r.m[1] = {a.y * a.x * k + a.z * s, c + a.y * a.y * k, a.y * a.z * k - a.x * s, 0.0};
    r.m[2] = {a.z * a.x * k - a.y * s, a.z * a.y * k + a.x * s, c + a.z * a.z * k, 0.0};
    return r;
}

}  // namespace

Mat4 Mat4::rotate(const Vec3d& axis, double radians) { return rotation(axis, std::cos(radians), std::sin(radians)); }

Mat4 Mat4::rotate_degrees(const Vec3d& axis, double degrees) {
    const double turns = degrees / 90.0;
    if (turns == std::round(turns) && std::abs(turns) < 1e15) {
        static constexpr double cosines[] = {1, 0, -1, 0}, sines[] = {0, 1, 0, -1};
        const auto quarter = static_cast<std::size_t>(((static_cast<long long>(turns) % 4) + 4) % 4);
        return rotation(axis, cosines[quarter], sines[quarter]);
    }
    const double radians = degrees * (std::numbers::pi / 180.0);
    return rotation(axis, std::cos(radians), std::sin(radians));
}

Mat4 Mat4::operator*(const Mat4& o) const {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double sum = 0.0;
            for (int k = 0; k < 4; ++k) sum += m[i][k] * o.m[k][j];
            r.m[i][j] = sum;
        }
    return r;
}

Mat4 Mat4::transpose() const {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = m[j][i];
    return r;
}

std::optional<Mat4> Mat4::inverse() const {
    Mat4 a = *this;
    Mat4 inv = identity();
    // Each row's largest entry of the linear part (a translation, however
    // large, does not make a map singular). Rows that are dependent up to
    // rounding leave a pivot of rounding-error size *relative to its row*,
    // not an exact 0, so singularity is judged against the row's scale.
    std::array<double, 4> row_scale{};
    for (int row = 0; row < 4; ++row) {
        for (int col = 0; col < 3; ++col) row_scale[row] = std::max(row_scale[row], std::abs(a.m[row][col]));
        if (row_scale[row] == 0.0) row_scale[row] = std::abs(a.m[row][3]);  // the affine row (0, 0, 0, 1)
    }
    for (int col = 0; col < 4; ++col) {
        int pivot = col;
        for (int row = col + 1; row < 4; ++row)
            if (std::abs(a.m[row][col]) > std::abs(a.m[pivot][col])) pivot = row;
        if (!(std::abs(a.m[pivot][col]) > 1e-12 * row_scale[pivot])) return std::nullopt;
        std::swap(a.m[col], a.m[pivot]);
        std::swap(inv.m[col], inv.m[pivot]);
        std::swap(row_scale[col], row_scale[pivot]);
        const double scale = 1.0 / a.m[col][col];
        for (int j = 0; j < 4; ++j) {
            a.m[col][j] *= scale;
            inv.m[col][j] *= scale;
        }
        for (int row = 0; row < 4; ++row) {
            if (row == col) continue;
            const double factor = a.m[row][col];
            if (factor == 0.0) continue;
            for (int j = 0; j < 4; ++j) {
                a.m[row][j] -= factor * a.m[col][j];
                inv.m[row][j] -= factor * inv.m[col][j];
            }
        }
    }
    return inv;
}


Box3 Mat4::transform_box(const Box3& box) const {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const auto finite = [](const Vec3d& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); };
    if (!finite(box.lo) || !finite(box.hi)) return {{-inf, -inf, -inf}, {inf, inf, inf}};
    Vec3d lo{inf, inf, inf}, hi{-inf, -inf, -inf};
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3d p{(corner & 1) ? box.hi.x : box.lo.x, (corner & 2) ? box.hi.y : box.lo.y,
                      (corner & 4) ? box.hi.z : box.lo.z};
        const Vec3d q = transform_point(p);
        lo = min(lo, q);
        hi = max(hi, q);
    }
    // The corners' images are rounded: widen by a few units of their size.
    const Vec3d pad = (max(abs_components(lo), abs_components(hi)) + Vec3d{1e-300, 1e-300, 1e-300}) * 1e-14;
    return {lo - pad, hi + pad};
}

Mat4 Mat4::rotate_xyz_degrees(const Vec3d& angles) {
    return rotate_degrees({0, 0, 1}, angles.z) * rotate_degrees({0, 1, 0}, angles.y) *
           rotate_degrees({1, 0, 0}, angles.x);
}

bool Mat4::is_finite() const {
    for (const auto& row : m)
        for (const double x : row)
            if (!std::isfinite(x)) return false;
    return true;
}

double Mat4::squareness() const {
    // The determinant of the columns made unit length: no product of
    // entries overflows or underflows, however large or small the map.
    std::array<Vec3d, 3> c;
    for (std::size_t j = 0; j < 3; ++j) {
        const double length = std::hypot(m[0][j], m[1][j], m[2][j]);
        if (!(length > 0.0)) return 0.0;
        c[j] = Vec3d{m[0][j], m[1][j], m[2][j]} / length;
    }
    return std::abs(dot(c[0], cross(c[1], c[2])));
}

double Mat4::max_stretch() const {
    double most = 0.0;
    for (int j = 0; j < 3; ++j) most = std::max(most, std::hypot(m[0][j], m[1][j], m[2][j]));
    return most;
}

}  // namespace zeroset
