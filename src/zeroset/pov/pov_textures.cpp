// POV-Ray textures as zeroset materials: a constant pigment colour and the
// finish's ambient, diffuse, phong, specular and reflection (the mapping is
// docs/povray.md's table). Patterns, normals, interiors, layered textures
// and the finish's other terms are read past and reported where the
// texture is used, with what is drawn instead.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "zeroset/pov/pov_parser.hpp"

namespace zeroset::pov {

namespace {

/// POV-Ray's default finish (3.7): ambient 0.1, diffuse 0.6, no highlights.
constexpr double default_ambient = 0.1, default_diffuse = 0.6, default_phong_size = 40.0, default_roughness = 0.05;

std::string format_color(const std::array<double, 5>& c) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "rgb <%.3g, %.3g, %.3g>", c[0], c[1], c[2]);
    return buffer;
}

}  // namespace

void PovFinish::merge(const PovFinish& later) {
    const auto take = [](std::optional<double>& mine, const std::optional<double>& theirs) {
        if (theirs) mine = theirs;
    };
    take(ambient, later.ambient);
    take(diffuse, later.diffuse);
    take(brilliance, later.brilliance);
    take(phong, later.phong);
    take(phong_size, later.phong_size);
    take(specular, later.specular);
    take(roughness, later.roughness);
    take(reflection, later.reflection);
}

void PovTexture::merge(const PovTexture& later) {
    if (later.color) color = later.color;
    finish.merge(later.finish);
    unsupported.insert(unsupported.end(), later.unsupported.begin(), later.unsupported.end());
}

std::optional<std::array<double, 5>> PovParser::skip_rest(const PovToken& opened) {
    int depth = 1;
    std::optional<std::array<double, 5>> first_color;
    for (;;) {
        const PovToken& t = peek();
        if (t.kind == PovTokenKind::End) fail(opened, "this " + opened.text + " block is not closed by '}'");
        if (t.is_symbol("{")) ++depth;
        if (t.is_symbol("}") && --depth == 0) {
            next();
            return first_color;
        }
        if (!first_color && starts_color(t)) {
            first_color = color_value(next()).v;
            continue;
        }
        next();
    }
}

void PovParser::left_out(PovTexture& texture, const PovToken& at, const std::string& what,
                         const std::optional<std::array<double, 5>>& first_color) {
    if (!texture.color && first_color) {
        texture.color = first_color;
        texture.unsupported.push_back(located(at) + ": " + what + " is not supported; rendered as its first colour, " +
                                      format_color(*first_color));
    } else {
        texture.unsupported.push_back(located(at) + ": " + what + " is not supported; left out");
    }
}

void PovParser::skip_block(const PovToken& keyword, const std::string& what, PovTexture* texture) {
    expect_symbol("{", "after " + keyword.text);
    const auto first_color = skip_rest(keyword);
    if (texture) left_out(*texture, keyword, what, keyword.text == "pigment" ? first_color : std::nullopt);
    else note(keyword, what + " is not supported; left out");
}

bool PovParser::texture_item(PovTexture& texture) {
    const Nesting nesting(*this);
    const PovToken& t = peek();
    if (t.kind != PovTokenKind::Name) return false;
    const std::string word = t.text;
    if (word == "pigment") {
        pigment_block(next(), texture);
    } else if (word == "finish") {
        const PovToken k = next();
        finish_block(k, texture.finish);
    } else if (word == "normal") {
        const PovToken k = next();
        skip_block(k, "a normal (bump pattern)", &texture);
    } else if (word == "interior") {
        const PovToken k = next();
        skip_block(k, "an interior (refraction, media)", &texture);
    } else if (word == "texture" || word == "material") {
        const PovToken k = next();
        expect_symbol("{", "after " + word);
        if (peek().kind == PovTokenKind::Name) {
            if (const PovValue* v = lookup(peek().text); v && v->kind == PovValue::Kind::Texture) {
                use(next().text);
                texture.merge(*v->texture);
            }
        }
        while (!accept_symbol("}")) {
            if (texture_item(texture)) continue;
            const PovToken u = peek();
            if (is_transform(u)) {
                next();
                (void)transform_statement(u);  // moves a pattern: a constant colour does not change
                continue;
            }
            // A pattern of textures, a texture_map, …: the rest of the block.
            left_out(texture, u, "'" + describe(u) + "' in a " + word, skip_rest(k));
            break;
        }
    } else {
        return false;
    }
    return true;
}

