// The scene's tree in the scene language (docs/scene-language.md): objects,
// groups and unions, intersections and differences, shapes and their
// instances, and loops over all of them.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/scene/constant_value.hpp"
#include "zeroset/scene/expression_parser.hpp"
#include "zeroset/scene/scene_error.hpp"
#include "zeroset/scene/scene_parser.hpp"
#include "zeroset/scene/wording.hpp"

namespace zeroset {

namespace {

/// How much of an expression a message quotes.
constexpr std::size_t message_expression_chars = 200;

constexpr std::array<std::string_view, 11> object_keys{"surface", "bounds", "method", "solver", "normals", "partition",
                                                       "material", "cut",    "open",   "clip",   "gate"};
constexpr std::array<std::string_view, 9> node_keywords{"object",   "group", "union",   "intersection", "difference",
                                                        "instance", "blob",  "fractal", "sweep"};


/// True when f is exactly 0 at 64 points spread over the bounds (a fixed
/// pseudo-random set): x − x or x·0, which no arithmetic folds away, and
/// which would make every point a surface point.
bool vanishes_throughout(const Expr& f, const Bounds& bounds) {
    Box3 box = bounds.enclosing_box();
    if (bounds.kind == Bounds::Kind::None) box = {{-1, -1, -1}, {1, 1, 1}};
    const Tape tape(f);
    Evaluator<double> eval(tape);
    std::uint64_t state = 0x9e3779b97f4a7c15ULL;
    const auto unit = [&state] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(state >> 11) * 0x1p-53;
    };
    for (int i = 0; i < 64; ++i) {
        const Vec3d p{box.lo.x + unit() * (box.hi.x - box.lo.x), box.lo.y + unit() * (box.hi.y - box.lo.y),
                      box.lo.z + unit() * (box.hi.z - box.lo.z)};
        if (eval(p.x, p.y, p.z) != 0.0) return false;
    }
    return true;
}

/// A SceneError with a note on where it was reached from appended.
SceneError with_note(const SceneError& e, const std::string& note) {
    if (e.line() == 0) return SceneError(e.file(), e.message() + " (" + note + ")");
    return SceneError(e.file(), {e.line(), e.column()}, e.message() + " (" + note + ")");
}

}  // namespace

class SceneParser::Nesting {
public:
    Nesting(SceneParser& parser, const Token& at) : parser_(parser) {
        const int limit = parser_.limits_.block_nesting;  // past it the text is refused rather than risking the stack
        if (++parser_.depth_ > limit)
            parser_.in_->fail(at.where, "blocks nested too deeply (more than " + std::to_string(limit) + " levels)");
    }
    ~Nesting() { --parser_.depth_; }
    Nesting(const Nesting&) = delete;
    Nesting& operator=(const Nesting&) = delete;

private:
    SceneParser& parser_;
};

bool SceneParser::at_node_statement() const { return is_one_of(node_keywords, in_->peek()); }

void SceneParser::node_statement(const NodeSink& sink) {
    const Token& keyword = in_->next();
    const Nesting nesting(*this, keyword);
    const std::string_view k = keyword.text;
    if (k == "object") sink(object(keyword));
    else if (k == "blob") sink(blob(keyword));
    else if (k == "fractal") sink(fractal(keyword));
    else if (k == "sweep") sink(sweep(keyword));
    else if (k == "group" || k == "union") sink(composite(keyword, SceneNode::Kind::Group));
    else if (k == "intersection") sink(composite(keyword, SceneNode::Kind::Intersection));
    else if (k == "difference") sink(composite(keyword, SceneNode::Kind::Difference));
    else sink(instance(keyword));
}

std::shared_ptr<SceneNode> SceneParser::object_node(const Token& keyword) {
    if (++objects_ > limits_.objects)
        in_->fail(keyword.where, "the scene makes more than " + std::to_string(limits_.objects) + " objects");
    auto node = std::make_shared<SceneNode>();
    node->kind = SceneNode::Kind::Object;
    if (in_->at(TokenKind::String)) node->name = in_->next().text;
    node->defined_at = format_location(in_->file_name(), keyword.where);
    return node;
}

bool SceneParser::body_entry(SceneNode& node, std::string_view items, const std::function<bool()>& entry) {
    const Token& t = in_->peek();
    if (t.kind != TokenKind::Name) return false;
    if (t.text == "let") {
        in_->next();
        let();
        return true;
    }
    if (t.text == "for") {
        in_->next();
        loop(t, [&] {
            while (!in_->accept(TokenKind::RightBrace))
                if (!entry()) in_->fail_expected(std::string(items) + ", let, for or '}'");
        });
        return true;
    }
    if (is_one_of(transform_keys, t)) {
        in_->next();
        add_transform(t, node);
        return true;
    }
    return false;
}

