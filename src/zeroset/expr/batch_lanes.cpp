// Highway's foreach_target compiles this file once per SIMD target; HWY_ONCE
// marks the part compiled once, which picks the target at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "zeroset/expr/batch_lanes.cpp"
#include <hwy/foreach_target.h>  // before highway.h, which it includes once per target
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "zeroset/expr/batch_lanes.hpp"
#include "zeroset/math/scalar.hpp"

HWY_BEFORE_NAMESPACE();
namespace zeroset {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

/// The ranges in which Highway's vector functions keep their stated accuracy.
template <class F>
struct VectorMathRange {
    static constexpr F exp_max = sizeof(F) == 4 ? F(104) : F(706);
    static constexpr F trig_max = F(39000);
};

template <class F>
class LaneLoops {
public:
    using D = hn::ScalableTag<F>;
    using V = hn::Vec<D>;

    static void run(const Clause* clauses, std::size_t count, F* slots, BatchConstants<F> constants) {
        // Lanes for a constant operand of an op that reads its operands lane
        // by lane (the vector functions' out-of-range lanes, per-lane ops).
        HWY_ALIGN F spill[2][batch_lanes];
        const auto operand = [&](std::uint32_t s, F* spill_to) {
            return constants.is_constant[s] ? Operand{nullptr, constants.value[s], spill_to}
                                            : Operand{slots + s * batch_lanes, F(0), nullptr};
        };
        for (std::size_t k = 0; k < count; ++k) {
            const Clause& c = clauses[k];
            const Operand a = operand(c.a, spill[0]);
            const Operand b = op_arity(c.op) == 2 ? operand(c.b, spill[1]) : a;
            clause(c, slots + c.out * batch_lanes, a, b);
        }
    }

private:
    /// A clause's operand: a slot's lanes, or a constant (lanes null).
    struct Operand {
        const F* lanes;
        F value;
        F* spill;  // where a constant is spread out when lanes are needed

        /// The operand's lanes, a constant's spread out over `spill`.
        const F* spread() const {
            if (lanes) return lanes;
            std::fill_n(spill, batch_lanes, value);
            return spill;
        }
    };
    struct Lanes {
        const F* at;
        V operator()(D d, std::size_t i) const { return hn::LoadU(d, at + i); }
    };
    struct Broadcast {
        F value;
        V operator()(D d, std::size_t) const { return hn::Set(d, value); }
    };