void PovParser::layers(PovTexture& texture) {
    while (peek_raw(0).is_name("texture")) {  // raw: a directive after the texture is not carried out early
        const PovToken at = peek();
        PovTexture layer;
        texture_item(layer);
        texture.unsupported.push_back(located(at) + ": a layered texture is not supported; rendered as its first layer");
    }
}

void PovParser::pigment_block(const PovToken& keyword, PovTexture& texture) {
    expect_symbol("{", "after pigment");
    if (accept_symbol("}")) {
        texture.color = std::array<double, 5>{};
        return;
    }
    const PovToken first = peek();
    const PovValue* named = first.kind == PovTokenKind::Name ? lookup(first.text) : nullptr;
    if (named && named->kind == PovValue::Kind::Texture) {
        use(next().text);
        texture.merge(*named->texture);
    } else if (starts_color(first) || first.is_symbol("<") || (named && named->is_numeric()) ||
               first.kind == PovTokenKind::Number) {
        texture.color = color("the pigment's colour");
    } else {  // a pattern (checker, gradient, image_map, …): the whole block
        const auto first_color = skip_rest(keyword);
        left_out(texture, first, "the pigment pattern " + describe(first), first_color);
        if (!texture.color) texture.color = std::array<double, 5>{};
        return;
    }
    while (!accept_symbol("}")) {
        const PovToken t = peek();
        if (is_transform(t)) {
            next();
            (void)transform_statement(t);
        } else if (t.is_name("quick_color") || t.is_name("quick_colour")) {
            next();
            (void)color("the quick colour");
        } else if (t.kind == PovTokenKind::End) {
            fail(keyword, "this pigment block is not closed by '}'");
        } else {
            left_out(texture, t, "'" + describe(t) + "' after a pigment's colour", skip_rest(keyword));
            return;
        }
    }
}

