// Rendering a Plot as SVG: the layout, the data-to-pixel map, clipping to
// the plot area (Liang–Barsky) and round-number ticks.
#include "zeroset/io/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>

#include "zeroset/io/atomic_file.hpp"

namespace zeroset {

namespace {

// Layout, in pixels.
constexpr double width = 1000.0;
constexpr double left = 120.0;       // room for y tick labels and lane labels
constexpr double plot_width = 600.0;
constexpr double top = 72.0;         // under the title and subtitle
constexpr double plot_height = 340.0;
constexpr double bottom = top + plot_height;
constexpr double right = left + plot_width;
constexpr double legend_x = right + 22.0;
constexpr double legend_width = 250.0;
constexpr double lane_height = 20.0;
constexpr double lanes_top = bottom + 74.0;

std::string px(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f", v);
    return buffer;
}

std::string xml_escaped(std::string_view text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string text_element(double x, double y, std::string_view text, std::string_view attributes = {}) {
    std::string out = "<text x=\"" + px(x) + "\" y=\"" + px(y) + "\"";
    if (!attributes.empty()) out += " " + std::string(attributes);
    return out + ">" + xml_escaped(text) + "</text>\n";
}

std::string line_element(double x1, double y1, double x2, double y2, std::string_view attributes) {
    return "<line x1=\"" + px(x1) + "\" y1=\"" + px(y1) + "\" x2=\"" + px(x2) + "\" y2=\"" + px(y2) + "\" " +
           std::string(attributes) + "/>\n";
}

std::string stroke_attributes(const std::string& colour, double stroke_width, bool dashed) {
    return "stroke=\"" + xml_escaped(colour) + "\" stroke-width=\"" + px(stroke_width) + "\"" +
           (dashed ? " stroke-dasharray=\"5 4\"" : "");
}

/// A tick's text: as many decimals as the tick spacing needs, a true minus sign.
std::string tick_label(double v, double step) {
    if (std::abs(v) < 1e-9 * step) return "0";
    char buffer[32];
    const double a = std::abs(v);
    if (a >= 1e5 || a < 1e-4) {
        std::snprintf(buffer, sizeof buffer, "%.3g", v);
    } else {
        const int decimals = std::clamp(static_cast<int>(-std::floor(std::log10(step) + 1e-9)), 0, 10);
        std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    }
    std::string label = buffer;
    if (label.front() == '-') label.replace(0, 1, "\u2212");
    return label;
}

/// The data rectangle and its map to pixels.
class Frame {
public:
    Frame(PlotRange x, PlotRange y) : x_(x), y_(y) {}

    [[nodiscard]] double px_x(double v) const { return left + (v - x_.lo) / (x_.hi - x_.lo) * plot_width; }
    [[nodiscard]] double px_y(double v) const { return top + (y_.hi - v) / (y_.hi - y_.lo) * plot_height; }
    [[nodiscard]] bool contains(PlotPoint p) const {
        return p.x >= x_.lo && p.x <= x_.hi && p.y >= y_.lo && p.y <= y_.hi;
    }

    /// `p` with infinite or huge coordinates pulled in to a million plot
    /// sizes away: the visible part of a line through it barely moves, and
    /// the arithmetic stays finite.
    [[nodiscard]] PlotPoint tamed(PlotPoint p) const {
        const double wx = 1e6 * (x_.hi - x_.lo), wy = 1e6 * (y_.hi - y_.lo);
        return {std::clamp(p.x, x_.lo - wx, x_.hi + wx), std::clamp(p.y, y_.lo - wy, y_.hi + wy)};
    }

    /// The part of segment ab inside the rectangle (Liang–Barsky); an end
    /// that is inside is returned unchanged.
    [[nodiscard]] std::optional<std::pair<PlotPoint, PlotPoint>> clip(PlotPoint a, PlotPoint b) const {
        if (std::isnan(a.x) || std::isnan(a.y) || std::isnan(b.x) || std::isnan(b.y)) return std::nullopt;
        a = tamed(a);
        b = tamed(b);
        const double dx = b.x - a.x, dy = b.y - a.y;
        double t0 = 0.0, t1 = 1.0;
        auto edge = [&](double p, double q) {  // keeps the t with p·t ≤ q
            if (p == 0.0) return q >= 0.0;
            const double r = q / p;
            if (p < 0.0) {
                if (r > t1) return false;
                t0 = std::max(t0, r);
            } else {
                if (r < t0) return false;
                t1 = std::min(t1, r);
            }
            return true;
        };
        if (!edge(-dx, a.x - x_.lo) || !edge(dx, x_.hi - a.x) || !edge(-dy, a.y - y_.lo) || !edge(dy, y_.hi - a.y))
            return std::nullopt;
        const PlotPoint from = t0 > 0.0 ? PlotPoint{a.x + t0 * dx, a.y + t0 * dy} : a;
        const PlotPoint to = t1 < 1.0 ? PlotPoint{a.x + t1 * dx, a.y + t1 * dy} : b;
        return std::pair{from, to};
    }

    [[nodiscard]] const PlotRange& x() const { return x_; }
    [[nodiscard]] const PlotRange& y() const { return y_; }

private:
    PlotRange x_, y_;
};

std::string polyline(std::span<const PlotPoint> points, const Frame& frame, const std::string& stroke) {
    std::string out = "<polyline fill=\"none\" " + stroke + " stroke-linejoin=\"round\" points=\"";
    for (const PlotPoint& p : points) out += px(frame.px_x(p.x)) + "," + px(frame.px_y(p.y)) + " ";
    out.back() = '"';
    return out + "/>\n";
}

/// The curve's visible pieces, one polyline each.
std::string curve_svg(const PlotCurve& curve, const Frame& frame) {
    const std::string stroke = stroke_attributes(curve.colour, curve.width, curve.dashed);
    std::string out;
    std::vector<PlotPoint> run;
    auto flush = [&] {
        if (run.size() >= 2) out += polyline(run, frame, stroke);
        run.clear();
    };
    for (std::size_t i = 1; i < curve.points.size(); ++i) {
        const auto piece = frame.clip(curve.points[i - 1], curve.points[i]);
        if (!piece) {
            flush();
            continue;
        }
        const bool continues = !run.empty() && run.back().x == piece->first.x && run.back().y == piece->first.y;
        if (!continues) {
            flush();
            run.push_back(piece->first);
        }
        run.push_back(piece->second);
    }
    flush();
    return out;
}

std::string segments_svg(const PlotSegments& set, const Frame& frame) {
    std::string out = "<g " + stroke_attributes(set.colour, set.width, set.dashed) + ">\n";
    for (const PlotSegment& s : set.segments)
        if (const auto piece = frame.clip(s.a, s.b))
            out += line_element(frame.px_x(piece->first.x), frame.px_y(piece->first.y), frame.px_x(piece->second.x),
                                frame.px_y(piece->second.y), "");
    return out + "</g>\n";
}

std::string boxes_svg(const PlotBoxes& set, const Frame& frame) {
    std::string out = "<g fill=\"" + xml_escaped(set.colour) + "\" fill-opacity=\"0.05\" stroke=\"" +
                      xml_escaped(set.colour) + "\" stroke-opacity=\"0.7\" stroke-width=\"0.8\">\n";
    for (const PlotBoxes::Box& b : set.boxes) {
        // Intersect with the plot rectangle; NaN bounds fail every comparison and drop out.
        const double x0 = std::max(b.x_lo, frame.x().lo), x1 = std::min(b.x_hi, frame.x().hi);
        const double y0 = std::max(b.y_lo, frame.y().lo), y1 = std::min(b.y_hi, frame.y().hi);
        if (!(x0 <= x1 && y0 <= y1)) continue;
        const double px0 = frame.px_x(x0), py1 = frame.px_y(y1);
        out += "<rect x=\"" + px(px0) + "\" y=\"" + px(py1) + "\" width=\"" + px(frame.px_x(x1) - px0) +
               "\" height=\"" + px(frame.px_y(y0) - py1) + "\"/>\n";
    }
    return out + "</g>\n";
}

/// Grid lines, tick marks and labels on both axes; x grid lines run on
/// through the lanes' panel (`x_grid_bottom`).
std::string axes_svg(const Plot& plot, const Frame& frame, double x_grid_bottom) {
    std::string out = "<g stroke=\"#e4e4e4\" stroke-width=\"1\">\n";
    const std::vector<double> xs = nice_ticks(plot.x.lo, plot.x.hi, 8), ys = nice_ticks(plot.y.lo, plot.y.hi, 7);
    for (const double x : xs) out += line_element(frame.px_x(x), top, frame.px_x(x), x_grid_bottom, "");
    for (const double y : ys) out += line_element(left, frame.px_y(y), right, frame.px_y(y), "");
    out += "</g>\n";
    if (plot.zero_line && plot.y.lo < 0.0 && plot.y.hi > 0.0)
        out += line_element(left, frame.px_y(0.0), right, frame.px_y(0.0), "stroke=\"#222222\" stroke-width=\"1.2\"");
    out += "<rect x=\"" + px(left) + "\" y=\"" + px(top) + "\" width=\"" + px(plot_width) + "\" height=\"" +
           px(plot_height) + "\" fill=\"none\" stroke=\"#444444\"/>\n";
    const double x_step = xs.size() > 1 ? xs[1] - xs[0] : 1.0, y_step = ys.size() > 1 ? ys[1] - ys[0] : 1.0;
    for (const double x : xs) {
        out += line_element(frame.px_x(x), bottom, frame.px_x(x), bottom + 5.0, "stroke=\"#444444\"");
        out += text_element(frame.px_x(x), bottom + 18.0, tick_label(x, x_step), "text-anchor=\"middle\"");
    }
    for (const double y : ys) {
        out += line_element(left - 5.0, frame.px_y(y), left, frame.px_y(y), "stroke=\"#444444\"");
        out += text_element(left - 8.0, frame.px_y(y) + 4.0, tick_label(y, y_step), "text-anchor=\"end\"");
    }
    out += text_element(left + plot_width / 2.0, bottom + 38.0, plot.x_label, "text-anchor=\"middle\" font-size=\"13\"");
    const double y_mid = top + plot_height / 2.0;
    out += text_element(left - 58.0, y_mid, plot.y_label,
                        "text-anchor=\"middle\" font-size=\"13\" transform=\"rotate(-90 " + px(left - 58.0) + " " +
                            px(y_mid) + ")\"");
    return out;
}

std::string legend_svg(const Plot& plot) {
    std::string entries;
    double y = top + 18.0;
    auto entry = [&](const std::string& swatch, const std::string& label) {
        entries += swatch + text_element(legend_x + 40.0, y + 4.0, label);
        y += 20.0;
    };
    auto line_swatch = [&](const std::string& stroke) {
        return line_element(legend_x + 8.0, y, legend_x + 32.0, y, stroke);
    };
    for (const PlotBoxes& b : plot.boxes)
        if (!b.label.empty())
            entry("<rect x=\"" + px(legend_x + 10.0) + "\" y=\"" + px(y - 6.0) + "\" width=\"20\" height=\"12\" fill=\"" +
                      xml_escaped(b.colour) + "\" fill-opacity=\"0.15\" stroke=\"" + xml_escaped(b.colour) + "\"/>\n",
                  b.label);
    for (const PlotCurve& c : plot.curves)
        if (!c.label.empty()) entry(line_swatch(stroke_attributes(c.colour, c.width, c.dashed)), c.label);
    for (const PlotSegments& s : plot.segments)
        if (!s.label.empty()) entry(line_swatch(stroke_attributes(s.colour, s.width, s.dashed)), s.label);
    for (const std::string& note : plot.legend_notes) {
        entries += text_element(legend_x + 8.0, y + 4.0, note, "fill=\"#555555\" font-size=\"11\"");
        y += 16.0;
    }
    if (entries.empty()) return {};
    return "<rect x=\"" + px(legend_x) + "\" y=\"" + px(top) + "\" width=\"" + px(legend_width) + "\" height=\"" +
           px(y - top) + "\" fill=\"white\" stroke=\"#bbbbbb\" rx=\"3\"/>\n" + entries;
}

std::string lanes_svg(const Plot& plot, const Frame& frame) {
    std::string out = text_element(left, lanes_top - 8.0, plot.lanes_title, "font-weight=\"bold\"");
    for (std::size_t i = 0; i < plot.lanes.size(); ++i) {
        const PlotLane& lane = plot.lanes[i];
        const double y0 = lanes_top + static_cast<double>(i) * lane_height, y = y0 + lane_height / 2.0;
        if (i % 2 == 0)
            out += "<rect x=\"" + px(left) + "\" y=\"" + px(y0) + "\" width=\"" + px(plot_width) + "\" height=\"" +
                   px(lane_height) + "\" fill=\"#000000\" fill-opacity=\"0.035\"/>\n";
        const std::string colour = xml_escaped(lane.colour);
        out += text_element(left - 8.0, y + 4.0, lane.label, "text-anchor=\"end\" fill=\"" + colour + "\"");
        bool any = false;
        for (const double x : lane.open)
            if (x >= plot.x.lo && x <= plot.x.hi) {
                out += "<circle cx=\"" + px(frame.px_x(x)) + "\" cy=\"" + px(y) + "\" r=\"4.5\" fill=\"white\" stroke=\"" +
                       colour + "\" stroke-width=\"1.6\"/>\n";
                any = true;
            }
        for (const double x : lane.filled)
            if (x >= plot.x.lo && x <= plot.x.hi) {
                out += "<circle cx=\"" + px(frame.px_x(x)) + "\" cy=\"" + px(y) + "\" r=\"3\" fill=\"" + colour + "\"/>\n";
                any = true;
            }
        if (!lane.note.empty())
            out += text_element(any ? right + 8.0 : left + 8.0, y + 4.0, lane.note,
                                "fill=\"#777777\" font-size=\"11\" font-style=\"italic\"");
    }
    const double panel_height = static_cast<double>(plot.lanes.size()) * lane_height;
    return out + "<rect x=\"" + px(left) + "\" y=\"" + px(lanes_top) + "\" width=\"" + px(plot_width) + "\" height=\"" +
           px(panel_height) + "\" fill=\"none\" stroke=\"#444444\"/>\n";
}

void check_range(const PlotRange& r, const char* axis) {
    if (!(std::isfinite(r.lo) && std::isfinite(r.hi) && r.lo < r.hi))
        throw std::invalid_argument(std::string("svg_plot: the ") + axis + " range is empty or not finite");
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target) {
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo < hi) || target < 1) return {};
    const double raw = (hi - lo) / target;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double r = raw / magnitude;
    const double step = (r < 1.5 ? 1.0 : r < 3.0 ? 2.0 : r < 7.0 ? 5.0 : 10.0) * magnitude;
    std::vector<double> ticks;
    for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; k += 1.0) {
        const double t = k * step;
        ticks.push_back(std::abs(t) < 1e-9 * step ? 0.0 : t);
    }
    return ticks;
}

