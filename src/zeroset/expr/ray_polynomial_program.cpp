// Compiling a tape into coefficient steps, and running them along a ray.
#include "zeroset/expr/ray_polynomial_program.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include "zeroset/expr/op.hpp"
#include "zeroset/math/scalar.hpp"

namespace zeroset {

namespace {

/// A rounding count standing for "no bound".
constexpr int unknown_roundings = std::numeric_limits<int>::max() / 4;
/// libm's functions on an exact constant: within 2 ulp, i.e. 4 roundings.
constexpr int libm_roundings = 4;

int add_roundings(int a, int b) { return std::min(a + b, unknown_roundings); }

/// γ_k = k·u / (1 − k·u), +∞ once k·u ≥ 1/2.
double gamma(int k) {
    const double ku = static_cast<double>(k) * unit_roundoff;
    return ku < 0.5 ? ku / (1.0 - ku) : std::numeric_limits<double>::infinity();
}

}  // namespace

/// Walks the tape once, tracking per slot where its coefficients live, their
/// structural degree and their rounding count.
class RayPolynomialCompiler {
public:
    RayPolynomialCompiler(const Tape& tape, int input_roundings)
        : tape_(tape), slots_(tape.slot_count()), input_roundings_(input_roundings) {}

    RayPolynomialProgram::Compiled run() {
        for (const std::uint32_t s : {Tape::slot_x, Tape::slot_y, Tape::slot_z}) {
            slots_[s] = allocate(1, input_roundings_);
            p_.variable_offset_[s] = slots_[s].offset;
        }
        for (const auto& [slot, value] : tape_.constants()) {
            slots_[slot] = allocate(0, 0);
            p_.pairs_[slots_[slot].offset] = RayPolynomialProgram::Pair{value, std::abs(value)};
        }
        for (const Clause& c : tape_.clauses()) {
            const auto out = clause(c);
            if (!out) return {std::nullopt, refusal_};
            slots_[c.out] = *out;
        }
        const SlotState& result = slots_[tape_.result_slot()];
        p_.result_offset_ = result.offset;
        p_.degree_ = result.degree;
        // M is rounded down by at most (1 − u)^K: γ_2K covers both; the
        // product radius() forms is rounded once more.
        p_.radius_scale_ = gamma(2 * result.roundings) * (1.0 + 4.0 * unit_roundoff);
        return {std::move(p_), std::nullopt};
    }

private:
    using Kind = RayPolynomialProgram::StepKind;
    struct SlotState {
        std::uint32_t offset = 0;
        int degree = 0;
        int roundings = 0;
    };

    SlotState allocate(int degree, int roundings) {
        const auto offset = static_cast<std::uint32_t>(p_.pairs_.size());
        p_.pairs_.resize(p_.pairs_.size() + static_cast<std::size_t>(degree) + 1, RayPolynomialProgram::Pair{0.0, 0.0});
        return {offset, degree, roundings};
    }

    /// Emits a step — or, when every operand is a constant, runs it now.
    SlotState emit(Kind kind, const SlotState& a, const SlotState& b, int degree, int roundings) {
        const SlotState out = allocate(degree, roundings);
        const RayPolynomialProgram::Step step{kind,
                                              static_cast<std::uint8_t>(a.degree),
                                              static_cast<std::uint8_t>(b.degree),
                                              a.offset,
                                              b.offset,
                                              out.offset,
                                              RayPolynomialProgram::kernel_for(kind, a.degree, b.degree)};
        if (a.degree == 0 && b.degree == 0) {
            step.kernel(step, p_.pairs_.data());
        } else {
            p_.steps_.push_back(step);
        }
        return out;
    }

    SlotState product(const SlotState& a, const SlotState& b) {
        const int terms = std::min(a.degree, b.degree) + 1;
        return emit(Kind::Mul, a, b, a.degree + b.degree, add_roundings(add_roundings(a.roundings, b.roundings), terms));
    }

    /// aⁿ (n ≥ 1) by repeated squaring, unrolled into products.
    SlotState power(SlotState a, int n) {
        std::optional<SlotState> result;
        while (n != 0) {
            if (n & 1) result = result ? product(*result, a) : a;
            n >>= 1;
            if (n != 0) a = product(a, a);
        }
        return *result;
    }

    /// A constant computed by double arithmetic (an op outside polynomial
    /// arithmetic): 4 roundings of exact operands, else no bound.
    SlotState folded(double value, const SlotState& a, const SlotState& b) {
        const bool exact = a.roundings == 0 && b.roundings == 0;
        SlotState out = allocate(0, exact ? libm_roundings : unknown_roundings);
        p_.pairs_[out.offset] = RayPolynomialProgram::Pair{value, std::abs(value)};
        return out;
    }

    std::optional<SlotState> refuse(RayPolynomialProgram::Refusal why) {
        refusal_ = why;
        return std::nullopt;
    }

    [[nodiscard]] double constant(const SlotState& s) const { return p_.pairs_[s.offset][0]; }