void PovParser::finish_block(const PovToken& keyword, PovFinish& finish) {
    expect_symbol("{", "after finish");
    if (peek().kind == PovTokenKind::Name) {
        if (const PovValue* v = lookup(peek().text); v && v->kind == PovValue::Kind::Texture) {
            use(next().text);
            finish.merge(v->texture->finish);
        }
    }
    while (!accept_symbol("}")) {
        const PovToken k = peek();
        if (k.kind == PovTokenKind::End) fail(keyword, "this finish block is not closed by '}'");
        if (k.kind != PovTokenKind::Name) fail_expected("a finish keyword or '}'");
        next();
        const std::string& w = k.text;
        const auto gray = [&](std::string_view what) {
            const PovToken at = peek();
            const std::array<double, 5> c = color(what);
            if (c[0] != c[1] || c[1] != c[2])
                warn(at, "a coloured " + std::string(what) + " is not supported; rendered as its mean, " +
                             std::to_string((c[0] + c[1] + c[2]) / 3.0));
            return (c[0] + c[1] + c[2]) / 3.0;
        };
        if (w == "ambient") {
            finish.ambient = gray("ambient");
        } else if (w == "diffuse") {
            accept_name("albedo");
            finish.diffuse = number("diffuse");
            if (accept_symbol(",")) {
                (void)number("the back side's diffuse");
                warn(k, "a back side diffuse is not supported; left out");
            }
        } else if (w == "brilliance") {
            finish.brilliance = number("brilliance");
        } else if (w == "phong") {
            accept_name("albedo");
            finish.phong = number("phong");
        } else if (w == "phong_size") {
            finish.phong_size = number("phong_size");
        } else if (w == "specular") {
            accept_name("albedo");
            finish.specular = number("specular");
        } else if (w == "roughness") {
            finish.roughness = number("roughness");
        } else if (w == "reflection") {
            if (peek().is_symbol("{")) {
                next();
                std::vector<double> values;
                while (!accept_symbol("}")) {
                    const PovToken& t = peek();
                    if (t.kind == PovTokenKind::Name && !lookup(t.text) && !starts_color(t)) {
                        const PovToken option = next();
                        if (option.text == "falloff" || option.text == "exponent") (void)number(option.text);
                        if (option.text == "metallic" && starts_optional_switch()) (void)number(option.text);
                        warn(option, "reflection's " + option.text + " is not supported; left out");
                        continue;
                    }
                    values.push_back(gray("reflection"));
                    accept_symbol(",");
                }
                if (values.size() > 1) warn(k, "a reflection varying with angle is not supported; rendered as its largest");
                if (!values.empty()) finish.reflection = *std::max_element(values.begin(), values.end());
            } else {
                finish.reflection = gray("reflection");
            }
        } else if (w == "emission") {
            (void)color("emission");
            warn(k, "emission is not supported; left out");
        } else if (w == "conserve_energy" || w == "metallic" || w == "crand" || w == "reflection_exponent" ||
                   w == "subsurface" || w == "irid" || w == "fresnel") {
            const PovToken& v = peek();
            if (v.is_symbol("{")) skip_block(k, "finish " + w, nullptr);
            else if (starts_optional_switch() || v.is_symbol("<") || v.is_symbol("(") || v.is_symbol("-") ||
                     (v.kind == PovTokenKind::Name && lookup(v.text)))
                (void)expression();
            warn(k, "the finish's " + w + " is not supported; left out");
        } else {
            fail(k, "unknown finish keyword '" + w + "'");
        }
    }
}

Material PovParser::material_of(const PovTexture& texture, const PovToken& at) {
    PovFinish f;
    f.ambient = default_ambient;
    f.diffuse = default_diffuse;
    f.merge(default_finish_);
    f.merge(texture.finish);
    Material m;
    const std::array<double, 5> c = texture.color.value_or(default_color_.value_or(std::array<double, 5>{}));
    m.color = {std::max(c[0], 0.0), std::max(c[1], 0.0), std::max(c[2], 0.0)};
    m.ambient = std::max(*f.ambient, 0.0);
    m.diffuse = std::max(*f.diffuse, 0.0);
    m.specular = 0.0;
    m.shininess = 1.0;
    // POV-Ray's highlights: phong p (cos of the mirror angle)^phong_size, and
    // specular s (Blinn's half-vector cosine)^(1/roughness). zeroset's is
    // Blinn's: for phong, the exponent 4·phong_size gives nearly the same spot.
    if (f.specular && *f.specular > 0.0) {
        m.specular = *f.specular;
        m.shininess = 1.0 / std::max(f.roughness.value_or(default_roughness), 1e-4);
    }
    if (f.phong && *f.phong > 0.0) {
        if (m.specular > 0.0) {
            warn(at, "phong and specular highlights together are not supported; rendered as the specular one, "
                     "with their strengths added");
            m.specular += *f.phong;
        } else {
            m.specular = *f.phong;
            m.shininess = 4.0 * f.phong_size.value_or(default_phong_size);
        }
    }
    m.reflection = std::clamp(f.reflection.value_or(0.0), 0.0, 1.0);
    for (const std::string& w : texture.unsupported)
        if (reported_.insert(w).second) result_.scene.warnings.push_back(w);
    if (f.brilliance && *f.brilliance != 1.0) warn(at, "the finish's brilliance is not supported; rendered as 1");
    return m;
}

}  // namespace zeroset::pov
