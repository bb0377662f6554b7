// Finding the singular points of a surface: minima of the residual on a grid
// for the starting points, Levenberg–Marquardt on (f, L·∇f) = 0 from them.
#include "support/surface_nodes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "zeroset/expr/evaluator.hpp"

namespace zeroset::test {

namespace {

constexpr int grid = 64;                   // cells per axis of the enclosing box
constexpr double accept_tolerance = 1e-9;  // × RMS of f, on |f| and L·|∇f|
constexpr double duplicate_radius = 1e-6;  // × L
constexpr int max_iterations = 200;

using Mat3 = std::array<std::array<double, 3>, 3>;

bool inside(const Bounds& bounds, const Vec3d& p) {
    if (bounds.kind == Bounds::Kind::Box) return bounds.box.contains(p);
    const Vec3d d = p - bounds.center;
    return dot(d, d) <= bounds.radius * bounds.radius;
}

/// x with (a + λI) x = b, by Cramer's rule (a + λI is symmetric positive definite for λ > 0).
Vec3d solve(const Mat3& a, double lambda, const Vec3d& b) {
    Mat3 m = a;
    for (int i = 0; i < 3; ++i) m[i][i] += lambda;
    const auto det = [](const Mat3& q) {
        return q[0][0] * (q[1][1] * q[2][2] - q[1][2] * q[2][1]) - q[0][1] * (q[1][0] * q[2][2] - q[1][2] * q[2][0]) +
               q[0][2] * (q[1][0] * q[2][1] - q[1][1] * q[2][0]);
    };
    const double d = det(m);
    Vec3d x;
    for (int column = 0; column < 3; ++column) {
        Mat3 replaced = m;
        for (int row = 0; row < 3; ++row) replaced[row][column] = b[row];
        x[column] = det(replaced) / d;
    }
    return x;
}

class NodeFinder {
public:
    NodeFinder(const Expr& surface, const Bounds& bounds)
        : tape_(surface), gradient_(tape_), curvature_(tape_), bounds_(bounds), box_(bounds.enclosing_box()),
          length_(box_.diagonal()), cell_(box_.size() / static_cast<double>(grid)) {}

    std::vector<Vec3d> run() {
        // The residual at the cells' centres, and the RMS of f for the tolerance.
        std::vector<double> residual(grid * grid * grid);
        double sum = 0.0;
        for (int i = 0; i < grid; ++i)
            for (int j = 0; j < grid; ++j)
                for (int k = 0; k < grid; ++k) {
                    const Dual<double> d = evaluate_gradient(gradient_, centre(i, j, k));
                    residual[index(i, j, k)] = cost(d);
                    sum += square(d.v);
                }
        tolerance_ = accept_tolerance * std::sqrt(sum / static_cast<double>(residual.size()));
        if (!(tolerance_ > 0.0) || !std::isfinite(tolerance_)) return {};
        // Levenberg–Marquardt from the residual's planar minima.
        for (int i = 0; i < grid; ++i)
            for (int j = 0; j < grid; ++j)
                for (int k = 0; k < grid; ++k)
                    if (planar_minimum(residual, i, j, k)) start_at(centre(i, j, k));
        return nodes_;
    }

private:
    static std::size_t index(int i, int j, int k) { return (static_cast<std::size_t>(i) * grid + j) * grid + k; }

    [[nodiscard]] Vec3d centre(int i, int j, int k) const {
        return box_.lo + Vec3d{(i + 0.5) * cell_.x, (j + 0.5) * cell_.y, (k + 0.5) * cell_.z};
    }

    /// Whether the residual at the cell (i, j, k) is a minimum of its 3 × 3
    /// neighbourhood in one of the three coordinate planes through it: true
    /// near an isolated node, and all along a singular curve (across it).
    static bool planar_minimum(const std::vector<double>& residual, int i, int j, int k) {
        const double r = residual[index(i, j, k)];
        for (int normal = 0; normal < 3; ++normal) {
            bool minimum = true;
            for (int du = -1; du <= 1 && minimum; ++du)
                for (int dv = -1; dv <= 1 && minimum; ++dv) {
                    int n[3] = {i, j, k};
                    n[(normal + 1) % 3] += du;
                    n[(normal + 2) % 3] += dv;
                    const bool in_grid = std::ranges::all_of(n, [](int c) { return c >= 0 && c < grid; });
                    minimum = !in_grid || residual[index(n[0], n[1], n[2])] >= r;
                }
            if (minimum) return true;
        }
        return false;
    }

