// Evaluator<T>: walks a tape with one number type T — double, float,
// Interval, Dual<…>, Jet<…> — the single evaluator body of DESIGN.md's
// "one tape, many number types". Each instance owns its slots (constants
// loaded once), so keep one per thread and call it as often as needed:
// evaluation itself never allocates.
#pragma once

#include <vector>

#include "zeroset/expr/tape.hpp"
#include "zeroset/math/dual.hpp"
#include "zeroset/math/interval.hpp"
#include "zeroset/math/jet.hpp"
#include "zeroset/math/scalar.hpp"

namespace zeroset {

template <class T>
class Evaluator {
public:
    explicit Evaluator(const Tape& tape) : tape_(&tape), slots_(tape.slot_count()) { load_constants(); }

    /// f(x, y, z) in the number type T.
    T operator()(const T& x, const T& y, const T& z) {
        T* s = slots_.data();
        s[Tape::slot_x] = x;
        s[Tape::slot_y] = y;
        s[Tape::slot_z] = z;
        for (const Clause& c : tape_->clauses()) {
            // Powi's b is its exponent, not a slot: it may lie past the last slot.
            const T& b = s[c.op == Op::Powi ? c.a : c.b];
            s[c.out] = apply_op<T>(c.op, s[c.a], b, static_cast<int>(c.b));
        }
        return s[tape_->result_slot()];
    }

    [[nodiscard]] const Tape& tape() const { return *tape_; }

    /// Switches to another tape — the original one, or one pruned from it
    /// (expr/tape_pruner.hpp), which never needs more slots — and loads its
    /// constants.
    void rebind(const Tape& tape) {
        tape_ = &tape;
        load_constants();
    }

private:
    void load_constants() {
        for (const auto& [slot, value] : tape_->constants()) slots_[slot] = T(value);
    }

    const Tape* tape_;
    std::vector<T> slots_;
};

/// f and ∇f at a point (survey eq. 33).
inline Dual<double> evaluate_gradient(Evaluator<Dual<double>>& eval, const Vec3d& p) {
    return eval(Dual<double>::variable(p.x, 0), Dual<double>::variable(p.y, 1), Dual<double>::variable(p.z, 2));
}

/// f over a box, as an interval.
inline Interval evaluate_box(Evaluator<Interval>& eval, const Vec3d& lo, const Vec3d& hi) {
    return eval(Interval(lo.x, hi.x), Interval(lo.y, hi.y), Interval(lo.z, hi.z));
}

/// H, H′, H″ along the ray origin + t·dir at the parameter t (a number or an interval).
template <class T>
Jet<T> evaluate_along_ray(Evaluator<Jet<T>>& eval, const Vec3d& origin, const Vec3d& dir, const T& t) {
    return eval(Jet<T>::line(origin.x, dir.x, t), Jet<T>::line(origin.y, dir.y, t), Jet<T>::line(origin.z, dir.z, t));
}

}  // namespace zeroset
