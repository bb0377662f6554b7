// OctreeWalk's block evaluation and edge refinement (octree_walk.hpp).
#include "zeroset/mesh/octree_walk.hpp"

#include <algorithm>

namespace zeroset {

namespace {
/// Regula falsi steps on an edge, and the bracket (a fraction of the edge) they aim for.
constexpr int max_refinements = 16;
constexpr double bracket_goal = 1e-7;
}  // namespace

bool OctreeWalk::evaluate_block(int i, int j, int k, int size, const Tape& tape) {
    points_.rebind(tape);
    grid_.rebind(tape);
    std::size_t n = 0;
    for (int c = 0; c <= size; ++c)
        for (int b = 0; b <= size; ++b)
            for (int a = 0; a <= size; ++a, ++n) {
                const Vec3d q = grid_point(i + a, j + b, k + c);
                xs_[n] = q.x, ys_[n] = q.y, zs_[n] = q.z;
            }
    std::array<double, block_points * block_points * block_points> values{};
    grid_.evaluate({xs_.data(), n}, {ys_.data(), n}, {zs_.data(), n}, {values.data(), n});
    n = 0;
    for (int c = 0; c <= size; ++c)
        for (int b = 0; b <= size; ++b)
            for (int a = 0; a <= size; ++a, ++n) {
                if (std::isnan(values[n])) {
                    nan_at_ = Vec3d{xs_[n], ys_[n], zs_[n]};
                    return false;
                }
                block_values_[static_cast<std::size_t>(a + block_points * (b + block_points * c))] = values[n];
            }
    return true;
}

double OctreeWalk::grid_value(int i, int j, int k) {
    const Vec3d q = grid_point(i, j, k);
    double value = 0.0;
    full_grid_.evaluate({&q.x, 1}, {&q.y, 1}, {&q.z, 1}, {&value, 1});
    if (std::isnan(value)) nan_at_ = q;
    return value;
}

Vec3d OctreeWalk::refine(const Vec3d& in, double f_in, const Vec3d& out, double f_out) {
    if (f_out == 0.0) return out;  // a zero at the corner itself: exact
    double lo = 0.0, hi = 1.0, f_lo = f_in, f_hi = f_out;
    int side = 0;
    for (int step = 0; step < max_refinements && hi - lo > bracket_goal; ++step) {
        const double t = std::clamp(lo + (hi - lo) * f_lo / (f_lo - f_hi), lo, hi);
        if (!std::isfinite(t) || t == lo || t == hi) break;
        const Vec3d q = in + (out - in) * t;
        const double f = points_(q.x, q.y, q.z);
        if (f == 0.0) return q;
        if (std::isnan(f)) {
            nan_at_ = q;
            break;
        }
        if (f < 0.0) {
            lo = t, f_lo = f;
            if (side == -1) f_hi *= 0.5;
            side = -1;
        } else {
            hi = t, f_hi = f;
            if (side == 1) f_lo *= 0.5;
            side = 1;
        }
    }
    vertex_tolerance_ = std::max(vertex_tolerance_, (hi - lo) * length(out - in));
    const double t = f_lo == f_hi ? 0.5 * (lo + hi) : std::clamp(lo + (hi - lo) * f_lo / (f_lo - f_hi), lo, hi);
    return in + (out - in) * (std::isfinite(t) ? t : 0.5 * (lo + hi));
}

}  // namespace zeroset
