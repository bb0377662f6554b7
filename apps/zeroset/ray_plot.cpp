// Building the ray plot from a probe: samples of H, a vertical range that
// exp-like blow-ups do not squash, and one colour per method.
#include "ray_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace zeroset::cli {

namespace {

constexpr int samples = 800;

/// One colour per method (Okabe–Ito, distinguishable with colour-blindness).
std::string method_colour(Method m) {
    switch (m) {
        case Method::Auto: return "#555555";
        case Method::Sphere: return "#009E73";
        case Method::Interval: return "#0072B2";
        case Method::Lg: return "#CC79A7";
        case Method::Polynomial: return "#882255";
        case Method::Newton: return "#D55E00";
        case Method::RegulaFalsi: return "#E69F00";
        case Method::Bisection: return "#56B4E9";
    }
    return "#000000";
}

std::string short_number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

std::string subscript(std::size_t n) {
    static constexpr const char* digits[] = {"₀", "₁", "₂", "₃", "₄", "₅", "₆", "₇", "₈", "₉"};
    const std::string decimal = std::to_string(n);
    std::string out;
    for (const char c : decimal) out += digits[c - '0'];
    return out;
}

/// The sampled values' 2nd–98th percentiles, widened to the full range
/// where that is at most half as far again, but no further from the axis
/// than 4 × the median |H|; always including 0 (the t axis), and padded by
/// 6 %. Neither a spike nor an exponential's steep end can squash the part
/// of the graph near its roots.
PlotRange vertical_range(const std::vector<PlotPoint>& graph) {
    std::vector<double> ys, sizes;
    for (const PlotPoint& p : graph)
        if (std::isfinite(p.y)) {
            ys.push_back(p.y);
            sizes.push_back(std::abs(p.y));
        }
    if (ys.empty()) return {-1.0, 1.0};
    std::sort(ys.begin(), ys.end());
    std::sort(sizes.begin(), sizes.end());
    const auto at = [](const std::vector<double>& v, double q) {
        return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
    };
    const double p2 = at(ys, 0.02), p98 = at(ys, 0.98), spread = p98 - p2;
    double lo = std::max(ys.front(), p2 - 0.5 * spread), hi = std::min(ys.back(), p98 + 0.5 * spread);
    if (const double limit = 4.0 * at(sizes, 0.5); limit > 0.0) {
        lo = std::max(lo, -limit);
        hi = std::min(hi, limit);
    }
    lo = std::min(lo, 0.0);
    hi = std::max(hi, 0.0);
    if (!(hi > lo)) return {lo - 1.0, hi + 1.0};
    const double pad = 0.06 * (hi - lo);
    return {lo - pad, hi + pad};
}

/// Fig. 4: from each iterate t_i, up (or down) to H(t_i), then along the
/// tangent to the axis at t_{i+1}; iterates are labelled t₀, t₁, … where
/// the labels do not crowd each other.
void add_newton(Plot& plot, const std::vector<double>& iterates, RayFunction& h, double start) {
    const std::string colour = method_colour(Method::Newton);
    PlotSegments verticals{"", colour, {}, 1.0, true};
    PlotSegments tangents{"Newton from t₀ = " + short_number(start) + " (Fig. 4)", colour, {}, 1.4, false};
    std::vector<double> labelled;
    int off_plot = 0;
    const double crowded = 0.025 * (plot.x.hi - plot.x.lo);
    TraceCounters unused;
    for (std::size_t i = 0; i < iterates.size(); ++i) {
        const double t = iterates[i], value = h.value(t, unused);
        verticals.segments.push_back({{t, 0.0}, {t, value}});
        if (i + 1 < iterates.size()) tangents.segments.push_back({{t, value}, {iterates[i + 1], 0.0}});
        const std::string name = "t" + subscript(i);
        if (t < plot.x.lo || t > plot.x.hi) {  // off the plot: say where, at that edge, one line per iterate
            const double y = plot.y.hi - static_cast<double>(++off_plot) * 0.06 * (plot.y.hi - plot.y.lo);
            const double inset = 0.01 * (plot.x.hi - plot.x.lo);
            plot.texts.push_back(t < plot.x.lo ? PlotText{{plot.x.lo + inset, y}, "← " + name + " = " + short_number(t),
                                                          colour, PlotText::Anchor::Start}
                                               : PlotText{{plot.x.hi - inset, y}, name + " = " + short_number(t) + " →",
                                                          colour, PlotText::Anchor::End});
        } else if (std::none_of(labelled.begin(), labelled.end(), [&](double u) { return std::abs(u - t) < crowded; })) {
            plot.texts.push_back({{t, 0.0}, name, colour, PlotText::Anchor::Middle});
            labelled.push_back(t);
        }
    }
    plot.segments.push_back(std::move(tangents));
    plot.segments.push_back(std::move(verticals));
}

PlotLane lane(const MethodOutcome& o) {
    PlotLane l{method_label(o), method_colour(o.method), {}, o.hits, {}};
    if (o.first_hit) l.filled.push_back(*o.first_hit);
    if (!o.message.empty()) {
        l.note = "failed: " + o.message;
        return l;
    }
    l.note = std::to_string(o.evaluations) + " + " + std::to_string(o.all_hits_evaluations) + " evaluations";
    if (o.status != HitStatus::Ok) l.note = std::string(hit_status_name(o.status)) + "; " + l.note;
    return l;
}

}  // namespace

