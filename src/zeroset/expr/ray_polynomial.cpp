// F(t) along a ray in Polynomial arithmetic, and f's structural degree.
#include "zeroset/expr/ray_polynomial.hpp"

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/ray_polynomial_program.hpp"

namespace zeroset {

std::optional<Polynomial> ray_polynomial(const Tape& tape, const Ray& ray) {
    Evaluator<Polynomial> eval(tape);
    return ray_polynomial(eval, ray);
}

std::optional<Polynomial> ray_polynomial(Evaluator<Polynomial>& eval, const Ray& ray) {
    Polynomial f = eval(Polynomial::line(ray.origin.x, ray.dir.x), Polynomial::line(ray.origin.y, ray.dir.y),
                        Polynomial::line(ray.origin.z, ray.dir.z));
    if (!f.valid()) return std::nullopt;
    return f;
}

int polynomial_degree(const Tape& tape) {
    const RayPolynomialProgram::Compiled compiled = RayPolynomialProgram::compile(tape);
    if (compiled.program) return compiled.program->degree();
    return *compiled.refusal == RayPolynomialProgram::Refusal::DegreeTooHigh ? Polynomial::max_degree + 1 : -1;
}

}  // namespace zeroset
