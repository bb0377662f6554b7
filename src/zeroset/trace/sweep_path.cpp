// Sweep paths cut into Bézier segments: the splines' standard conversions
// to the Bézier basis, one segment per span between consecutive points.
#include "zeroset/trace/sweep_path.hpp"

#include <stdexcept>
#include <string>

namespace zeroset {

std::optional<SweepCurve> sweep_curve_named(std::string_view name) {
    for (const SweepCurveInfo& c : sweep_curves)
        if (c.name == name) return c.curve;
    return std::nullopt;
}

namespace {

void need(bool enough, const std::string& what) {
    if (!enough) throw std::invalid_argument(what);
}

}  // namespace

std::vector<SweptSegment> sweep_segments(SweepCurve curve, const std::vector<SweepPoint>& points, bool closed) {
    const int n = static_cast<int>(points.size());
    std::vector<SweptSegment> segments;
    // Point i, wrapping around a closed curve.
    const auto at = [&](int i) -> const SweepPoint& { return points[static_cast<std::size_t>((i % n + n) % n)]; };
    switch (curve) {
        case SweepCurve::Linear: {
            need(n >= 2, "a linear sweep needs at least 2 points");
            const int count = closed ? n : n - 1;
            for (int i = 0; i < count; ++i)
                segments.emplace_back(1, std::array<Vec3d, 4>{at(i).position, at(i + 1).position}, at(i).radius,
                                      at(i + 1).radius);
            break;
        }
        case SweepCurve::Bezier: {
            need(!closed, "a bezier sweep cannot be closed: end it on its first point");
            need(n >= 4 && (n - 1) % 3 == 0, "a bezier sweep needs 3k + 1 points (4, 7, 10, …), not " + std::to_string(n));
            for (int i = 0; i + 3 < n; i += 3)
                segments.emplace_back(3, std::array<Vec3d, 4>{at(i).position, at(i + 1).position, at(i + 2).position, at(i + 3).position},
                                      at(i).radius, at(i + 3).radius);
            break;
        }
        case SweepCurve::CatmullRom:
        case SweepCurve::BSpline: {
            need(closed ? n >= 3 : n >= 4, std::string(closed ? "a closed" : "an open") + " spline sweep needs at least " +
                                               (closed ? "3" : "4") + " points");
            // Segment i runs between points i and i + 1 (open: from 1 to n − 2).
            const int first = closed ? 0 : 1, last = closed ? n : n - 2;
            for (int i = first; i < last; ++i) {
                const Vec3d p0 = at(i - 1).position, p1 = at(i).position, p2 = at(i + 1).position, p3 = at(i + 2).position;
                std::array<Vec3d, 4> b;
                if (curve == SweepCurve::CatmullRom) {  // tangents (p2 − p0)/2 and (p3 − p1)/2
                    b = {p1, p1 + (p2 - p0) / 6.0, p2 - (p3 - p1) / 6.0, p2};
                } else {  // the uniform B-spline's Bézier points
                    b = {(p0 + 4.0 * p1 + p2) / 6.0, (2.0 * p1 + p2) / 3.0, (p1 + 2.0 * p2) / 3.0, (p1 + 4.0 * p2 + p3) / 6.0};
                }
                segments.emplace_back(3, b, at(i).radius, at(i + 1).radius);
            }
            break;
        }
    }
    return segments;
}

}  // namespace zeroset
