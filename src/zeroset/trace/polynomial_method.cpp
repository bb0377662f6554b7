// F(t) in Polynomial arithmetic, then the chosen solver.
#include "zeroset/trace/polynomial_method.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "zeroset/expr/ray_polynomial.hpp"
#include "zeroset/roots/closed_form.hpp"
#include "zeroset/roots/descartes.hpp"
#include "zeroset/roots/fast_polynomial.hpp"
#include "zeroset/roots/laguerre.hpp"
#include "zeroset/roots/sturm.hpp"

namespace zeroset {

PolynomialMethod::PolynomialMethod(const Tape& tape, const RootFinderSettings& settings)
    : settings_(settings), coefficients_(tape) {
    const int degree = polynomial_degree(tape);
    if (degree < 0 || degree > Polynomial::max_degree)
        throw std::invalid_argument("the polynomial method needs a surface that is a polynomial in x, y, z of degree at most " +
                                    std::to_string(Polynomial::max_degree));
}

int PolynomialMethod::solve(const Polynomial& f, double t0, double t1, std::span<double> out,
                            TraceCounters& counters) const {
    const std::span<const double> c = f.coefficients();
    PolynomialSolver solver = settings_.polynomial_solver;
    if (solver == PolynomialSolver::Closed && f.degree() > max_closed_form_degree) solver = PolynomialSolver::Sturm;
    PolynomialRoots r;
    switch (solver) {
        case PolynomialSolver::Closed: {
            std::array<double, max_closed_form_degree> roots{};
            r.count = closed_form_roots_in(c, t0, t1, roots);
            r.evaluations = 1;
            for (int i = 0; i < r.count && i < static_cast<int>(out.size()); ++i) out[static_cast<std::size_t>(i)] = roots[static_cast<std::size_t>(i)];
            r.count = std::min(r.count, static_cast<int>(out.size()));
            break;
        }
        case PolynomialSolver::Sturm: r = sturm_roots(c, t0, t1, out); break;
        case PolynomialSolver::Descartes: r = descartes_roots(c, t0, t1, out); break;
        case PolynomialSolver::Laguerre: r = laguerre_roots(c, t0, t1, out); break;
        case PolynomialSolver::Fast: r = fast_polynomial_roots(c, t0, t1, out); break;
    }
    counters.point_evaluations += static_cast<std::uint64_t>(r.evaluations);
    return r.count;
}

HitResult PolynomialMethod::first_hit(RayFunction& h, Span span, TraceCounters& counters) {
    ++counters.point_evaluations;  // one walk of the tape in Polynomial arithmetic
    const auto f = ray_polynomial(coefficients_, h.ray());
    if (!f) return {std::nullopt, HitStatus::Failed};
    const double start = (*f)(span.t0);
    if (std::isnan(start)) return {std::nullopt, HitStatus::Failed};
    if (start <= 0.0) return {span.t0, HitStatus::Ok};  // the ray starts in the solid
    std::array<double, 1> first{};
    if (solve(*f, span.t0, span.t1, first, counters) == 0) return {std::nullopt, HitStatus::NoHit};
    return {first[0], HitStatus::Ok};
}

HitStatus PolynomialMethod::all_hits(RayFunction& h, Span span, std::vector<double>& hits, TraceCounters& counters) {
    ++counters.point_evaluations;
    const auto f = ray_polynomial(coefficients_, h.ray());
    if (!f) return HitStatus::Failed;
    std::array<double, Polynomial::max_degree> roots{};
    const int count = solve(*f, span.t0, span.t1, roots, counters);
    hits.insert(hits.end(), roots.begin(), roots.begin() + count);
    return count > 0 ? HitStatus::Ok : HitStatus::NoHit;
}

}  // namespace zeroset
