// BatchEvaluator: copying points in and values out around the lane loops.
#include "zeroset/expr/batch_evaluator.hpp"

#include <algorithm>
#include <cstring>

namespace zeroset {

template <class F>
BatchEvaluator<F>::BatchEvaluator(const Tape& tape)
    : tape_(&tape),
      slots_(static_cast<std::size_t>(tape.slot_count()) * lanes),
      constant_(tape.slot_count()),
      filled_(tape.slot_count(), 0) {
    load_constants();
}

template <class F>
void BatchEvaluator<F>::rebind(const Tape& tape) {
    tape_ = &tape;
    load_constants();
}

template <class F>
void BatchEvaluator<F>::load_constants() {
    for (const auto& [s, value] : tape_->constants()) {
        const F v = static_cast<F>(value);
        if (filled_[s] && std::memcmp(&constant_[s], &v, sizeof v) == 0) continue;  // bits, for −0 and NaN
        std::fill_n(slot(s), lanes, v);
        constant_[s] = v;
        filled_[s] = 1;
    }
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
    // The clauses wrote over their slots, which another tape may use for a constant.
    for (const Clause& c : tape_->clauses()) filled_[c.out] = 0;
}

// Every lane is computed even in a partial batch: the loop count stays a
// compile-time constant (clean SIMD), and stale lanes are simply not copied out.
template <class F>
void BatchEvaluator<F>::evaluate_lanes() {
    run_batch_lanes(tape_->clauses().data(), tape_->clauses().size(), slots_.data());
}

template class BatchEvaluator<float>;
template class BatchEvaluator<double>;

}  // namespace zeroset
