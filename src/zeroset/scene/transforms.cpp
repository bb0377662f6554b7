// The affine transforms of the scene language (survey §9, eq. 36): translate,
// rotate, scale, shear and matrix, each a Mat4 from an object's own space to
// its parent's. Every one must be invertible — rays are moved by the inverse.
#include <array>
#include <cmath>

#include "zeroset/scene/constant_value.hpp"
#include "zeroset/scene/scene_parser.hpp"
#include "zeroset/scene/wording.hpp"

namespace zeroset {

namespace {

constexpr std::array<std::string_view, 6> shear_keys{"xy", "xz", "yx", "yz", "zx", "zy"};

/// A map this close to flattening space (Mat4::squareness) is refused: its
/// inverse would lose most of the digits of every moved ray.
constexpr double least_squareness = 1e-9;
/// The most a map or its inverse may stretch a length: beyond it, the
/// powers of a moved ray's direction in a ray polynomial overflow.
constexpr double most_stretch = 1e100;

}  // namespace

void SceneParser::add_transform(const Token& keyword, SceneNode& node) {
    // Applied after the node's earlier transforms; each one, and so what
    // they make together, must be invertible.
    const Mat4 m = read_transform(keyword);
    const std::string what(keyword.text);
    if (!m.is_finite()) in_->fail(keyword.where, what + ": the transform's numbers must be finite");
    for (const Mat4& check : {m, m * node.transform}) {
        const std::optional<Mat4> inverse = check.inverse();
        const auto too_large = [](const Mat4& a) { return !a.is_finite() || !(a.max_stretch() <= most_stretch); };
        if (too_large(check) || (inverse && too_large(*inverse)))
            in_->fail(keyword.where, what + ": the transform or its inverse stretches lengths by more than 1e100 "
                                            "(keep scale factors between 1e-100 and 1e100)");
        const double squareness = check.squareness();
        if (!inverse || !(squareness > least_squareness) || !std::isfinite(squareness))
            in_->fail(keyword.where, what + ": the transform is singular or nearly so (|det| / column lengths = " +
                                         format_number(squareness) + "); it would flatten the object");
    }
    node.transform = m * node.transform;
}

Mat4 SceneParser::read_transform(const Token& keyword) {
    const std::string_view k = keyword.text;
    if (k == "translate") return Mat4::translate(vector("the translation").value);
    if (k == "rotate") {
        const auto [v, where] = value();
        if (v.is_vector()) return Mat4::rotate_xyz_degrees(constant_vector(*in_, v, where, "the rotation angles"));
        const double angle = constant_number(*in_, v, where, "the rotation angle");
        const Token& word = in_->peek();
        if (word.kind != TokenKind::Name || word.text != "around")
            in_->fail_expected("'around' and an axis, as in rotate 30 around (0, 1, 0),");
        in_->next();
        const auto [axis, axis_at] = vector("the rotation axis");
        if (!(length(axis) > 0.0)) in_->fail(axis_at, "the rotation axis must not be zero");
        return Mat4::rotate_degrees(axis, angle);
    }
    if (k == "scale") {
        const auto [v, where] = value();
        const Vec3d s = v.is_vector() ? constant_vector(*in_, v, where, "the scale")
                                      : Vec3d{1, 1, 1} * constant_number(*in_, v, where, "the scale");
        if (s.x == 0.0 || s.y == 0.0 || s.z == 0.0)
            in_->fail(where, "a scale of 0 would flatten the object; scale by nonzero factors (negative mirrors)");
        return Mat4::scale(s);
    }
    Mat4 m = Mat4::identity();
    if (k == "shear") {
        // x gains xy·y + xz·z, y gains yx·x + yz·z, z gains zx·x + zy·y.
        block(keyword, shear_keys, [&](const Token& key) {
            const int row = key.text[0] - 'x', column = key.text[1] - 'x';
            m.m[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)] =
                number("shear " + std::string(key.text)).value;
        });
        return m;
    }
    // matrix (m00, m01, m02, m03, m10, …, m23): p' = A·p + t, row by row
    in_->expect(TokenKind::LeftParen);
    for (std::size_t i = 0; i < 12; ++i) {
        if (i > 0 && !in_->accept(TokenKind::Comma))
            in_->fail_expected("',' (a matrix has 12 numbers: 3 rows of A, each followed by its t)");
        m.m[i / 4][i % 4] = number("a matrix entry").value;
    }
    in_->expect(TokenKind::RightParen);
    return m;
}

}  // namespace zeroset
