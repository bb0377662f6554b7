// Highway compiles this file once per SIMD target (foreach_target); the
// HWY_ONCE part dispatches to the best one the CPU runs.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fma_ceiling.cpp"
#include <hwy/foreach_target.h>  // before highway.h, which it includes once per target
#include <hwy/highway.h>

#include "fma_ceiling.hpp"
#include "zeroset/expr/batch_lanes.hpp"

HWY_BEFORE_NAMESPACE();
namespace zeroset::bench {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

template <class F>
void Fma(F* slots, std::size_t clauses) {
    const hn::ScalableTag<F> d;
    const auto quarter = hn::Set(d, F(0.25));
    for (std::size_t c = 0; c < clauses; ++c) {
        F* HWY_RESTRICT out = slots + (c % 8) * batch_lanes;
        const F* HWY_RESTRICT a = slots + ((c + 1) % 8) * batch_lanes;
        const F* HWY_RESTRICT b = slots + ((c + 2) % 8) * batch_lanes;
        for (std::size_t i = 0; i < batch_lanes; i += hn::Lanes(d))
            hn::StoreU(hn::MulAdd(hn::LoadU(d, a + i), hn::LoadU(d, b + i), quarter), d, out + i);
    }
}
void FmaFloat(float* slots, std::size_t clauses) { Fma(slots, clauses); }
void FmaDouble(double* slots, std::size_t clauses) { Fma(slots, clauses); }

}  // namespace HWY_NAMESPACE
}  // namespace zeroset::bench
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zeroset::bench {
HWY_EXPORT(FmaFloat);
HWY_EXPORT(FmaDouble);
void straight_line_fma(float* slots, std::size_t clauses) { HWY_DYNAMIC_DISPATCH(FmaFloat)(slots, clauses); }
void straight_line_fma(double* slots, std::size_t clauses) { HWY_DYNAMIC_DISPATCH(FmaDouble)(slots, clauses); }
}  // namespace zeroset::bench
#endif
