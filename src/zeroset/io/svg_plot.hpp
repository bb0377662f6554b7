// Plot: a small line-plot description and its SVG rendering, for the
// survey-style figures zeroset draws of one function along one ray (Figs.
// 2–4, 10): curves, line segments, translucent boxes and text labels in data
// coordinates over a framed plot area with tick labels, a legend, and lanes
// of markers under the plot that share its x axis (one lane per series, e.g.
// the roots each method found). Everything is clipped to the plot area, so
// far-off or infinite coordinates are harmless.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace zeroset {

struct PlotPoint {
    double x = 0.0;
    double y = 0.0;
};

struct PlotRange {
    double lo = 0.0;
    double hi = 1.0;
};

/// A polyline; a point with a non-finite coordinate breaks it in two.
struct PlotCurve {
    std::string label;  // legend text; empty: not in the legend
    std::string colour;
    std::vector<PlotPoint> points;
    double width = 1.5;
    bool dashed = false;
};

struct PlotSegment {
    PlotPoint a, b;
};

struct PlotSegments {
    std::string label;
    std::string colour;
    std::vector<PlotSegment> segments;
    double width = 1.2;
    bool dashed = false;
};

/// Axis-aligned rectangles [x_lo, x_hi] × [y_lo, y_hi], filled translucently.
struct PlotBoxes {
    struct Box {
        double x_lo, x_hi, y_lo, y_hi;
    };
    std::string label;
    std::string colour;
    std::vector<Box> boxes;
};

/// Text at a data point, drawn just above it, centred on it or starting or
/// ending there; labels outside the plot are dropped.
struct PlotText {
    enum class Anchor { Start, Middle, End };
    PlotPoint at;
    std::string text;
    std::string colour = "#333333";
    Anchor anchor = Anchor::Middle;
};

/// One row under the plot: circles at x positions, filled for `filled`,
/// open for `open`, and a note at the row's end (e.g. why it is empty).
struct PlotLane {
    std::string label;
    std::string colour;
    std::vector<double> filled;
    std::vector<double> open;
    std::string note;
};

struct Plot {
    std::string title;
    std::string subtitle;
    std::string x_label;
    std::string y_label;
    PlotRange x;
    PlotRange y;
    std::vector<PlotBoxes> boxes;  // drawn first, under everything else
    std::vector<PlotCurve> curves;
    std::vector<PlotSegments> segments;
    std::vector<PlotText> texts;
    std::vector<PlotLane> lanes;
    std::string lanes_title;  // heading of the lanes' panel
    bool zero_line = true;    // emphasise y = 0 (the t axis of H(t))
    /// Extra legend lines, after the series' entries (e.g. what filled and open markers mean).
    std::vector<std::string> legend_notes;
};

/// The plot as a standalone SVG document. Throws std::invalid_argument when
/// a range is empty or not finite.
std::string svg_plot(const Plot& plot);

/// Writes svg_plot(plot) to `file` atomically (FileWriteError on failure).
void write_svg_plot(const Plot& plot, const std::filesystem::path& file);

/// Tick positions for [lo, hi]: about `target` round numbers (1, 2 or 5 × 10ᵏ apart).
std::vector<double> nice_ticks(double lo, double hi, int target);

}  // namespace zeroset