std::string svg_plot(const Plot& plot) {
    check_range(plot.x, "x");
    check_range(plot.y, "y");
    const Frame frame(plot.x, plot.y);
    const double lanes_bottom = lanes_top + static_cast<double>(plot.lanes.size()) * lane_height;
    const double height = plot.lanes.empty() ? bottom + 56.0 : lanes_bottom + 18.0;

    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                      px(width) + "\" height=\"" + px(height) + "\" viewBox=\"0 0 " + px(width) + " " + px(height) +
                      "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\"12\" fill=\"#222222\">\n";
    out += "<title>" + xml_escaped(plot.title) + "</title>\n";
    out += "<defs><clipPath id=\"plot-area\"><rect x=\"" + px(left) + "\" y=\"" + px(top) + "\" width=\"" +
           px(plot_width) + "\" height=\"" + px(plot_height) + "\"/></clipPath></defs>\n";
    out += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    out += text_element(left, 28.0, plot.title, "font-size=\"16\" font-weight=\"bold\"");
    out += text_element(left, 50.0, plot.subtitle, "fill=\"#555555\"");
    out += axes_svg(plot, frame, plot.lanes.empty() ? bottom : lanes_bottom);

    out += "<g clip-path=\"url(#plot-area)\">\n";
    for (const PlotBoxes& b : plot.boxes) out += boxes_svg(b, frame);
    for (const PlotSegments& s : plot.segments) out += segments_svg(s, frame);
    for (const PlotCurve& c : plot.curves) out += curve_svg(c, frame);
    out += "</g>\n";
    for (const PlotText& t : plot.texts) {
        if (!frame.contains(t.at)) continue;
        const char* anchor = t.anchor == PlotText::Anchor::Start ? "start"
                             : t.anchor == PlotText::Anchor::End ? "end"
                                                                 : "middle";
        out += text_element(frame.px_x(t.at.x), frame.px_y(t.at.y) - 6.0, t.text,
                            "text-anchor=\"" + std::string(anchor) + "\" fill=\"" + xml_escaped(t.colour) +
                                "\" stroke=\"white\" stroke-width=\"3\" paint-order=\"stroke\"");
    }
    out += legend_svg(plot);
    if (!plot.lanes.empty()) out += lanes_svg(plot, frame);
    return out + "</svg>\n";
}

void write_svg_plot(const Plot& plot, const std::filesystem::path& file) {
    const std::string text = svg_plot(plot);
    write_file_atomically(file, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

}  // namespace zeroset
