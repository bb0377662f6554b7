// `sweep "name" { curve … closed … radius … point (…) [radius …] … }` in the
// scene language (docs/sweeps.md): a sphere swept along a curve through
// points (trace/sweep_path.hpp), read into an object node whose Object
// carries the curve's Bézier segments.
#include <array>
#include <cmath>
#include <map>
#include <optional>

#include "zeroset/scene/scene_error.hpp"
#include "zeroset/scene/scene_parser.hpp"
#include "zeroset/scene/wording.hpp"
#include "zeroset/trace/sweep_path.hpp"

namespace zeroset {

namespace {

constexpr std::array<std::string_view, 5> sweep_keys{"curve", "closed", "radius", "point", "material"};

}  // namespace

struct SceneParser::SweepReading {
    SceneNode& node;
    SweepCurve curve = SweepCurve::CatmullRom;
    bool closed = false;
    std::optional<double> radius;  // the sweep's, for points that give none
    std::vector<SweepPoint> points;
    std::vector<std::optional<SourceLocation>> own_radius;  // where each point gives its own
    std::optional<SourceLocation> first_point;
    std::map<std::string_view, SourceLocation> seen;  // the keys set once
};

SceneNodePtr SceneParser::sweep(const Token& keyword) {
    auto node = object_node(keyword);
    SweepReading reading{*node, SweepCurve::CatmullRom, false, {}, {}, {}, {}, {}};
    in_->expect(TokenKind::LeftBrace);
    while (!in_->accept(TokenKind::RightBrace)) {
        const Token& entry = in_->peek();
        if (entry.kind == TokenKind::End)
            in_->fail(entry.where, "expected '}' to close the sweep block opened at " + line_and_column(keyword.where) +
                                       ", but found end of file");
        if (!sweep_entry(reading))
            in_->fail_expected("a key (" + join_words(sweep_keys, "or") + "), a transform, let, for or '}'");
    }
    if (reading.curve == SweepCurve::Bezier)
        for (std::size_t i = 0; i < reading.points.size(); ++i)
            if (i % 3 != 0 && reading.own_radius[i])
                in_->fail(*reading.own_radius[i], "a Bézier control point takes no radius: the radius goes linearly "
                                                  "from each piece's first point to its last");
    Object& object = node->object;
    try {
        object.sweep = std::make_shared<const std::vector<SweptSegment>>(
            sweep_segments(reading.curve, reading.points, reading.closed));
    } catch (const std::invalid_argument& e) {
        in_->fail(reading.first_point.value_or(keyword.where), std::string("sweep: ") + e.what());
    }
    Box3 box = empty_box();
    for (const SweptSegment& s : *object.sweep) box = united(box, s.bounds());
    object.bounds = Bounds::make_box(box);
    return node;
}

bool SceneParser::sweep_entry(SweepReading& reading) {
    if (body_entry(reading.node, "a point", [this, &reading] { return sweep_entry(reading); })) return true;
    const Token& entry = in_->peek();
    if (!is_one_of(sweep_keys, entry)) return false;
    const std::string_view word = entry.text;
    if (word != "point") {
        set_once(reading.seen, entry, "sweep");
        if (reading.first_point && (word == "radius" || word == "curve"))
            in_->fail(entry.where, "the sweep's " + std::string(word) + " must come before its points (a radius after "
                                   "a point is that point's own)");
    }
    in_->next();
    if (word == "curve") {
        std::vector<std::string_view> names;
        for (const SweepCurveInfo& c : sweep_curves) names.push_back(c.name);
        reading.curve = *sweep_curve_named(choice("curve", names).text);
    } else if (word == "closed") {
        reading.closed = on_off("closed");
    } else if (word == "radius") {
        const auto [r, where] = number("the radius");
        if (!(r > 0.0)) in_->fail(where, "the sweep's radius must be positive");
        reading.radius = r;
    } else if (word == "point") {
        if (++objects_ > limits_.objects)
            in_->fail(entry.where, "the scene makes more than " + std::to_string(limits_.objects) + " objects and sweep points");
        if (!reading.first_point) reading.first_point = entry.where;
        SweepPoint p{vector("the point").value, 0.0};
        std::optional<SourceLocation> own;
        if (in_->peek().kind == TokenKind::Name && in_->peek().text == "radius") {
            own = in_->next().where;
            const auto [r, where] = number("the point's radius");
            if (!(r >= 0.0)) in_->fail(where, "a point's radius must not be negative");
            p.radius = r;
        } else if (reading.radius) {
            p.radius = *reading.radius;
        } else {
            in_->fail(entry.where, "this point has no radius: give the sweep one (radius R, before its points) or "
                                   "the point its own (point (x, y, z) radius R)");
        }
        reading.points.push_back(p);
        reading.own_radius.push_back(own);
    } else {
        reading.node.material = material(entry);
    }
    return true;
}

}  // namespace zeroset
