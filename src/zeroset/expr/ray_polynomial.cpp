// F(t) along a ray in Polynomial arithmetic, and f's structural degree.
#include "zeroset/expr/ray_polynomial.hpp"

#include <algorithm>
#include <vector>

#include "zeroset/expr/evaluator.hpp"

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

namespace {

constexpr int too_high = Polynomial::max_degree + 1;
constexpr int not_polynomial = -1;

/// A slot's degree, and its value when it is a constant (degree 0).
struct SlotDegree {
    int degree = 0;
    double value = 0.0;
};

int saturated(long long d) { return static_cast<int>(std::min<long long>(d, too_high)); }

/// The degree of an op's result from its operands' (both ≥ 0).
int result_degree(const Clause& c, const SlotDegree& a, const SlotDegree& b) {
    const int n = static_cast<int>(c.b);  // Powi's exponent
    switch (c.op) {
        case Op::Add: case Op::Sub: return std::max(a.degree, b.degree);
        case Op::Min: case Op::Max: return (a.degree == 0 && b.degree == 0) ? 0 : not_polynomial;
        case Op::Mul: return saturated(static_cast<long long>(a.degree) + b.degree);
        case Op::Div: return b.degree == 0 ? a.degree : not_polynomial;
        case Op::Neg: return a.degree;
        case Op::Square: return saturated(2LL * a.degree);
        case Op::Powi:
            if (a.degree == 0) return 0;
            return n < 0 ? not_polynomial : saturated(static_cast<long long>(a.degree) * n);
        case Op::Pow: {
            if (a.degree == 0 && b.degree == 0) return 0;
            const auto k = b.degree == 0 ? integer_value(b.value) : std::nullopt;
            if (!k || *k < 0) return not_polynomial;
            return saturated(static_cast<long long>(a.degree) * *k);
        }
        default: return a.degree == 0 ? 0 : not_polynomial;  // sqrt, abs, exp, log, sin, cos
    }
}

}  // namespace

int polynomial_degree(const Tape& tape) {
    std::vector<SlotDegree> slots(tape.slot_count());
    for (std::uint32_t s : {Tape::slot_x, Tape::slot_y, Tape::slot_z}) slots[s].degree = 1;
    for (const auto& [slot, value] : tape.constants()) slots[slot] = {0, value};
    for (const Clause& c : tape.clauses()) {
        const SlotDegree& a = slots[c.a];
        const SlotDegree& b = c.op == Op::Powi ? a : slots[c.b];
        if (a.degree < 0 || b.degree < 0) return not_polynomial;
        const int d = result_degree(c, a, b);
        if (d < 0) return not_polynomial;
        const double v = d == 0 ? apply_op<double>(c.op, a.value, b.value, static_cast<int>(c.b)) : 0.0;
        slots[c.out] = {d, v};
    }
    return slots[tape.result_slot()].degree;
}

}  // namespace zeroset