void SceneParser::set_once(std::map<std::string_view, SourceLocation>& seen, const Token& key, std::string_view block) {
    if (const auto first = seen.find(key.text); first != seen.end())
        in_->fail(key.where, "'" + std::string(key.text) + "' is already set in this " + std::string(block) + " block (at " +
                                 line_and_column(first->second) + ")");
    seen.emplace(key.text, key.where);
}

SceneNodePtr SceneParser::object(const Token& keyword) {
    auto node = object_node(keyword);
    Object& object = node->object;
    bool has_surface = false;
    std::optional<SourceLocation> clip_at, gate_at;
    SourceLocation surface_at{};
    std::vector<std::string_view> keys(object_keys.begin(), object_keys.end());
    keys.insert(keys.end(), transform_keys.begin(), transform_keys.end());
    block(
        keyword, keys,
        [&](const Token& key) {
            if (is_one_of(transform_keys, key)) {
                add_transform(key, *node);
            } else if (key.text == "surface") {
                const auto [surface, where] = value();
                if (surface.is_vector())
                    in_->fail(where, "the surface must be a number (an expression in x, y, z), but found a vector");
                if (surface.number().is_constant_valued())
                    in_->fail(where, "the surface must depend on x, y or z, but it is the constant " +
                                         format_number(surface.number().value()));
                object.surface = surface.number();
                has_surface = true;
                surface_at = where;
            } else if (key.text == "bounds") {
                object.bounds = bounds();
            } else if (key.text == "gate") {
                gate_at = key.where;
                const Bounds gate = bounds();
                object.gate = gate.kind == Bounds::Kind::None ? std::nullopt : std::optional<Bounds>(gate);
            } else if (key.text == "method") {
                object.method = method();
            } else if (key.text == "solver") {
                object.solver = polynomial_solver();
            } else if (key.text == "normals") {
                object.normals = normal_mode();
            } else if (key.text == "partition") {
                object.partition = partition();
            } else if (key.text == "cut") {
                object.cut_by_bounds = on_off("cut");
            } else if (key.text == "open") {
                object.open = on_off("open");
            } else if (key.text == "clip") {
                const auto [clip, where] = value();
                if (clip.is_vector()) in_->fail(where, "the clip must be a number (an expression in x, y, z), but found a vector");
                object.clip = clip.number();
                clip_at = where;
            } else {
                node->material = material(key);
            }
        },
        transform_keys);
    if (!has_surface) in_->fail(keyword.where, "an object needs a surface");
    if (object.clip && !object.open) in_->fail(*clip_at, "a clip is for open objects: add open on");
    if (object.gate && object.bounds.kind == Bounds::Kind::None)
        in_->fail(*gate_at, "a gate is for bounded objects: an object with bounds none is a half-space, which every ray meets");
    if (vanishes_throughout(object.surface, object.bounds))
        in_->fail(surface_at, "the surface is 0 at every point tried in its bounds (" +
                                  object.surface.to_string(message_expression_chars) +
                                  "): it must be negative inside and positive outside to have an inside at all");
    return node;
}

SceneNodePtr SceneParser::composite(const Token& keyword, SceneNode::Kind kind) {
    auto node = std::make_shared<SceneNode>();
    node->kind = kind;
    if (in_->at(TokenKind::String)) node->name = in_->next().text;
    in_->expect(TokenKind::LeftBrace);
    node_body(keyword.text, keyword.where, *node);
    if (kind != SceneNode::Kind::Group && node->children.empty())
        in_->fail(keyword.where, std::string(kind == SceneNode::Kind::Intersection ? "an " : "a ") +
                                     std::string(keyword.text) + " needs at least one object, group or instance");
    return node;
}

bool SceneParser::child_entry(SceneNode& node) {
    const Token& entry = in_->peek();
    if (at_node_statement()) {
        node_statement([&node](SceneNodePtr child) { node.children.push_back(std::move(child)); });
        return true;
    }
    if (entry.kind != TokenKind::Name) return false;
    if (entry.text == "let") {
        in_->next();
        let();
        return true;
    }
    if (entry.text == "for") {
        in_->next();
        loop(entry, [this, &node] {
            while (!in_->accept(TokenKind::RightBrace))
                if (!child_entry(node))
                    in_->fail_expected("an object, blob, fractal, sweep, group, union, intersection, difference, instance, let, for or '}'");
        });
        return true;
    }
    return false;
}

