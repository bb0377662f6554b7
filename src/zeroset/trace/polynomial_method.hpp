// The polynomial method (survey §§3.3–3.4): when f is a polynomial in x, y, z,
// F(t) = f(x_o + t·x_d) is a polynomial in t, and a root solver finds its
// real roots in the span — closed forms up to degree 4, Sturm
// sequences (van Wijk), Descartes' rule in the Bernstein basis (Hanrahan),
// Laguerre's method, or the recursive-derivative solver after Yuksel (HPG
// 2022). Sturm, Descartes and the fast solver isolate every real root;
// Laguerre and the closed forms can lose nearly-double roots.
//
// F is formed by a compiled program (expr/ray_polynomial_program.hpp) about
// the span's point nearest f's origin (or the ray's focus), with a proven
// bound R on its rounding, so F is known as F̂ ± R; a long span is cut to
// F's root radius about that point. The first hit is guarded (roots/polynomial_enclosure.hpp): an extremum of F̂ before
// its first root that comes within R of 0 is a graze the arithmetic cannot
// resolve, and counts as a hit rather than a miss. all_hits is guarded the
// same way: F̂'s roots and every unresolvable graze, so spans built from it
// (Roth CSG, accel/) lose nothing the first hit would find.
#pragma once

#include <array>
#include <span>

#include "zeroset/expr/ray_polynomial_program.hpp"
#include "zeroset/roots/polynomial_enclosure.hpp"
#include "zeroset/trace/root_finder.hpp"

namespace zeroset {

class PolynomialMethod : public RootFinder {
public:
    /// Throws std::invalid_argument unless the tape is a polynomial of degree
    /// at most 32 (see polynomial_degree).
    PolynomialMethod(const Tape& tape, const RootFinderSettings& settings);

    HitResult first_hit(RayFunction& h, Span span, TraceCounters& counters) override;
    HitStatus all_hits(RayFunction& h, Span span, std::vector<double>& hits, TraceCounters& counters) override;

    /// The method's resolution on this ray: the largest proven bound on
    /// |F(t) − F̂(t)| over the span (+∞ when the bound is lost). Where the
    /// exact |F| is below it the arithmetic cannot tell F from 0, and the
    /// first hit may be reported without a root.
    double rounding_bound(const Ray& ray, Span span);

private:
    /// The real roots of F in [t0, t1], increasing, into `out`; their number.
    int solve(std::span<const double> f, double t0, double t1, std::span<double> out, TraceCounters& counters) const;

    /// F̂'s extrema in [s0, s1] (the fast solver finds them on its way; any
    /// other solves F̂′), increasing, into `out`; their number.
    int extrema_of(std::span<const double> value, double s0, double s1, std::span<double> out,
                   TraceCounters& counters) const;

    /// F̂ from the program's last run, with its coefficients' radii.
    inline PolynomialEnclosure current_enclosure();  // defined, and used, in polynomial_method.cpp only

    RootFinderSettings settings_;
    RayPolynomialProgram program_;
    std::array<double, RayPolynomialProgram::max_degree + 1> radius_{};
};

}  // namespace zeroset