    /// Levenberg–Marquardt from p, unless a node already found lies within a cell of it.
    void start_at(const Vec3d& p) {
        const Box3 near{p - cell_, p + cell_};
        if (std::ranges::any_of(nodes_, [&](const Vec3d& n) { return near.contains(n); })) return;
        const auto node = converge(p);
        if (!node || !inside(bounds_, *node)) return;
        if (std::ranges::any_of(nodes_, [&](const Vec3d& n) { return length(n - *node) <= duplicate_radius * length_; }))
            return;
        nodes_.push_back(*node);
    }

    /// f² + L²|∇f|², the squared residual of the system.
    [[nodiscard]] double cost(const Dual<double>& d) const { return square(d.v) + square(length_) * dot(d.g, d.g); }

    /// Whether f and ∇f vanish to the tolerance.
    [[nodiscard]] bool singular(const Dual<double>& d) const {
        return std::abs(d.v) <= tolerance_ && length_ * length(d.g) <= tolerance_;
    }

    /// The Hessian of f at p: the second derivative along e_i and e_i + e_j.
    Mat3 hessian(const Vec3d& p) {
        const auto second = [&](const Vec3d& u) { return evaluate_along_ray(curvature_, p, u, 0.0).d2; };
        const Vec3d axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        Mat3 h{};
        for (int i = 0; i < 3; ++i) h[i][i] = second(axes[i]);
        for (int i = 0; i < 3; ++i)
            for (int j = i + 1; j < 3; ++j) h[i][j] = h[j][i] = 0.5 * (second(axes[i] + axes[j]) - h[i][i] - h[j][j]);
        return h;
    }

    /// The point Levenberg–Marquardt converges to from p, if it is a singular point.
    std::optional<Vec3d> converge(Vec3d p) {
        Dual<double> d = evaluate_gradient(gradient_, p);
        double c = cost(d), mu = 1e-3;
        for (int iteration = 0; iteration < max_iterations && c > 0.0; ++iteration) {
            // The Jacobian of (f, L∇f) is (∇f, L·H): the normal equations are
            // (∇f ∇fᵀ + L²H²) δ = −(f ∇f + L² H ∇f).
            const Mat3 h = hessian(p);
            Mat3 a{};
            Vec3d b;
            for (int i = 0; i < 3; ++i) {
                double hg = 0.0;
                for (int k = 0; k < 3; ++k) hg += h[i][k] * d.g[k];
                b[i] = -(d.v * d.g[i] + square(length_) * hg);
                for (int j = 0; j < 3; ++j) {
                    double hh = 0.0;
                    for (int k = 0; k < 3; ++k) hh += h[i][k] * h[k][j];
                    a[i][j] = d.g[i] * d.g[j] + square(length_) * hh;
                }
            }
            const double trace = a[0][0] + a[1][1] + a[2][2];
            if (!(trace > 0.0)) break;  // ∇f = 0 and H = 0: a singular point of higher order
            // Isotropic damping, allowed to fade to nothing: a degenerate
            // singular point (a cusp, a pinch point) is flat in one direction
            // and converges only linearly, with steps far below any fixed
            // damping. Along a singular curve that direction has no curvature
            // at all: steps longer than a cell count as failures, and once the
            // point is singular to tolerance only steps that halve the
            // residual count, so that the search stops on the curve instead of
            // drifting along it to its special points.
            const double wanted = singular(d) ? 0.5 * c : c;
            Vec3d step{};
            bool improved = false;
            while (!improved && mu < 1e12) {
                step = solve(a, mu * trace / 3.0, b);
                const Dual<double> trial = evaluate_gradient(gradient_, p + step);
                if (length(step) <= length(cell_) && cost(trial) < wanted) {
                    p = p + step;
                    d = trial;
                    c = cost(trial);
                    mu = std::max(mu * 0.1, 1e-30);
                    improved = true;
                } else {
                    mu *= 10.0;
                }
            }
            if (!improved || length(step) <= 1e-16 * length_) break;
            if (!box_.contains(p)) return std::nullopt;
        }
        if (singular(d)) return p;
        return std::nullopt;
    }

    Tape tape_;
    Evaluator<Dual<double>> gradient_;
    Evaluator<Jet<double>> curvature_;
    Bounds bounds_;
    Box3 box_;
    double length_;
    Vec3d cell_;
    double tolerance_ = 0.0;
    std::vector<Vec3d> nodes_;
};

}  // namespace

std::vector<Vec3d> surface_nodes(const Expr& surface, const Bounds& bounds, int max_count) {
    std::vector<Vec3d> nodes = NodeFinder(surface, bounds).run();
    if (static_cast<int>(nodes.size()) <= max_count) return nodes;
    // Every k-th point, in the (spatially coherent) order found.
    std::vector<Vec3d> spread;
    for (int i = 0; i < max_count; ++i)
        spread.push_back(nodes[static_cast<std::size_t>(i) * nodes.size() / static_cast<std::size_t>(max_count)]);
    return spread;
}

}  // namespace zeroset::test
