// svg_plot: a well-formed SVG document with the curve, segments, boxes,
// texts and lane markers asked for; everything drawn stays inside the plot
// area whatever the data; bad ranges are refused and leave no file.
#include "zeroset/io/svg_plot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/temp_dir.hpp"

namespace zeroset {
namespace {

/// Every element opened is closed, in order, and the document is one <svg>
/// element after the XML declaration. Returns what is wrong, or "".
std::string xml_problem(const std::string& text) {
    std::vector<std::string> open;
    std::size_t i = 0, roots = 0;
    if (!text.starts_with("<?xml ")) return "no XML declaration";
    i = text.find("?>") + 2;
    while ((i = text.find('<', i)) != std::string::npos) {
        const std::size_t end = text.find('>', i);
        if (end == std::string::npos) return "unterminated tag";
        const std::string tag = text.substr(i + 1, end - i - 1);
        if (std::count(tag.begin(), tag.end(), '"') % 2 != 0) return "unbalanced quotes in <" + tag + ">";
        if (tag.starts_with('/')) {
            if (open.empty() || open.back() != tag.substr(1)) return "unexpected </" + tag.substr(1) + ">";
            open.pop_back();
        } else {
            if (open.empty()) ++roots;
            if (!tag.ends_with('/')) open.push_back(tag.substr(0, tag.find_first_of(" \n")));
        }
        // Text between tags must not hold a bare '<' or an unescaped '&'.
        const std::size_t next = text.find('<', end);
        const std::string between = text.substr(end + 1, next == std::string::npos ? std::string::npos : next - end - 1);
        for (std::size_t a = between.find('&'); a != std::string::npos; a = between.find('&', a + 1))
            if (!std::regex_search(between.substr(a), std::regex("^&(amp|lt|gt|quot);"))) return "bare & in text";
        i = end + 1;
    }
    if (!open.empty()) return "<" + open.back() + "> not closed";
    if (roots != 1) return "more than one root element";
    return "";
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t i = text.find(what); i != std::string::npos; i = text.find(what, i + 1)) ++n;
    return n;
}

/// All numbers of every `points="…"` attribute, as (x, y) pairs.
std::vector<std::pair<double, double>> polyline_points(const std::string& svg) {
    std::vector<std::pair<double, double>> points;
    const std::regex attribute("points=\"([^\"]*)\"");
    for (std::sregex_iterator it(svg.begin(), svg.end(), attribute), end; it != end; ++it) {
        const std::string list = (*it)[1];
        const char* p = list.c_str();
        char* next = nullptr;
        while (true) {
            const double x = std::strtod(p, &next);
            if (next == p) break;
            p = next + 1;  // the comma
            const double y = std::strtod(p, &next);
            points.emplace_back(x, y);
            p = next;
        }
    }
    return points;
}

Plot sample_plot() {
    Plot plot;
    plot.title = "H(t) <of> \"blobs\" & more";
    plot.subtitle = "a subtitle";
    plot.x_label = "t";
    plot.y_label = "H(t)";
    plot.x = {0.0, 10.0};
    plot.y = {-1.0, 1.0};
    PlotCurve curve{"H(t)", "#111111", {}, 1.5, false};
    for (int i = 0; i <= 100; ++i) curve.points.push_back({0.1 * i, std::sin(0.1 * i)});
    plot.curves.push_back(curve);
    plot.segments.push_back({"tangents", "#D55E00", {{{1.0, 0.5}, {2.0, 0.0}}, {{2.0, 0.0}, {2.0, -0.3}}}, 1.2, true});
    plot.boxes.push_back({"boxes", "#0072B2", {{0.0, 5.0, -2.0, 3.0}, {5.0, 7.5, -0.5, 0.25}}});
    plot.texts.push_back({{2.0, 0.0}, "t₁", "#D55E00", PlotText::Anchor::Middle});
    plot.lanes.push_back({"interval", "#0072B2", {3.14}, {3.14, 6.28}, "16 + 93 evaluations"});
    plot.lanes.push_back({"newton", "#D55E00", {}, {}, "failed: not available"});
    plot.lanes_title = "Hits by method";
    return plot;
}

TEST(SvgPlot, IsAWellFormedDocumentWithEveryPart) {
    const std::string svg = svg_plot(sample_plot());
    EXPECT_EQ(xml_problem(svg), "");
    EXPECT_NE(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
    EXPECT_TRUE(svg.ends_with("</svg>\n"));
    EXPECT_EQ(count(svg, "<polyline"), 1u);
    EXPECT_EQ(count(svg, "<circle"), 3u);  // the lanes' markers: one filled, two open
    EXPECT_EQ(count(svg, "stroke-dasharray"), 2u);  // the dashed segments and their legend swatch
    EXPECT_NE(svg.find("H(t) &lt;of&gt; &quot;blobs&quot; &amp; more"), std::string::npos);  // escaped title
    for (const char* part : {">t₁<", ">interval<", ">newton<", ">16 + 93 evaluations<", ">failed: not available<",
                             ">Hits by method<", ">tangents<", ">boxes<", ">H(t)<", ">a subtitle<"})
        EXPECT_NE(svg.find(part), std::string::npos) << part;
    EXPECT_EQ(svg.find("nan"), std::string::npos);
    EXPECT_EQ(svg.find("inf"), std::string::npos);
}

TEST(SvgPlot, TicksAreRoundNumbers) {
    EXPECT_EQ(nice_ticks(0.0, 1.0, 5), (std::vector<double>{0.0, 0.2, 0.4, 0.6000000000000001, 0.8, 1.0}));
    EXPECT_EQ(nice_ticks(2.55, 7.45, 8), (std::vector<double>{3.0, 3.5, 4.0, 4.5, 5.0, 5.5, 6.0, 6.5, 7.0}));
    const auto around_zero = nice_ticks(-0.75, 0.9, 7);
    EXPECT_NE(std::find(around_zero.begin(), around_zero.end(), 0.0), around_zero.end());
    EXPECT_TRUE(nice_ticks(1.0, 1.0, 5).empty());
    EXPECT_TRUE(nice_ticks(0.0, std::numeric_limits<double>::infinity(), 5).empty());
    const std::string svg = svg_plot(sample_plot());
    for (const char* label : {">0<", ">2<", ">10<", ">\u22120.4<", ">0.4<"}) EXPECT_NE(svg.find(label), std::string::npos) << label;
}

TEST(SvgPlot, ClipsEverythingToThePlotArea) {
    Plot plot = sample_plot();
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    // Far outside, infinite and NaN points: what is visible stays inside,
    // and NaN breaks the curve in two.
    plot.curves[0].points = {{0.0, 0.0}, {1.0, 1e300}, {2.0, 0.5}, {3.0, 0.5}, {4.0, nan}, {5.0, 0.0}, {6.0, -inf},
                             {7.0, 0.0}, {8.0, 0.2}, {1e12, 0.2}};
    plot.segments[0].segments.push_back({{-1e308, -1e308}, {1e308, 1e308}});
    plot.boxes[0].boxes.push_back({-inf, inf, -inf, inf});
    plot.boxes[0].boxes.push_back({nan, 1.0, 0.0, 1.0});
    plot.texts.push_back({{20.0, 0.0}, "outside", "#000000", PlotText::Anchor::Middle});
    const std::string svg = svg_plot(plot);
    EXPECT_EQ(xml_problem(svg), "");
    EXPECT_EQ(svg.find("nan"), std::string::npos);
    EXPECT_EQ(svg.find("inf"), std::string::npos);
    EXPECT_EQ(svg.find(">outside<"), std::string::npos);

    std::smatch area;
    ASSERT_TRUE(std::regex_search(svg, area, std::regex(R"re(<clipPath id="plot-area"><rect x="([0-9.]+)" y="([0-9.]+)" width="([0-9.]+)" height="([0-9.]+)")re")));
    const double x0 = std::stod(area[1]), y0 = std::stod(area[2]), x1 = x0 + std::stod(area[3]), y1 = y0 + std::stod(area[4]);
    const auto points = polyline_points(svg);
    ASSERT_GE(points.size(), 6u);
    for (const auto& [x, y] : points) {
        EXPECT_GE(x, x0 - 0.05);
        EXPECT_LE(x, x1 + 0.05);
        EXPECT_GE(y, y0 - 0.05);
        EXPECT_LE(y, y1 + 0.05);
    }
    EXPECT_GE(count(svg, "<polyline"), 2u);
}

TEST(SvgPlot, RefusesEmptyOrInfiniteRanges) {
    Plot plot = sample_plot();
    plot.x = {1.0, 1.0};
    EXPECT_THROW((void)svg_plot(plot), std::invalid_argument);
    plot.x = {0.0, 1.0};
    plot.y = {0.0, std::numeric_limits<double>::infinity()};
    EXPECT_THROW((void)svg_plot(plot), std::invalid_argument);
}

TEST(SvgPlot, WritesTheFileAndNothingOnFailure) {
    const test::TempDir dir;
    write_svg_plot(sample_plot(), dir / "plot.svg");
    const auto bytes = test::read_bytes(dir / "plot.svg");
    EXPECT_EQ(std::string(bytes.begin(), bytes.end()), svg_plot(sample_plot()));

    Plot bad = sample_plot();
    bad.y = {2.0, 1.0};
    EXPECT_THROW(write_svg_plot(bad, dir / "bad.svg"), std::invalid_argument);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"plot.svg"});
}

}  // namespace
}  // namespace zeroset