    template <class A, class Fn>
    static void unary_loop(F* HWY_RESTRICT out, A a, Fn fn) {
        const D d;
        for (std::size_t i = 0; i < batch_lanes; i += hn::Lanes(d)) hn::StoreU(fn(d, a(d, i)), d, out + i);
    }
    template <class A, class B, class Fn>
    static void binary_loop(F* HWY_RESTRICT out, A a, B b, Fn fn) {
        const D d;
        for (std::size_t i = 0; i < batch_lanes; i += hn::Lanes(d)) hn::StoreU(fn(d, a(d, i), b(d, i)), d, out + i);
    }
    template <class Fn>
    static void unary(F* HWY_RESTRICT out, const Operand& a, Fn fn) {
        if (a.lanes) unary_loop(out, Lanes{a.lanes}, fn);
        else unary_loop(out, Broadcast{a.value}, fn);
    }
    template <class Fn>
    static void binary(F* HWY_RESTRICT out, const Operand& a, const Operand& b, Fn fn) {
        if (a.lanes && b.lanes) binary_loop(out, Lanes{a.lanes}, Lanes{b.lanes}, fn);
        else if (a.lanes) binary_loop(out, Lanes{a.lanes}, Broadcast{b.value}, fn);
        else if (b.lanes) binary_loop(out, Broadcast{a.value}, Lanes{b.lanes}, fn);
        else binary_loop(out, Broadcast{a.value}, Broadcast{b.value}, fn);
    }
    /// A vector function accurate in [lo, hi]; lanes outside (or NaN) take `scalar`.
    template <class Fn, class Scalar>
    static void ranged(F* HWY_RESTRICT out, const F* HWY_RESTRICT a, F lo, F hi, Fn fn, Scalar scalar) {
        const D d;
        const V vlo = hn::Set(d, lo), vhi = hn::Set(d, hi);
        for (std::size_t i = 0; i < batch_lanes; i += hn::Lanes(d)) {
            const V x = hn::LoadU(d, a + i);
            hn::StoreU(fn(d, x), d, out + i);
            const auto in_range = hn::And(hn::Ge(x, vlo), hn::Le(x, vhi));  // false for NaN
            if (hn::AllTrue(d, in_range)) continue;
            for (std::size_t j = i; j < i + hn::Lanes(d); ++j)
                if (!(lo <= a[j] && a[j] <= hi)) out[j] = scalar(a[j]);
        }
    }
    /// Per lane with the op table's scalar meaning.
    static void per_lane(const Clause& c, F* HWY_RESTRICT out, const F* HWY_RESTRICT a, const F* HWY_RESTRICT b) {
        for (std::size_t i = 0; i < batch_lanes; ++i) out[i] = apply_op<F>(c.op, a[i], b[i], static_cast<int>(c.b));
    }
    /// max(a, b) + ln(1 + e^−|a−b|) as scalar log_sum_exp; Exp's argument is
    /// ≤ 0 and Log1p's in [0, 1], inside both ranges. Lanes where a − b is
    /// not finite (an operand NaN or infinite, or the difference overflows)
    /// take the scalar function.
    static void log_sum_exp(F* HWY_RESTRICT out, const F* HWY_RESTRICT a, const F* HWY_RESTRICT b) {
        const D d;
        for (std::size_t i = 0; i < batch_lanes; i += hn::Lanes(d)) {
            const V x = hn::LoadU(d, a + i), y = hn::LoadU(d, b + i);
            const V difference = hn::Sub(x, y);
            const V tail = hn::Log1p(d, hn::Exp(d, hn::Neg(hn::Abs(difference))));
            hn::StoreU(hn::Add(hn::Max(x, y), tail), d, out + i);
            if (hn::AllTrue(d, hn::IsFinite(difference))) continue;
            for (std::size_t j = i; j < i + hn::Lanes(d); ++j)
                if (!std::isfinite(a[j] - b[j])) out[j] = zeroset::log_sum_exp(a[j], b[j]);
        }
    }
    /// √(a² + b²) where a² + b² neither overflows nor loses bits to underflow
    /// (or a = b = 0); other lanes (and NaN, ±∞) take std::hypot.
    static void hypot(F* HWY_RESTRICT out, const F* HWY_RESTRICT a, const F* HWY_RESTRICT b) {
        const D d;
        const V tiny = hn::Set(d, sizeof(F) == 4 ? F(0x1p-100) : F(0x1p-900));
        const V huge = hn::Set(d, std::numeric_limits<F>::max());
        const V zero = hn::Zero(d);
        for (std::size_t i = 0; i < batch_lanes; i += hn::Lanes(d)) {
            const V x = hn::LoadU(d, a + i), y = hn::LoadU(d, b + i);
            const V sum = hn::MulAdd(x, x, hn::Mul(y, y));
            hn::StoreU(hn::Sqrt(sum), d, out + i);
            const auto both_zero = hn::And(hn::Eq(x, zero), hn::Eq(y, zero));
            const auto in_range = hn::Or(hn::And(hn::Ge(sum, tiny), hn::Le(sum, huge)), both_zero);
            if (hn::AllTrue(d, in_range)) continue;
            for (std::size_t j = i; j < i + hn::Lanes(d); ++j) out[j] = std::hypot(a[j], b[j]);
        }
    }
    /// a^n by repeated squaring, the same products as scalar powi.
    static V powi(D d, V a, int n) {
        const bool invert = n < 0;
        unsigned m = invert ? 0u - static_cast<unsigned>(n) : static_cast<unsigned>(n);
        V result = hn::Set(d, F(1)), base = a;
        while (m != 0) {
            if (m & 1u) result = hn::Mul(result, base);
            base = hn::Mul(base, base);
            m >>= 1;
        }
        return invert ? hn::Div(hn::Set(d, F(1)), result) : result;
    }

