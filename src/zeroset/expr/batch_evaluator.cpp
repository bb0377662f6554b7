// The lane loops of BatchEvaluator, one per op, generated from the op table.
#include "zeroset/expr/batch_evaluator.hpp"

#include <algorithm>

#include "zeroset/math/scalar.hpp"

namespace zeroset {

template <class F>
BatchEvaluator<F>::BatchEvaluator(const Tape& tape)
    : tape_(&tape), slots_(static_cast<std::size_t>(tape.slot_count()) * lanes) {
    load_constants();
}

template <class F>
void BatchEvaluator<F>::rebind(const Tape& tape) {
    tape_ = &tape;
    load_constants();
}

template <class F>
void BatchEvaluator<F>::load_constants() {
    for (const auto& [s, value] : tape_->constants()) std::fill_n(slot(s), lanes, static_cast<F>(value));
}

template <class F>
void BatchEvaluator<F>::evaluate(std::span<const F> x, std::span<const F> y, std::span<const F> z,
                                 std::span<F> out) {
    for (std::size_t start = 0; start < out.size(); start += lanes) {
        const std::size_t count = std::min(lanes, out.size() - start);
        std::copy_n(x.data() + start, count, slot(Tape::slot_x));
        std::copy_n(y.data() + start, count, slot(Tape::slot_y));
        std::copy_n(z.data() + start, count, slot(Tape::slot_z));
        evaluate_lanes();
        std::copy_n(slot(tape_->result_slot()), count, out.data() + start);
    }
}

// Every lane is computed even in a partial batch: the loop count stays a
// compile-time constant (clean SIMD), and stale lanes are simply not copied out.
// A clause's output slot never aliases its operands (see Tape), hence __restrict.
template <class F>
void BatchEvaluator<F>::evaluate_lanes() {
    for (const Clause& c : tape_->clauses()) {
        F* __restrict out = slot(c.out);
        const F* __restrict pa = slot(c.a);
        const F* __restrict pb = c.op == Op::Powi ? pa : slot(c.b);
        const int n = static_cast<int>(c.b);
        (void)n;
        switch (c.op) {
#define ZEROSET_LANE_LOOP(name, vm, arity, expr)       \
    case Op::name:                                     \
        for (std::size_t i = 0; i < lanes; ++i) {    \
            const F a = pa[i];                         \
            [[maybe_unused]] const F b = pb[i];        \
            out[i] = expr;                             \
        }                                              \
        break;
            ZEROSET_OPS(ZEROSET_LANE_LOOP)
#undef ZEROSET_LANE_LOOP
        }
    }
}

template class BatchEvaluator<float>;
template class BatchEvaluator<double>;

}  // namespace zeroset
