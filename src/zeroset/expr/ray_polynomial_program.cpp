// Compiling a tape into coefficient steps, and running them along a ray.
#include "zeroset/expr/ray_polynomial_program.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "zeroset/expr/op.hpp"

namespace zeroset {

namespace {

constexpr double unit_roundoff = std::numeric_limits<double>::epsilon() / 2.0;
/// A rounding count standing for "no bound".
constexpr int unknown_roundings = std::numeric_limits<int>::max() / 4;
/// libm's functions on an exact constant: within 2 ulp, i.e. 4 roundings.
constexpr int libm_roundings = 4;
/// The centred line's origin (see the header).
constexpr int centre_roundings = 2;

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
    explicit RayPolynomialCompiler(const Tape& tape) : tape_(tape), slots_(tape.slot_count()) {}

    RayPolynomialProgram::Compiled run() {
        for (const std::uint32_t s : {Tape::slot_x, Tape::slot_y, Tape::slot_z}) {
            slots_[s] = allocate(1, centre_roundings);
            p_.variable_offset_[s] = slots_[s].offset;
        }
        for (const auto& [slot, value] : tape_.constants()) {
            slots_[slot] = allocate(0, 0);
            p_.values_[slots_[slot].offset] = value;
            p_.magnitudes_[slots_[slot].offset] = std::abs(value);
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
        const auto offset = static_cast<std::uint32_t>(p_.values_.size());
        p_.values_.resize(p_.values_.size() + static_cast<std::size_t>(degree) + 1, 0.0);
        p_.magnitudes_.resize(p_.values_.size(), 0.0);
        return {offset, degree, roundings};
    }

    /// Emits a step — or, when every operand is a constant, runs it now.
    SlotState emit(Kind kind, const SlotState& a, const SlotState& b, int degree, int roundings) {
        const SlotState out = allocate(degree, roundings);
        const RayPolynomialProgram::Step step{kind, static_cast<std::uint8_t>(a.degree),
                                              static_cast<std::uint8_t>(b.degree), static_cast<std::uint8_t>(degree),
                                              a.offset, b.offset, out.offset};
        if (a.degree == 0 && b.degree == 0) {
            RayPolynomialProgram::run(step, p_.values_.data(), p_.magnitudes_.data());
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
        p_.values_[out.offset] = value;
        p_.magnitudes_[out.offset] = std::abs(value);
        return out;
    }

    std::optional<SlotState> refuse(RayPolynomialProgram::Refusal why) {
        refusal_ = why;
        return std::nullopt;
    }

    [[nodiscard]] double constant(const SlotState& s) const { return p_.values_[s.offset]; }

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
};

// Every case below gives the same bits as the plain loops it stands for
// (a sum of products started from 0, in increasing order of the first
// operand's index); they only leave out padding, zero fills and branches.
void RayPolynomialProgram::run(const Step& s, double* v, double* m) {
    const int da = s.a_degree;
    const int db = s.b_degree;
    double* vo = v + s.out;
    double* mo = m + s.out;
    const double* va = v + s.a;
    const double* ma = m + s.a;
    const double* vb = v + s.b;
    const double* mb = m + s.b;
    switch (s.kind) {
        case StepKind::Add:
        case StepKind::Sub: {
            const double sign = s.kind == StepKind::Add ? 1.0 : -1.0;
            const int common = std::min(da, db);
            for (int i = 0; i <= common; ++i) {
                vo[i] = va[i] + sign * vb[i];
                mo[i] = ma[i] + mb[i];
            }
            // The longer operand's tail, added to the other's zero padding.
            for (int i = common + 1; i <= da; ++i) {
                vo[i] = va[i] + sign * 0.0;
                mo[i] = ma[i] + 0.0;
            }
            for (int i = common + 1; i <= db; ++i) {
                vo[i] = 0.0 + sign * vb[i];
                mo[i] = 0.0 + mb[i];
            }
            break;
        }
        case StepKind::Neg:
            for (int i = 0; i <= da; ++i) {
                vo[i] = -va[i];
                mo[i] = ma[i];
            }
            break;
        case StepKind::Mul:
            if (da == 1 && db == 1) {  // the square or product of two coordinates: the commonest step, unrolled
                vo[0] = va[0] * vb[0];
                vo[1] = va[0] * vb[1] + va[1] * vb[0];
                vo[2] = va[1] * vb[1];
                mo[0] = ma[0] * mb[0];
                mo[1] = ma[0] * mb[1] + ma[1] * mb[0];
                mo[2] = ma[1] * mb[1];
                break;
            }
            if (db == 0) {  // times a constant
                for (int i = 0; i <= da; ++i) {
                    vo[i] = 0.0 + va[i] * vb[0];
                    mo[i] = 0.0 + ma[i] * mb[0];
                }
                break;
            }
            if (da == 0) {
                for (int j = 0; j <= db; ++j) {
                    vo[j] = 0.0 + va[0] * vb[j];
                    mo[j] = 0.0 + ma[0] * mb[j];
                }
                break;
            }
            for (int k = 0; k <= s.out_degree; ++k) {  // each coefficient of the product as one sum
                double value = 0.0;
                double magnitude = 0.0;
                for (int i = std::max(0, k - db); i <= std::min(k, da); ++i) {
                    value += va[i] * vb[k - i];
                    magnitude += ma[i] * mb[k - i];
                }
                vo[k] = value;
                mo[k] = magnitude;
            }
            break;
        case StepKind::Scale: {
            const double d = vb[0];
            const double magnitude = std::abs(d);
            for (int i = 0; i <= da; ++i) {
                vo[i] = va[i] / d;
                mo[i] = ma[i] / magnitude;
            }
            break;
        }
    }
}

RayPolynomialProgram::Compiled RayPolynomialProgram::compile(const Tape& tape) {
    return RayPolynomialCompiler(tape).run();
}

void RayPolynomialProgram::evaluate(const Ray& ray, double t_c) {
    const double origin[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const double direction[3] = {ray.dir.x, ray.dir.y, ray.dir.z};
    for (int k = 0; k < 3; ++k) {
        // centre = o + t_c·d, with its rounding error found exactly and added back.
        const double o = origin[k];
        const double d = direction[k];
        const double product = t_c * d;
        const double product_error = std::fma(t_c, d, -product);
        const double sum = o + product;
        const double virtual_product = sum - o;
        const double sum_error = (o - (sum - virtual_product)) + (product - virtual_product);
        const double residual = sum_error + product_error;
        const double centre = sum + residual;
        const std::uint32_t at = variable_offset_[k];
        values_[at] = centre;
        values_[at + 1] = d;
        magnitudes_[at] = std::abs(centre) + std::abs(residual);
        magnitudes_[at + 1] = std::abs(d);
    }
    for (const Step& s : steps_) run(s, values_.data(), magnitudes_.data());
}

double RayPolynomialProgram::radius(int i) const {
    return radius_scale_ * magnitudes_[result_offset_ + static_cast<std::size_t>(i)];
}

}  // namespace zeroset