Plot ray_plot(const RaySubject& subject, const RayProbe& probe, const Tape& tape,
              const std::optional<ComparedFunction>& compared) {
    if (!probe.span) throw std::invalid_argument("ray_plot: the ray misses the object's bounds");
    const Span span = *probe.span;
    RayFunction h(tape);
    h.set_ray(probe.ray);
    TraceCounters unused;

    Plot plot;
    plot.x = span.t1 > span.t0 ? PlotRange{span.t0, span.t1} : PlotRange{span.t0 - 0.5, span.t0 + 0.5};
    PlotCurve graph{"H(t) = f(origin + t·dir)", "#1a1a1a", {}, 1.8, false};
    for (int i = 0; i <= samples; ++i) {
        const double t = plot.x.lo + (plot.x.hi - plot.x.lo) * i / samples;
        graph.points.push_back({t, h.value(t, unused)});
    }
    plot.y = vertical_range(graph.points);
    plot.curves.push_back(std::move(graph));
    if (compared) {
        RayFunction other(*compared->tape);
        other.set_ray(probe.ray);
        PlotCurve curve{compared->label, "#7a5195", {}, 1.6, true};
        for (int i = 0; i <= samples; ++i) {
            const double t = plot.x.lo + (plot.x.hi - plot.x.lo) * i / samples;
            curve.points.push_back({t, other.value(t, unused)});
        }
        plot.curves.push_back(std::move(curve));
    }

    plot.title = "H(t) along the ray" + (subject.object.empty() ? std::string() : " through " + subject.object) +
                 " (" + subject.scene + ")";
    const Vec3d& o = probe.ray.origin;
    const Vec3d& d = probe.ray.dir;
    plot.subtitle = "origin (" + short_number(o.x) + ", " + short_number(o.y) + ", " + short_number(o.z) + "), dir (" +
                    short_number(d.x) + ", " + short_number(d.y) + ", " + short_number(d.z) + ") as given; t in [" +
                    short_number(span.t0) + ", " + short_number(span.t1) + "], where the ray is inside the bounds";
    plot.x_label = "t";
    plot.y_label = "H(t)";
    plot.lanes_title = "Hits by method  (● first hit, ○ all hits; evaluations: first-hit + all-hits query)";

    for (const MethodOutcome& m : probe.methods) plot.lanes.push_back(lane(m));
    // The first run of each method (`auto` may stand for it too) supplies its log.
    const auto run_of = [&](Method method) {
        return std::find_if(probe.methods.begin(), probe.methods.end(),
                            [&](const MethodOutcome& m) { return m.resolved == method; });
    };
    if (const auto interval = run_of(Method::Interval); interval != probe.methods.end()) {
        PlotBoxes boxes{"interval boxes (Fig. 10)", method_colour(Method::Interval), {}};
        for (const auto& [t_lo, t_hi, h_lo, h_hi] : interval->all_hits_log.interval_boxes)
            boxes.boxes.push_back({t_lo, t_hi, h_lo, h_hi});
        if (!boxes.boxes.empty()) plot.boxes.push_back(std::move(boxes));
    }
    if (const auto newton = run_of(Method::Newton); newton != probe.methods.end() && subject.newton_from &&
                                                    !newton->first_hit_log.newton_iterates.empty())
        add_newton(plot, newton->first_hit_log.newton_iterates, h, *subject.newton_from);
    return plot;
}

}  // namespace zeroset::cli