void SceneParser::node_body(std::string_view what, SourceLocation opened_at, SceneNode& node) {
    std::optional<SourceLocation> material_at;
    while (!in_->accept(TokenKind::RightBrace)) {
        const Token& entry = in_->peek();
        if (entry.kind == TokenKind::End)
            in_->fail(entry.where, "expected '}' to close the " + std::string(what) + " block opened at " +
                                       line_and_column(opened_at) + ", but found end of file");
        if (child_entry(node)) continue;
        if (is_one_of(transform_keys, entry)) {
            in_->next();
            add_transform(entry, node);
            continue;
        }
        if (entry.kind == TokenKind::Name && entry.text == "material") {
            if (material_at)
                in_->fail(entry.where, "'material' is already set in this " + std::string(what) + " block (at " +
                                           line_and_column(*material_at) + ")");
            material_at = entry.where;
            in_->next();
            node.material = material(entry);
            continue;
        }
        in_->fail_expected("an object, blob, fractal, sweep, group, union, intersection, difference, instance, let, for, a transform "
                           "(translate, rotate, scale, shear, matrix), material or '}'");
    }
}

void SceneParser::skip_block(std::string_view what) {
    const Token& open = in_->expect(TokenKind::LeftBrace);
    for (int level = 1; level > 0;) {
        const Token& t = in_->next();
        if (t.kind == TokenKind::End)
            in_->fail(t.where, "expected '}' to close the " + std::string(what) + " opened at " + line_and_column(open.where) +
                                   ", but found end of file");
        if (t.kind == TokenKind::LeftBrace) ++level;
        if (t.kind == TokenKind::RightBrace) --level;
    }
}

void SceneParser::shape() {
    const Token& name = in_->expect(TokenKind::Name);
    check_unbound(name);
    auto definition = std::make_shared<ShapeDefinition>();
    definition->name = std::string(name.text);
    if (in_->accept(TokenKind::LeftParen) && !in_->accept(TokenKind::RightParen)) {
        do {
            const Token& parameter = in_->expect(TokenKind::Name);
            check_unbound(parameter);
            const std::string p(parameter.text);
            if (std::ranges::find(definition->parameters, p) != definition->parameters.end())
                in_->fail(parameter.where, "the shape already has a parameter '" + p + "'");
            definition->parameters.push_back(p);
        } while (in_->accept(TokenKind::Comma));
        if (!in_->accept(TokenKind::RightParen)) in_->fail_expected("',' or ')'");
    }
    if (!in_->at(TokenKind::LeftBrace)) in_->fail_expected("'{' to start the shape's body");
    definition->stream = in_;
    definition->body = in_->position();
    definition->visible = scope_.mark();
    definition->dir = dir_;
    skip_block("shape body");  // read when the shape is placed, once per list of arguments
    Binding binding{Expr(), format_location(in_->file_name(), name.where), definition};
    scope_.define(definition->name, std::move(binding));
}

