// find_bounds_cut: each face of a box split into quarters to a depth of 5
// (1024 patches a face at most) where its interval does not rule f < 0 out;
// a sphere sampled at a spiral of points.
#include "zeroset/trace/bounds_cut.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/math/box3.hpp"

namespace zeroset {

namespace {

constexpr int max_depth = 5;
constexpr int sphere_samples = 1024;

std::string format_coordinate(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

class FaceSearch {
public:
    explicit FaceSearch(const Tape& tape) : points_(tape), intervals_(tape) {}

    /// A point of `patch` (a box flat along one axis) where f < 0.
    std::optional<Vec3d> search(const Box3& patch, int depth) {
        const Interval f = evaluate_box(intervals_, patch.lo, patch.hi);
        if (f.lo > 0.0) return std::nullopt;  // f > 0 all over it (NaN bounds do not rule out)
        const Vec3d c = patch.center();
        if (points_(c.x, c.y, c.z) < 0.0) return c;
        if (depth == max_depth) return std::nullopt;
        // Quarters: halve the two axes along which the patch has extent.
        const Vec3d size = patch.size();
        for (int q = 0; q < 4; ++q) {
            Box3 part = patch;
            int split = 0;
            for (int axis = 0; axis < 3; ++axis) {
                if (!(size[axis] > 0.0)) continue;
                const bool upper = (q >> split++) & 1;
                (upper ? part.lo : part.hi)[axis] = c[axis];
            }
            if (const auto found = search(part, depth + 1)) return found;
        }
        return std::nullopt;
    }

private:
    Evaluator<double> points_;
    Evaluator<Interval> intervals_;
};

std::optional<BoundsCut> box_cut(const Tape& tape, const Box3& box) {
    FaceSearch search(tape);
    constexpr const char* axis_names[] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
        for (const bool upper : {false, true}) {
            Box3 face = box;
            const double at = upper ? box.hi[axis] : box.lo[axis];
            face.lo[axis] = face.hi[axis] = at;
            if (const auto p = search.search(face, 0))
                return BoundsCut{*p, std::string("the face ") + axis_names[axis] + " = " + format_coordinate(at)};
        }
    }
    return std::nullopt;
}

/// Points spread evenly over the sphere (a Fibonacci spiral).
std::optional<BoundsCut> sphere_cut(const Tape& tape, const Vec3d& center, double radius) {
    Evaluator<double> f(tape);
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < sphere_samples; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / sphere_samples;
        const double r = std::sqrt(1.0 - y * y);
        // A hair outside the sphere, so that rounding cannot put a sample inside
        // a surface that only touches the bounds.
        const Vec3d p = center + Vec3d{r * std::cos(golden * i), y, r * std::sin(golden * i)} * (radius * (1.0 + 1e-9));
        if (f(p.x, p.y, p.z) < 0.0) return BoundsCut{p, "the bounding sphere"};
    }
    return std::nullopt;
}

}  // namespace

std::optional<BoundsCut> find_bounds_cut(const Tape& tape, const Bounds& bounds) {
    switch (bounds.kind) {
        case Bounds::Kind::Box: return box_cut(tape, bounds.box);
        case Bounds::Kind::Sphere: return sphere_cut(tape, bounds.center, bounds.radius);
        case Bounds::Kind::None: return std::nullopt;
    }
    return std::nullopt;
}

}  // namespace zeroset
