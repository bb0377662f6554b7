// `fractal "name" { kind julia c (…) … }` in the scene language
// (docs/fractals.md): a deterministic 3-D fractal by its distance estimate
// (trace/fractal_estimate.hpp), read into an object node whose Object
// carries the estimate.
#include <array>
#include <map>

#include "zeroset/scene/scene_error.hpp"
#include "zeroset/scene/scene_parser.hpp"
#include "zeroset/scene/wording.hpp"

namespace zeroset {

namespace {

constexpr std::array<std::string_view, 8> fractal_keys{"kind",       "c",      "ck",     "slice",
                                                       "iterations", "power",  "detail", "material"};

}  // namespace

SceneNodePtr SceneParser::fractal(const Token& keyword) {
    auto node = object_node(keyword);
    FractalParameters p;
    std::map<std::string_view, SourceLocation> seen;
    in_->expect(TokenKind::LeftBrace);
    while (!in_->accept(TokenKind::RightBrace)) {
        const Token& entry = in_->peek();
        if (entry.kind == TokenKind::End)
            in_->fail(entry.where, "expected '}' to close the fractal block opened at " + line_and_column(keyword.where) +
                                       ", but found end of file");
        if (is_one_of(transform_keys, entry)) {
            in_->next();
            add_transform(entry, *node);
            continue;
        }
        if (!is_one_of(fractal_keys, entry))
            in_->fail_expected("a key (" + join_words(fractal_keys, "or") + "), a transform or '}'");
        const std::string_view word = entry.text;
        set_once(seen, entry, "fractal");
        in_->next();
        if (word == "kind") {
            std::vector<std::string_view> names;
            for (const FractalKindInfo& k : fractal_kinds()) names.push_back(k.name);
            p.kind = *fractal_kind_named(choice("kind", names).text);
        } else if (word == "c") {
            const Vec3d c = vector("c (its real, i and j parts)").value;
            p.c.r = c.x;
            p.c.i = c.y;
            p.c.j = c.z;
        } else if (word == "ck") {
            p.c.k = number("ck (the k part of c)").value;
        } else if (word == "slice") {
            p.slice = number("the slice").value;
        } else if (word == "iterations") {
            p.iterations = count("the iterations", max_fractal_iterations);
        } else if (word == "power") {
            const auto [power, where] = number("the power");
            if (!(power >= min_mandelbulb_power && power <= max_mandelbulb_power))
                in_->fail(where, "the power must be between 2 and 16");
            p.power = power;
        } else if (word == "detail") {
            const auto [detail, where] = number("the detail");
            if (!(detail > 0.0)) in_->fail(where, "the detail (the hit tolerance, in pixels) must be positive");
            node->object.fractal_detail = detail;
        } else {
            node->material = material(entry);
        }
    }
    const bool julia = p.kind == FractalKind::QuaternionJulia;
    for (const std::string_view key : {"c", "ck", "slice"})
        if (!julia && seen.contains(key))
            in_->fail(seen.at(key), "'" + std::string(key) + "' is for Julia sets (kind julia)");
    if (julia && seen.contains("power")) in_->fail(seen.at("power"), "'power' is for Mandelbulbs (kind mandelbulb)");
    Object& object = node->object;
    try {
        object.fractal = std::make_shared<const FractalEstimate>(p);
    } catch (const std::invalid_argument& e) {
        in_->fail(keyword.where, std::string("fractal: ") + e.what());
    }
    const double r = object.fractal->bounding_radius();
    object.bounds = Bounds::make_box({{-r, -r, -r}, {r, r, r}});
    return node;
}

}  // namespace zeroset
