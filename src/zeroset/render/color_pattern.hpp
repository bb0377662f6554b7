// A material's colour pattern — three expressions of the object's own
// coordinates (render/../scene/scene.hpp, Material::color_pattern) — compiled
// to tapes once per scene and evaluated at a hit by each thread's own
// evaluators, so shading a pattern never allocates.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/tape.hpp"
#include "zeroset/math/vec3.hpp"

namespace zeroset {

struct ColorPatternTapes {
    explicit ColorPatternTapes(const std::array<Expr, 3>& rgb) : tapes{Tape(rgb[0]), Tape(rgb[1]), Tape(rgb[2])} {}
    std::array<Tape, 3> tapes;
};

class ColorPatternEvaluator {
public:
    explicit ColorPatternEvaluator(const ColorPatternTapes& pattern)
        : rgb_{Evaluator<double>(pattern.tapes[0]), Evaluator<double>(pattern.tapes[1]),
               Evaluator<double>(pattern.tapes[2])} {}

    /// The colour at a point of the object's space; negative components are
    /// 0, NaN stays NaN (the renderer reports the pixel).
    Vec3d operator()(const Vec3d& p) {
        Vec3d c;
        for (int i = 0; i < 3; ++i) {
            const double v = rgb_[static_cast<std::size_t>(i)](p.x, p.y, p.z);
            c[i] = v < 0.0 ? 0.0 : v;
        }
        return c;
    }

private:
    std::array<Evaluator<double>, 3> rgb_;
};

}  // namespace zeroset
