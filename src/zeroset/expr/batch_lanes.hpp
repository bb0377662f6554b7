// The lane loops of BatchEvaluator, compiled with Highway for every x86-64
// SIMD level (SSE4, AVX2, AVX-512, …) and dispatched at run time to the
// best one the CPU has, so one binary runs everywhere at full width.
//
// exp, log, sin, cos and atan use Highway's vector versions (hwy/contrib/
// math), accurate to 1 ulp (exp), 4 (log), 3 (sin, cos, atan) — against at
// most 2 for glibc's scalar functions — within their stated ranges; a lane
// outside the range (or NaN, ±∞) is recomputed with the scalar function, so
// overflow, domain errors and NaN behave as in Evaluator<F>. The other ops
// are IEEE-exact (+ − × ÷ √, min, max, abs, floor, powi by the same
// squarings as scalar) or run per lane with the scalar function (tan,
// atan2, hypot, pow).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "zeroset/expr/tape.hpp"

namespace zeroset {

/// Lanes of every slot, slot-major: slot s holds lanes [s·lanes, (s+1)·lanes).
inline constexpr std::size_t batch_lanes = 256;

/// The slots that hold a tape's constants: read as one broadcast value
/// each, their lanes are never filled (19 of a prospero leaf's 45-clause
/// tapes' operands are constants, and filling their lanes cost more than
/// broadcasting them). Indexed by slot, valid for every slot a clause reads.
template <class F>
struct BatchConstants {
    const std::uint8_t* is_constant;
    const F* value;  // where is_constant
};

/// Runs the clauses over every lane of `slots`, reading constant slots from
/// `constants`.
void run_batch_lanes(const Clause* clauses, std::size_t count, float* slots, BatchConstants<float> constants);
void run_batch_lanes(const Clause* clauses, std::size_t count, double* slots, BatchConstants<double> constants);

/// The SIMD level the lane loops run at on this CPU (e.g. "AVX3" for AVX-512).
std::string batch_simd_target();

}  // namespace zeroset
