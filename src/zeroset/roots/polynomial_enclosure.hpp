// The first hit of a polynomial that is only known to within a bound. The
// ray polynomial F(t) is formed in floating point (math/bounded_polynomial):
// what a solver gets is F̂ with |F(t) − F̂(t)| ≤ R(t) = Σ r_i |t|^i. Where a
// grazing ray dips below the surface by less than R, F has two roots and F̂
// none, so every solver that trusts F̂ misses the hit. Guarded, a solver
// reports the first t where F *may* vanish: the first root of F̂, or an
// earlier extremum of F̂ that comes within R of 0 — a graze closer than the
// arithmetic can resolve counts as a hit (the same conservative choice the
// interval method makes) rather than a miss.
//
// The scan runs over the pieces between F̂'s extrema, on which F̂ is
// monotone: a piece whose ends have the same sign and both lie farther from 0
// than R on the piece (R grows with |t|, so its largest value on the piece is
// at an end) cannot hold a root of F; the first piece that can gives the hit
// — F̂'s root when F̂ changes sign across it, else the end nearer to 0.
#pragma once

#include <span>

namespace zeroset {

struct PolynomialEnclosure {
    /// F̂, ascending powers.
    std::span<const double> value;
    /// r_i ≥ 0, ascending powers, with |F(t) − F̂(t)| ≤ Σ r_i |t|^i for the
    /// exact coefficients; the rounding of evaluating F̂ is added here.
    std::span<const double> radius;
};

struct PossibleRoot {
    bool found = false;
    double t = 0.0;
    /// F̂ changes sign at t (a root of F lies within R of it); false for a
    /// graze the arithmetic cannot resolve.
    bool sign_change = false;
    int evaluations = 0;
};

/// R(t) plus the rounding of evaluating F̂ at t by Horner's rule (Higham
/// §5.1: γ₂ₙ·Σ|ĉ_i||t|^i), rounded up: |F(t) − horner(F̂, t)| ≤ this.
double enclosure_bound(const PolynomialEnclosure& f, double t);

/// A radius ρ beyond which F has no root up to `within`, whatever F is
/// within R of F̂ (ρ ≤ |t| ≤ within ⇒ F(t) ≠ 0), by Fujiwara's bound: where
/// |t| exceeds 2·((|f̂_{n−k}| + r_{n−k}) / (|f̂_n| − r_n))^{1/k} for every k,
/// the leading term outweighs all the others with their radii. When the
/// leading coefficient may be 0 the next one leads, less what the terms
/// above it can reach up to `within`. ρ is `largest` halved while it stays
/// such a bound: at most twice the least one. +∞ when no coefficient can
/// lead, or the bound exceeds `largest` (≤ within), or F̂ is a constant.
double root_radius(const PolynomialEnclosure& f, double within, double largest);

/// True when F > 0 throughout [t0, t1], shown by F̂'s Bernstein coefficients
/// on it (bernstein.hpp) all exceeding the conversion's rounding plus R at
/// the end farther from 0 (R grows with |t|). A cheap test before the
/// extrema are found: most spans a ray's bounds hand over hold no root.
/// False proves nothing.
bool provably_positive(const PolynomialEnclosure& f, double t0, double t1);

/// The first t in [t0, t1] where F may vanish, given the extrema of F̂ in
/// [t0, t1] (the roots of F̂′, increasing). When `t1_is_root`, t1 is a root
/// of F̂ already found (by any solver) and the scan only checks the pieces
/// before the last extremum ahead of it, answering t1 when they hold none.
PossibleRoot first_possible_root(const PolynomialEnclosure& f, double t0, double t1, std::span<const double> extrema,
                                 bool t1_is_root);

/// Every t in (t0, t1] where F may vanish, increasing, by the same scan over
/// the whole span: F̂'s roots, and one point for each piece that comes
/// within R of 0 without a sign change (a graze, or a double root of F).
/// Writes at most out.size() of them; returns how many, and counts the
/// evaluations of F̂ in `evaluations`.
int possible_roots(const PolynomialEnclosure& f, double t0, double t1, std::span<const double> extrema,
                   std::span<double> out, int& evaluations);

}  // namespace zeroset
