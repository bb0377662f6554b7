// Sweep paths: the curve a swept sphere follows, given as points the way a
// modeller writes them — a polyline, Bézier control points, or a spline
// through the points (Catmull–Rom, or the smoother uniform B-spline) — cut
// into the Bézier segments that swept_sphere.hpp traces. The radius goes
// linearly along each segment, from its first point's radius to its last's.
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <vector>

#include "zeroset/trace/swept_sphere.hpp"

namespace zeroset {

enum class SweepCurve {
    Linear,      // straight segments between consecutive points
    Bezier,      // cubic Bézier pieces: points 0–3, 3–6, …; the inner ones are control points
    CatmullRom,  // through every point; open: the first and last only set the end tangents
    BSpline,     // the uniform cubic B-spline: near the points, through none of them
};

struct SweepCurveInfo {
    SweepCurve curve;
    std::string_view name;         // in scenes
    std::string_view description;  // for messages and docs
};

inline constexpr std::array<SweepCurveInfo, 4> sweep_curves{{
    {SweepCurve::Linear, "linear", "straight segments between the points"},
    {SweepCurve::Bezier, "bezier", "cubic Bézier pieces; points 3k + 1 … 3k + 2 are control points"},
    {SweepCurve::CatmullRom, "catmull_rom", "a Catmull–Rom spline through the points"},
    {SweepCurve::BSpline, "b_spline", "a uniform cubic B-spline guided by the points"},
}};

std::optional<SweepCurve> sweep_curve_named(std::string_view name);

struct SweepPoint {
    Vec3d position;
    double radius;
};

/// The Bézier segments of the curve through `points`. `closed` joins the
/// last point back to the first (not for Bezier: repeat the first point).
/// A Bézier control point's radius is not used. Throws
/// std::invalid_argument with a message for too few points (linear 2,
/// Bézier 3k + 1 with k ≥ 1, open splines 4, closed ones 3), `closed` on a
/// Bézier curve, or a segment SweptSegment refuses.
std::vector<SweptSegment> sweep_segments(SweepCurve curve, const std::vector<SweepPoint>& points, bool closed);

}  // namespace zeroset