    std::optional<SlotState> clause(const Clause& c) {
        using Refusal = RayPolynomialProgram::Refusal;
        const SlotState a = slots_[c.a];
        const SlotState b = c.op == Op::Powi ? a : slots_[c.b];
        const bool constants = a.degree == 0 && b.degree == 0;
        const auto too_high = [](long long d) { return d > RayPolynomialProgram::max_degree; };
        switch (c.op) {
            case Op::Add:
            case Op::Sub:
                return emit(c.op == Op::Add ? Kind::Add : Kind::Sub, a, b, std::max(a.degree, b.degree),
                            add_roundings(std::max(a.roundings, b.roundings), 1));
            case Op::Neg: return emit(Kind::Neg, a, a, a.degree, a.roundings);
            case Op::Mul:
            case Op::Square: {
                const SlotState& other = c.op == Op::Mul ? b : a;
                if (too_high(static_cast<long long>(a.degree) + other.degree)) return refuse(Refusal::DegreeTooHigh);
                return product(a, other);
            }
            case Op::Div:
                if (b.degree != 0 || constant(b) == 0.0) return refuse(Refusal::NotPolynomial);
                return emit(Kind::Scale, a, b, a.degree,
                            b.roundings == 0 ? add_roundings(a.roundings, 1) : unknown_roundings);
            case Op::Powi:
            case Op::Pow: {
                const auto n = c.op == Op::Powi ? std::optional<int>(static_cast<int>(c.b))
                                                : (b.degree == 0 && b.roundings == 0 ? integer_value(constant(b))
                                                                                     : std::nullopt);
                const bool natural = n && *n >= 1;
                if (constants && !natural) {
                    return folded(apply_op<double>(c.op, constant(a), constant(b), static_cast<int>(c.b)), a,
                                  c.op == Op::Powi ? SlotState{} : b);
                }
                if (!n || *n < 0) return refuse(Refusal::NotPolynomial);
                if (*n == 0) return folded(1.0, SlotState{}, SlotState{});
                if (too_high(static_cast<long long>(a.degree) * *n)) return refuse(Refusal::DegreeTooHigh);
                return power(a, *n);
            }
            default:  // sqrt, abs, exp, log, sin, cos, tan, atan, atan2, floor, hypot, min, max; leaves are no clauses
                if (!constants) return refuse(Refusal::NotPolynomial);
                return folded(apply_op<double>(c.op, constant(a), constant(b), static_cast<int>(c.b)), a,
                              op_arity(c.op) == 2 ? b : SlotState{});
        }
    }

private:
    const Tape& tape_;
    std::vector<SlotState> slots_;
    RayPolynomialProgram p_;
    RayPolynomialProgram::Refusal refusal_ = RayPolynomialProgram::Refusal::NotPolynomial;
    int input_roundings_;
};

namespace {

using Pair = RayPolynomialProgram::Pair;
using Step = RayPolynomialProgram::Step;
using StepKind = RayPolynomialProgram::StepKind;

/// One step, written once for two uses: with plain ints for any degrees,
/// and with std::integral_constant degrees and kind, where every loop has a
/// known length and the compiler unrolls it. Every case gives the same bits
/// as the plain loops it stands for (a sum of products started from 0, in
/// increasing order of the first operand's index; a difference as a sum with
/// the negated operand; the product of two linear operands without the 0, as
/// it always was — +0 + −0 would turn a −0 coefficient into +0); they only
/// leave out padding, zero fills and branches.
template <class Kind, class DegreeA, class DegreeB>
inline void run_step(Kind kind_, DegreeA da_, DegreeB db_, Pair* out, const Pair* a, const Pair* b) {
    const StepKind kind = kind_;
    const int da = da_;
    const int db = db_;
    constexpr Pair zero{0.0, 0.0};
    switch (kind) {
        case StepKind::Add:
        case StepKind::Sub: {
            // F's coefficients add or subtract; M's always add.
            const Pair sign{kind == StepKind::Add ? 1.0 : -1.0, 1.0};
            const int common = std::min(da, db);
            for (int i = 0; i <= common; ++i) out[i] = a[i] + sign * b[i];
            for (int i = common + 1; i <= da; ++i) out[i] = a[i] + sign * zero;  // the other's zero padding
            for (int i = common + 1; i <= db; ++i) out[i] = zero + sign * b[i];
            break;
        }
        case StepKind::Neg: {
            const Pair sign{-1.0, 1.0};
            for (int i = 0; i <= da; ++i) out[i] = sign * a[i];
            break;
        }
        case StepKind::Mul:
            if (da == 1 && db == 1) {  // the square or product of two coordinates: the commonest step
                out[0] = a[0] * b[0];
                out[1] = a[0] * b[1] + a[1] * b[0];
                out[2] = a[1] * b[1];
                break;
            }
            if (db == 0) {  // times a constant
                for (int i = 0; i <= da; ++i) out[i] = zero + a[i] * b[0];
                break;
            }
            if (da == 0) {
                for (int j = 0; j <= db; ++j) out[j] = zero + a[0] * b[j];
                break;
            }
            for (int k = 0; k <= da + db; ++k) {  // each coefficient of the product as one sum
                Pair sum = zero;
                for (int i = std::max(0, k - db); i <= std::min(k, da); ++i) sum += a[i] * b[k - i];
                out[k] = sum;
            }
            break;
        case StepKind::Scale: {
            const Pair divisor{b[0][0], std::abs(b[0][0])};
            for (int i = 0; i <= da; ++i) out[i] = a[i] / divisor;
            break;
        }
    }
}

void general_kernel(const Step& s, Pair* pairs) {
    run_step(s.kind, int{s.a_degree}, int{s.b_degree}, pairs + s.out, pairs + s.a, pairs + s.b);
}

/// Degrees up to this get kernels of their own (quartics' steps all do).
constexpr int fixed_degree_limit = 4;
constexpr int fixed_degrees = fixed_degree_limit + 1;

template <StepKind K, int A, int B>
void fixed_kernel(const Step& s, Pair* pairs) {
    run_step(std::integral_constant<StepKind, K>{}, std::integral_constant<int, A>{}, std::integral_constant<int, B>{},
             pairs + s.out, pairs + s.a, pairs + s.b);
}

template <StepKind K, int... I>
constexpr std::array<RayPolynomialProgram::Kernel, sizeof...(I)> fixed_kernels(std::integer_sequence<int, I...>) {
    return {&fixed_kernel<K, I / fixed_degrees, I % fixed_degrees>...};
}

template <StepKind K>
constexpr auto fixed_kernels_of_kind = fixed_kernels<K>(std::make_integer_sequence<int, fixed_degrees * fixed_degrees>{});

/// The fixed kernels by kind (in StepKind's order), then by degrees.
constexpr std::array fixed_kernel_table{fixed_kernels_of_kind<StepKind::Add>, fixed_kernels_of_kind<StepKind::Sub>,
                                        fixed_kernels_of_kind<StepKind::Neg>, fixed_kernels_of_kind<StepKind::Mul>,
                                        fixed_kernels_of_kind<StepKind::Scale>};

}  // namespace

RayPolynomialProgram::Kernel RayPolynomialProgram::kernel_for(StepKind kind, int a_degree, int b_degree) {
    if (a_degree > fixed_degree_limit || b_degree > fixed_degree_limit) return &general_kernel;
    return fixed_kernel_table[static_cast<std::size_t>(kind)][static_cast<std::size_t>(a_degree * fixed_degrees + b_degree)];
}

RayPolynomialProgram::Compiled RayPolynomialProgram::compile(const Tape& tape) {
    return compile(tape, default_input_roundings);
}

RayPolynomialProgram::Compiled RayPolynomialProgram::compile(const Tape& tape, int input_roundings) {
    return RayPolynomialCompiler(tape, input_roundings).run();
}

[[gnu::always_inline]] inline void RayPolynomialProgram::run() {
    for (const Step& s : steps_) s.kernel(s, pairs_.data());
    for (int i = 0; i <= degree_; ++i) {
        const Pair& p = pairs_[result_offset_ + static_cast<std::size_t>(i)];
        value_[static_cast<std::size_t>(i)] = p[0];
        magnitude_[static_cast<std::size_t>(i)] = p[1];
    }
}

// Inlined into both evaluate()s: called per coordinate, it was a tenth of a quartic's run.
[[gnu::always_inline]] inline void RayPolynomialProgram::load_variable(int k, double o, double d, double t_c,
                                                                       double direction_magnitude,
                                                                       double centre_uncertainty) {
    // centre = o + t_c·d, with its rounding error found exactly and added back.
    const double product = t_c * d;
    const double product_error = std::fma(t_c, d, -product);
    const double sum = o + product;
    const double virtual_product = sum - o;
    const double sum_error = (o - (sum - virtual_product)) + (product - virtual_product);
    const double residual = sum_error + product_error;
    const double centre = sum + residual;
    const std::uint32_t at = variable_offset_[k];
    pairs_[at] = Pair{centre, std::abs(centre) + std::abs(residual) + centre_uncertainty};
    pairs_[at + 1] = Pair{d, direction_magnitude};
}

void RayPolynomialProgram::evaluate(const Ray& ray, double t_c) {
    const double origin[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const double direction[3] = {ray.dir.x, ray.dir.y, ray.dir.z};
    for (int k = 0; k < 3; ++k) load_variable(k, origin[k], direction[k], t_c, std::abs(direction[k]), 0.0);
    run();
}

void RayPolynomialProgram::evaluate(const Ray& ray, double t_c, const Vec3d& direction_magnitude) {
    const double origin[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const double direction[3] = {ray.dir.x, ray.dir.y, ray.dir.z};
    const double magnitude[3] = {direction_magnitude.x, direction_magnitude.y, direction_magnitude.z};
    // The direction's error moves the centre by |t_c| times as much.
    for (int k = 0; k < 3; ++k)
        load_variable(k, origin[k], direction[k], t_c, magnitude[k], std::abs(t_c) * magnitude[k]);
    run();
}

}  // namespace zeroset