SceneNodePtr SceneParser::instance(const Token& keyword) {
    const Token& name = in_->expect(TokenKind::Name);
    const Binding* binding = scope_.find(name.text);
    if (!binding || !binding->shape)
        in_->fail(name.where, binding ? "'" + std::string(name.text) + "' is not a shape"
                                      : "unknown shape '" + std::string(name.text) + "'");
    const std::shared_ptr<ShapeDefinition> definition = binding->shape;
    std::vector<Value> arguments;
    if (in_->accept(TokenKind::LeftParen) && !in_->accept(TokenKind::RightParen)) {
        do arguments.push_back(value().value);
        while (in_->accept(TokenKind::Comma));
        if (!in_->accept(TokenKind::RightParen)) in_->fail_expected("',' or ')'");
    }
    if (arguments.size() != definition->parameters.size())
        in_->fail(name.where, "shape '" + definition->name + "' takes " +
                                  std::to_string(definition->parameters.size()) + " argument" +
                                  (definition->parameters.size() == 1 ? "" : "s") + ", but " +
                                  std::to_string(arguments.size()) + (arguments.size() == 1 ? " was" : " were") +
                                  " given");
    std::vector<std::uint64_t> key;
    const auto add_expression = [&key](const Expr& e) {
        key.push_back(1);
        key.push_back(reinterpret_cast<std::uintptr_t>(e.id()));
    };
    for (const Value& a : arguments) {
        if (a.is_vector()) {
            for (const Expr& e : a.vector()) add_expression(e);
        } else if (a.is_constant()) {
            key.push_back(2);
            key.push_back(std::bit_cast<std::uint64_t>(a.constant()));
        } else {
            add_expression(a.number());
        }
        key.push_back(0);  // ends the argument: a vector and three numbers are told apart
    }
    ShapeDefinition::Reading& reading = definition->read[key];
    if (!reading.node) {
        reading.arguments = arguments;
        try {
            // Read the body where it is written, seeing what was visible there.
            const Detour detour(*this, *definition);
            const Scope::Frame frame(scope_, definition->visible);
            for (std::size_t i = 0; i < arguments.size(); ++i)
                scope_.define(definition->parameters[i], {arguments[i], "a parameter of shape " + definition->name});
            const Token& open = in_->next();  // the body's '{'
            auto node = std::make_shared<SceneNode>();
            node->name = definition->name;
            node_body("shape " + definition->name, open.where, *node);
            reading.node = std::move(node);
        } catch (const SceneError& e) {
            definition->read.erase(key);
            throw with_note(e, "in shape '" + definition->name + "' placed at " +
                                   format_location(in_->file_name(), name.where));
        }
    }
    auto node = std::make_shared<SceneNode>();
    node->kind = SceneNode::Kind::Group;
    node->name = definition->name;
    node->children.push_back(reading.node);
    if (in_->at(TokenKind::LeftBrace)) {
        std::vector<std::string_view> keys(transform_keys.begin(), transform_keys.end());
        keys.push_back("material");
        block(
            keyword, keys,
            [&](const Token& entry) {
                if (entry.text == "material") node->material = material(entry);
                else add_transform(entry, *node);
            },
            transform_keys);
    }
    return node;
}

SceneParser::Detour::Detour(SceneParser& parser, const ShapeDefinition& to)
    : parser_(parser),
      stream_(std::exchange(parser.in_, to.stream)),
      dir_(std::exchange(parser.dir_, to.dir)),
      position_(to.stream->position()) {
    to.stream->seek(to.body);
}

SceneParser::Detour::~Detour() {
    parser_.in_->seek(position_);
    parser_.in_ = stream_;
    parser_.dir_ = std::move(dir_);
}

void SceneParser::loop(const Token& keyword, const std::function<void()>& body) {
    const Token& name = in_->expect(TokenKind::Name);
    check_unbound(name);
    const auto expect_word = [this](std::string_view word) {
        const Token& t = in_->peek();
        if (t.kind != TokenKind::Name || t.text != word) in_->fail_expected("'" + std::string(word) + "'");
        in_->next();
    };
    expect_word("from");
    const auto [first, first_at] = number("the loop's start");
    expect_word("to");
    const auto [last, last_at] = number("the loop's end");
    double step = 1.0;
    if (in_->peek().kind == TokenKind::Name && in_->peek().text == "step") {
        in_->next();
        const auto [s, step_at] = number("the loop's step");
        if (s == 0.0) in_->fail(step_at, "the loop's step must not be 0");
        step = s;
    }
    const double span = (last - first) / step;
    if (span > static_cast<double>(limits_.loop_iterations))
        in_->fail(keyword.where, "the loop would run more than " + std::to_string(limits_.loop_iterations) + " times");
    const long long count = span < 0.0 ? 0 : static_cast<long long>(std::floor(span * (1.0 + 1e-12))) + 1;
    if ((iterations_ += count) > limits_.loop_iterations)
        in_->fail(keyword.where, "the scene's loops would run more than " + std::to_string(limits_.loop_iterations) +
                                     " times in all");
    if (!in_->at(TokenKind::LeftBrace)) in_->fail_expected("'{' to start the loop's body");
    const Nesting nesting(*this, keyword);
    const std::size_t start = in_->position();
    const std::string defined_at = format_location(in_->file_name(), name.where);
    for (long long k = 0; k < count; ++k) {
        const double i = first + static_cast<double>(k) * step;
        in_->seek(start);
        in_->next();  // '{'
        try {
            const Scope::Frame frame(scope_, scope_.mark());
            scope_.define(std::string(name.text), {i, defined_at});
            body();
        } catch (const SceneError& e) {
            throw with_note(e, "in the loop at " + format_location(in_->file_name(), keyword.where) + " with " +
                                   std::string(name.text) + " = " + format_number(i));
        }
    }
    if (count == 0) {  // the body is not read at all
        in_->seek(start);
        skip_block("loop body");
    }
}

}  // namespace zeroset
