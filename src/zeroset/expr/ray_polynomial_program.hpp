// The ray polynomial, compiled. The polynomial method needs F(t) = f(o + t·d)
// for every ray (survey §3.3–3.4) and, since its coefficients are rounded, a
// proven bound on their error. Walking the tape with a Polynomial number type
// (expr/ray_polynomial.hpp, the reference) moves 33-coefficient arrays through
// every clause; here the tape is compiled once into straight-line coefficient
// arithmetic whose sizes are the clauses' structural degrees, constant
// clauses are folded at compile time, and powers are unrolled into products.
//
// Along the ray the parameter is centred: s = t − t_c with t_c in the span,
// x = (o + t_c·d) + s·d. About t_c the values stay near the surface's size
// instead of the camera's distance, which shrinks both the cancellation in
// the coefficients and the rounding of every evaluation of F.
//
// The error bound is the classical a-priori one (Higham, "Accuracy and
// Stability of Numerical Algorithms", §3.1, Lemma 3.3). Alongside each
// coefficient the program carries the magnitude polynomial M — the same
// computation on absolute values, with subtraction made addition — and, per
// clause, K, the number of roundings on the longest path to it, which depends
// only on the tape and is found at compile time: a sum adds one rounding, a
// product of degrees m and n adds min(m, n) + 1 to the sum of its operands'
// counts (γ_a + γ_b + γ_a·γ_b ≤ γ_(a+b)), a division by an exact constant
// one. Then |c_i − ĉ_i| ≤ γ_K·M_i with γ_K = K·u/(1 − K·u); M is itself
// rounded down by at most (1 − u)^K, which radius() absorbs by using γ_2K.
// The centre o + t_c·d is rounded too: its error is found exactly (an FMA for
// the product, Knuth's TwoSum for the sum), added back once, and counted as
// 2 roundings of a magnitude that includes it. Constants are exact: the
// surface is f with the tape's double constants. A libm function of an exact
// constant (sqrt(2) left unfolded) counts 4 roundings (≤ 2 ulp); of a rounded
// one, or a division by a rounded constant, the bound is lost: error_known()
// is false and the method falls back to trusting the rounded coefficients.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "zeroset/expr/tape.hpp"
#include "zeroset/math/ray.hpp"

namespace zeroset {

class RayPolynomialProgram {
public:
    static constexpr int max_degree = 32;

    /// Why a tape does not compile.
    enum class Refusal : std::uint8_t {
        NotPolynomial,  // an op outside polynomial arithmetic on something that depends on x, y, z
        DegreeTooHigh,  // the structural degree exceeds max_degree
    };

    /// The program for f, or the reason there is none. The structural degree
    /// rules: constants are degree 0 and any op on them is a constant; + −
    /// take the max, × adds, square doubles, powi and pow with a constant
    /// integral exponent n ≥ 0 multiply by n, division by a constant keeps
    /// the degree; anything else on a non-constant is not polynomial.
    struct Compiled;
    static Compiled compile(const Tape& tape);
    /// The same with each coordinate's line o + t·d taken to be off by up
    /// to `input_roundings` roundings of its magnitude (the centre's own
    /// error counts 2, the default): for directions computed from others.
    static Compiled compile(const Tape& tape, int input_roundings);
    static constexpr int default_input_roundings = 2;

    /// F's structural degree — an upper bound on its degree along any ray.
    [[nodiscard]] int degree() const { return degree_; }
    [[nodiscard]] bool error_known() const { return std::isfinite(radius_scale_); }

    /// Computes the coefficients of G(s) = F(t_c + s) along the ray; valid
    /// until the next call. Allocates nothing.
    void evaluate(const Ray& ray, double t_c);
    /// The same for a direction computed from others, within the program's
    /// input roundings (compile) of `direction_magnitude` (≥ |ray.dir| in
    /// each coordinate) of the exact one: the radii then bound the
    /// coefficients along the exact direction, whose error moves the centre
    /// by up to |t_c| times as much.
    void evaluate(const Ray& ray, double t_c, const Vec3d& direction_magnitude);

    /// G's rounded coefficients ĉ₀ … ĉ_degree(), ascending.
    [[nodiscard]] std::span<const double> value() const { return result(value_); }
    /// The magnitude polynomial M, ascending.
    [[nodiscard]] std::span<const double> magnitude() const { return result(magnitude_); }
    /// r_i ≥ |c_i − ĉ_i| for G's exact coefficient c_i (+∞ when the bound is
    /// lost).
    [[nodiscard]] double radius(int i) const { return radius_scale_ * magnitude_[static_cast<std::size_t>(i)]; }

    // The compiled steps; public for the step kernels (ray_polynomial_program.cpp).
    enum class StepKind : std::uint8_t { Add, Sub, Neg, Mul, Scale };

    /// A coefficient of F and the same coefficient of M side by side: every
    /// step does the same arithmetic on both (up to signs), so one 128-bit
    /// operation serves the two (GCC's and Clang's vector extension; SSE2 is
    /// in every x86-64).
    using Pair = double __attribute__((vector_size(16)));

    struct Step;
    /// The code that runs a step: compiled for its kind and operand degrees
    /// when both are small (loops of known length, unrolled), else general.
    using Kernel = void (*)(const Step& s, Pair* pairs);

    /// One coefficient operation: out = a ∘ b over ranges of the buffers.
    struct Step {
        StepKind kind;
        std::uint8_t a_degree, b_degree;
        std::uint32_t a, b, out;  // offsets into the buffers (b: a Scale's divisor)
        Kernel kernel;
    };

private:
    RayPolynomialProgram() = default;
    /// The kernel for a step of this kind and these degrees.
    static Kernel kernel_for(StepKind kind, int a_degree, int b_degree);
    /// Coordinate k's line about t_c into its slot: the centre o + t_c·d
    /// and the direction d, with their magnitudes.
    void load_variable(int k, double o, double d, double t_c, double direction_magnitude, double centre_uncertainty);
    /// The steps, once the variables' lines are loaded.
    void run();
    [[nodiscard]] std::span<const double> result(const std::array<double, max_degree + 1>& buffer) const {
        return {buffer.data(), static_cast<std::size_t>(degree_) + 1};
    }

    std::vector<Step> steps_;
    std::vector<Pair> pairs_;  // every clause's coefficients of F and M; constants preloaded
    std::array<double, max_degree + 1> value_{};      // the result's F, after evaluate()
    std::array<double, max_degree + 1> magnitude_{};  // and its M
    std::uint32_t variable_offset_[3] = {0, 0, 0};
    std::uint32_t result_offset_ = 0;
    int degree_ = 0;
    double radius_scale_ = 0.0;  // γ_2K (rounded up) for the result's K; +∞ when the bound is lost

    friend class RayPolynomialCompiler;
};

struct RayPolynomialProgram::Compiled {
    std::optional<RayPolynomialProgram> program;
    std::optional<Refusal> refusal;
};

}  // namespace zeroset
