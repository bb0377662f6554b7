// The polynomial method (survey §§3.3–3.4): when f is a polynomial in x, y, z,
// F(t) = f(x_o + t·x_d) is a polynomial in t whose exact coefficients come
// from one walk of the tape in Polynomial arithmetic; a root solver then
// finds its real roots in the span — closed forms up to degree 4, Sturm
// sequences (van Wijk), Descartes' rule in the Bernstein basis (Hanrahan),
// Laguerre's method, or the recursive-derivative solver after Yuksel (HPG
// 2022). Sturm, Descartes and the fast solver isolate every real root;
// Laguerre and the closed forms can lose nearly-double roots.
#pragma once

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/math/polynomial.hpp"
#include "zeroset/trace/root_finder.hpp"

namespace zeroset {

class PolynomialMethod : public RootFinder {
public:
    /// Throws std::invalid_argument unless the tape is a polynomial of degree
    /// at most 32 (see polynomial_degree).
    PolynomialMethod(const Tape& tape, const RootFinderSettings& settings);

    HitResult first_hit(RayFunction& h, Span span, TraceCounters& counters) override;
    HitStatus all_hits(RayFunction& h, Span span, std::vector<double>& hits, TraceCounters& counters) override;

private:
    /// The real roots of F in [t0, t1], increasing, into `out`; their number.
    int solve(const Polynomial& f, double t0, double t1, std::span<double> out, TraceCounters& counters) const;

    RootFinderSettings settings_;
    Evaluator<Polynomial> coefficients_;
};

}  // namespace zeroset
