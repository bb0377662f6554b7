// The guarded first hit of polynomial_enclosure.hpp found by Bernstein
// subdivision instead of by F̂'s extrema: Descartes' rule of signs (survey
// §3.4, after Hanrahan 1983) applied to F itself, the exact polynomial, whose
// Bernstein coefficients on a piece lie within δ of the ones computed for F̂
// — δ being the conversion's and the splits' rounding plus R at the piece's
// end farther from 0 (the Bernstein coefficients of Σ rᵢtⁱ on a piece are
// blossoms of tⁱ at its ends, at most Σ rᵢ|t|ⁱ there). So, front to back
// over pieces of [t0, t1]:
//
//   - every coefficient above δ: F > 0 on the piece, no root;
//   - signs + … + (at most one within δ) − … −: F and F̂ have exactly one
//     root on the piece; F̂'s, refined by bracketed Newton from where the
//     control polygon crosses 0, is the hit (the end coefficients are F̂ at
//     the ends: beyond δ, their signs bracket it without an evaluation);
//   - anything else is split at its middle (de Casteljau), and after six
//     splits a piece still undecided — a dip towards 0, a cluster, a graze
//     — goes to the scan over F̂'s extrema on that piece alone.
//
// Most rays are settled by the first conversion (a miss) or within a few
// splits (one simple crossing ahead); the extrema, the costly part of the
// scan, are found only on the small pieces that need them.
#pragma once

#include "zeroset/roots/polynomial_enclosure.hpp"

namespace zeroset {

/// The first t in [t0, t1] where F may vanish: the answer of
/// first_possible_root with F̂'s extrema, or a later one where the bound
/// here is tighter — R taken over a small piece rather than a whole
/// monotone one, and a dip within R before a crossing that the signs prove
/// simple is no hit (F has that one root there). A span where F̂ starts
/// below 0 is scanned whole, as first_possible_root does. Counts
/// conversions, splits and samples as evaluations. A crossing's Newton
/// stops once a step is within `tolerance` (and shrinking), after one more
/// step: with 0, when the steps reach F̂'s rounding noise.
PossibleRoot first_possible_root_subdividing(const PolynomialEnclosure& f, double t0, double t1, double tolerance = 0.0);

}  // namespace zeroset