    static void clause(const Clause& c, F* HWY_RESTRICT out, const Operand& a, const Operand& b) {
        constexpr F max_finite = std::numeric_limits<F>::max();
        using R = VectorMathRange<F>;
        switch (c.op) {
            case Op::Const: case Op::VarX: case Op::VarY: case Op::VarZ: break;  // never clauses
            case Op::Add: binary(out, a, b, [](D, V x, V y) { return hn::Add(x, y); }); break;
            case Op::Sub: binary(out, a, b, [](D, V x, V y) { return hn::Sub(x, y); }); break;
            case Op::Mul: binary(out, a, b, [](D, V x, V y) { return hn::Mul(x, y); }); break;
            case Op::Div: binary(out, a, b, [](D, V x, V y) { return hn::Div(x, y); }); break;
            case Op::Neg: unary(out, a, [](D, V x) { return hn::Neg(x); }); break;
            case Op::Square: unary(out, a, [](D, V x) { return hn::Mul(x, x); }); break;
            case Op::Sqrt: unary(out, a, [](D, V x) { return hn::Sqrt(x); }); break;
            case Op::Abs: unary(out, a, [](D, V x) { return hn::Abs(x); }); break;
            case Op::Floor: unary(out, a, [](D, V x) { return hn::Floor(x); }); break;
            // NaN-propagating, as scalar min/max: a NaN b fails the comparison and is returned.
            case Op::Min:
                binary(out, a, b, [](D, V x, V y) { return hn::IfThenElse(hn::IsNaN(x), x, hn::IfThenElse(hn::Lt(x, y), x, y)); });
                break;
            case Op::Max:
                binary(out, a, b, [](D, V x, V y) { return hn::IfThenElse(hn::IsNaN(x), x, hn::IfThenElse(hn::Gt(x, y), x, y)); });
                break;
            case Op::Powi: {
                const int n = static_cast<int>(c.b);
                unary(out, a, [n](D d, V x) { return powi(d, x, n); });
                break;
            }
            case Op::Exp:
                ranged(out, a.spread(), -max_finite, R::exp_max, [](D d, V x) { return hn::Exp(d, x); }, [](F x) { return std::exp(x); });
                break;
            case Op::Log:
                ranged(out, a.spread(), std::numeric_limits<F>::min(), max_finite, [](D d, V x) { return hn::Log(d, x); },
                       [](F x) { return std::log(x); });
                break;
            case Op::Sin:
                ranged(out, a.spread(), -R::trig_max, R::trig_max, [](D d, V x) { return hn::Sin(d, x); }, [](F x) { return std::sin(x); });
                break;
            case Op::Cos:
                ranged(out, a.spread(), -R::trig_max, R::trig_max, [](D d, V x) { return hn::Cos(d, x); }, [](F x) { return std::cos(x); });
                break;
            case Op::Atan:
                ranged(out, a.spread(), -max_finite, max_finite, [](D d, V x) { return hn::Atan(d, x); }, [](F x) { return std::atan(x); });
                break;
            case Op::LogSumExp: log_sum_exp(out, a.spread(), b.spread()); break;
            case Op::Hypot: hypot(out, a.spread(), b.spread()); break;
            case Op::Tan: case Op::Atan2: case Op::Pow: per_lane(c, out, a.spread(), b.spread()); break;
        }
    }
};

void RunFloatLanes(const Clause* clauses, std::size_t count, float* slots, BatchConstants<float> constants) {
    LaneLoops<float>::run(clauses, count, slots, constants);
}
void RunDoubleLanes(const Clause* clauses, std::size_t count, double* slots, BatchConstants<double> constants) {
    LaneLoops<double>::run(clauses, count, slots, constants);
}

}  // namespace HWY_NAMESPACE
}  // namespace zeroset
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zeroset {

HWY_EXPORT(RunFloatLanes);
HWY_EXPORT(RunDoubleLanes);

void run_batch_lanes(const Clause* clauses, std::size_t count, float* slots, BatchConstants<float> constants) {
    HWY_DYNAMIC_DISPATCH(RunFloatLanes)(clauses, count, slots, constants);
}
void run_batch_lanes(const Clause* clauses, std::size_t count, double* slots, BatchConstants<double> constants) {
    HWY_DYNAMIC_DISPATCH(RunDoubleLanes)(clauses, count, slots, constants);
}

std::string batch_simd_target() {
    const std::int64_t available = hwy::SupportedTargets() & HWY_TARGETS;
    // Highway numbers better targets with lower bits.
    return available == 0 ? "none" : hwy::TargetName(available & -available);
}

}  // namespace zeroset
#endif
