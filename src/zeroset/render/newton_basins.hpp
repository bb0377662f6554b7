// The survey's Figure 5: the basins of Newton's method (eq. 22) for H(t) =
// f(x_o + t·x_d) over a rectangle of the complex t-plane. Each pixel is a
// start value t₀; Newton's method t ← t − H(t)/H′(t), run in complex
// arithmetic, converges to a real root (shaded in that root's colour, darker
// the more iterations it took), to a complex root (black), or diverges
// (white). The picture shows why §2 calls Newton's method unpredictable: the
// basins of the ray's intersections are fractal and interleaved, so a start
// value near the first root may well converge to the third.
#pragma once

#include <vector>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/tape.hpp"
#include "zeroset/math/complex.hpp"
#include "zeroset/math/ray.hpp"
#include "zeroset/render/image.hpp"

namespace zeroset {

/// A rectangle of the complex plane: re_min ≤ Re t ≤ re_max, im_min ≤ Im t ≤ im_max.
struct ComplexRect {
    double re_min, re_max, im_min, im_max;
};

struct BasinSettings {
    /// Shows the four real roots of the survey's blobs along the survey's ray
    /// (t ≈ 3.00, 4.50, 5.85, 6.25) and the complex roots around them.
    ComplexRect region{0.5, 9.1, -2.42, 2.42};
    int width = 480;
    int height = 270;
    int max_iterations = 100;  // more without converging counts as diverged
    int threads = 0;           // 0: all hardware threads
};

/// Where Newton's method from one start value ends up.
struct NewtonOutcome {
    enum class Kind { RealRoot, ComplexRoot, Diverged };
    Kind kind;
    Complex limit;   // the last iterate: the root unless Diverged
    int iterations;  // Newton steps taken
};

/// Newton's method (eq. 22) on H along `ray` from t₀, H and H′ from `eval`.
/// It has converged when a step is below 1e-10·max(1, |t|); the root is real
/// when |Im t| ≤ 1e-8·max(1, |t|) there. It diverges when t leaves the disc
/// |t| ≤ 1e10, becomes NaN or infinite, or has not converged after
/// `max_iterations` steps.
NewtonOutcome newton_from(Evaluator<Jet<Complex>>& eval, const Ray& ray, Complex t0, int max_iterations);

struct BasinMap {
    static constexpr int complex_root = -1;
    static constexpr int diverged = -2;

    Image image;                     // linear RGB, row 0 at Im t = im_max
    std::vector<double> real_roots;  // the distinct real limits, ascending
    std::vector<int> labels;         // per pixel, row-major: an index into real_roots, complex_root or diverged

    [[nodiscard]] int label_at(int x, int y) const {
        const auto w = static_cast<std::size_t>(image.width);
        return labels[static_cast<std::size_t>(y) * w + static_cast<std::size_t>(x)];
    }
};

/// The start value at the centre of pixel (x, y).
Complex basin_start(const BasinSettings& settings, int x, int y);

/// The full-brightness colour of the basin of real root number `index`
/// (a fixed palette of 10 colours, repeating; never black or white).
Vec3f basin_colour(int index);

/// Figure 5 for the surface `tape` along `ray` (its direction used as given,
/// not normalised). Rows are spread over threads; the result does not depend
/// on their number. Throws RenderError for bad settings (sizes outside
/// 1…65536, fewer than 1 or more than 100000 iterations, an empty or
/// non-finite rectangle) or a zero or non-finite ray.
BasinMap newton_basins(const Tape& tape, const Ray& ray, const BasinSettings& settings);

}  // namespace zeroset
