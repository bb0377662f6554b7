// BatchEvaluator<F>: f at many points per walk of the tape. Slots hold a
// fixed number of lanes in structure-of-arrays form, and each clause runs a
// SIMD loop over its lanes (expr/batch_lanes.hpp, at the CPU's best width)
// — so the interpretation cost (one op dispatch per clause) is paid once per
// `lanes` points instead of once per point.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "zeroset/expr/batch_lanes.hpp"
#include "zeroset/expr/tape.hpp"

namespace zeroset {

template <class F>
class BatchEvaluator {
public:
    static constexpr std::size_t lanes = batch_lanes;

    explicit BatchEvaluator(const Tape& tape);
    /// Bound to no tape yet: rebind() before evaluating. Its lanes are sized
    /// by the tapes it is bound to, so one that only ever sees short pruned
    /// tapes never holds the full tape's (1.4 MB for prospero in float).
    BatchEvaluator() = default;

    /// Switches to the original tape or one pruned from it, as Evaluator::rebind.
    void rebind(const Tape& tape);

    /// out[i] = f(x[i], y[i], z[i]) for every i; all spans of equal length.
    void evaluate(std::span<const F> x, std::span<const F> y, std::span<const F> z, std::span<F> out);

    /// For a caller that writes one batch's points in place: the `lanes`
    /// values of x, y and z to fill (lanes left unfilled are computed from
    /// stale values and mean nothing), then evaluate_in_place().
    struct Inputs {
        F* x;
        F* y;
        F* z;
    };
    Inputs inputs() { return {slot(Tape::slot_x), slot(Tape::slot_y), slot(Tape::slot_z)}; }
    /// f at the points in inputs(), lane by lane; valid until the next call.
    std::span<const F, lanes> evaluate_in_place();

private:
    void load_constants();
    [[nodiscard]] BatchConstants<F> constants() const { return {is_constant_.data(), constant_.data()}; }
    F* slot(std::uint32_t s) { return slots_.data() + static_cast<std::size_t>(s) * lanes; }

    const Tape* tape_ = nullptr;
    std::vector<F> slots_;  // slot-major: slot s occupies [s·lanes, (s+1)·lanes)
    // Per slot, for the bound tape: whether it holds a constant, and which.
    // The lane loops broadcast those; a constant slot's lanes are never filled.
    std::vector<std::uint8_t> is_constant_;
    std::vector<F> constant_;
};

extern template class BatchEvaluator<float>;
extern template class BatchEvaluator<double>;

}  // namespace zeroset
