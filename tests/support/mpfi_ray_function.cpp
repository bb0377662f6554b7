// Every op of the op table over MPFI, with its forward-mode derivative (see
// mpfi_ray_function.hpp for the rules on domains and regularity).
#include "support/mpfi_ray_function.hpp"

#include <stdexcept>
#include <unordered_map>

namespace zeroset::test {

namespace {

mpfr_ptr lo(mpfi_ptr x) { return &x->left; }
mpfr_ptr hi(mpfi_ptr x) { return &x->right; }
mpfr_srcptr lo(mpfi_srcptr x) { return &x->left; }
mpfr_srcptr hi(mpfi_srcptr x) { return &x->right; }

void set_entire(mpfi_ptr x) {
    mpfr_set_inf(lo(x), -1);
    mpfr_set_inf(hi(x), 1);
}

bool is_zero(mpfi_srcptr x) { return mpfr_zero_p(lo(x)) && mpfr_zero_p(hi(x)); }

/// x ∩ [0, +∞) into `out`; returns true when x reached 0 or below (the op is clipped).
bool clip_nonnegative(mpfi_ptr out, mpfi_srcptr x) {
    mpfi_set(out, x);
    if (mpfr_sgn(lo(x)) > 0) return false;
    mpfr_set_zero(lo(out), 1);
    return true;
}

}  // namespace

MpfiArray::MpfiArray(std::size_t count, mpfr_prec_t precision) : items_(count) {
    for (auto& item : items_) mpfi_init2(&item, precision);
}

MpfiArray::~MpfiArray() {
    for (auto& item : items_) mpfi_clear(&item);
}

std::vector<MpfiRayFunction::Node> MpfiRayFunction::compile(const Expr& f) {
    std::vector<Node> nodes;
    std::unordered_map<const void*, std::uint32_t> index;
    struct Frame {
        Expr e;
        bool expanded;
    };
    std::vector<Frame> stack{{f, false}};
    while (!stack.empty()) {
        const Frame frame = stack.back();
        stack.pop_back();
        const Expr& e = frame.e;
        if (index.contains(e.id())) continue;
        const int arity = op_arity(e.op());
        if (!frame.expanded) {
            stack.push_back({e, true});
            for (int i = arity - 1; i >= 0; --i) stack.push_back({e.operand(i), false});
            continue;
        }
        Node node{e.op(), 0, 0, 0, 0.0};
        if (arity >= 1) node.a = index.at(e.operand(0).id());
        if (arity == 2) node.b = index.at(e.operand(1).id());
        if (e.op() == Op::Powi) node.n = e.exponent();
        if (e.op() == Op::Const) node.constant = e.value();
        index.emplace(e.id(), static_cast<std::uint32_t>(nodes.size()));
        nodes.push_back(node);
    }
    return nodes;
}

MpfiRayFunction::MpfiRayFunction(const Expr& f, mpfr_prec_t precision)
    : nodes_(compile(f)),
      root_(static_cast<std::uint32_t>(nodes_.size() - 1)),
      value_(nodes_.size(), precision),
      slope_(nodes_.size(), precision),
      scratch_(5, precision),
      defined_(nodes_.size(), 0) {}

void MpfiRayFunction::set_ray(const Ray& ray) { ray_ = ray; }

Enclosure MpfiRayFunction::evaluate(mpfi_srcptr t, bool with_derivative) {
    ++evaluations_;
    clipped_ = false;
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        const bool ok = apply(i, t, with_derivative);
        defined_[i] = ok;
        if (!ok) continue;
        // NaN bounds come from ∞ − ∞, 0/0 and the like: the range is unknown.
        if (mpfi_nan_p(value_[i])) {
            set_entire(value_[i]);
            clipped_ = true;
        }
        if (with_derivative && mpfi_nan_p(slope_[i])) {
            set_entire(slope_[i]);
            clipped_ = true;
        }
    }
    const bool defined = defined_[root_] != 0;
    const bool regular =
        defined && !clipped_ && mpfi_bounded_p(value()) && (!with_derivative || mpfi_bounded_p(derivative()));
    return {defined, regular};
}

void MpfiRayFunction::power(mpfi_ptr value, mpfi_srcptr a, unsigned long n) {
    mpfi_srcptr base = a;
    if (n % 2 == 0) {  // even: a^n = |a|^n, increasing on [0, ∞)
        mpfi_abs(scratch_[4], a);
        base = scratch_[4];
    }
    mpfr_pow_ui(lo(value), lo(base), n, MPFR_RNDD);
    mpfr_pow_ui(hi(value), hi(base), n, MPFR_RNDU);
}

bool MpfiRayFunction::integer_power(mpfi_ptr value, mpfi_srcptr a, long n) {
    if (n == 0) {
        mpfi_set_si(value, 1);
        return true;
    }
    if (n > 0) {
        power(value, a, static_cast<unsigned long>(n));
        return true;
    }
    if (is_zero(a)) return false;  // 0 to a negative power: never a finite value
    if (mpfi_has_zero(a)) clipped_ = true;
    power(scratch_[3], a, static_cast<unsigned long>(-n));
    mpfi_ui_div(value, 1, scratch_[3]);
    return true;
}

bool MpfiRayFunction::apply(std::size_t i, mpfi_srcptr t, bool with_derivative) {
    const Node& node = nodes_[i];
    mpfi_ptr v = value_[i];
    mpfi_ptr s = slope_[i];
    const auto coordinate = [&](double origin, double dir) {
        mpfi_mul_d(v, t, dir);
        mpfi_add_d(v, v, origin);
        if (with_derivative) mpfi_set_d(s, dir);
        return true;
    };
    switch (node.op) {
        case Op::Const:
            mpfi_set_d(v, node.constant);
            if (with_derivative) mpfi_set_si(s, 0);
            return true;
        case Op::VarX: return coordinate(ray_.origin.x, ray_.dir.x);
        case Op::VarY: return coordinate(ray_.origin.y, ray_.dir.y);
        case Op::VarZ: return coordinate(ray_.origin.z, ray_.dir.z);
        default: break;
    }
    const bool binary = op_arity(node.op) == 2;
    if (!defined_[node.a] || (binary && !defined_[node.b])) return false;  // NaN propagates
    mpfi_srcptr a = value_[node.a];
    mpfi_srcptr da = slope_[node.a];
    mpfi_srcptr b = value_[binary ? node.b : node.a];
    mpfi_srcptr db = slope_[binary ? node.b : node.a];
    mpfi_ptr t0 = scratch_[0];
    mpfi_ptr t1 = scratch_[1];
    mpfi_ptr t2 = scratch_[2];

    switch (node.op) {
        case Op::Add:
            mpfi_add(v, a, b);
            if (with_derivative) mpfi_add(s, da, db);
            return true;
        case Op::Sub:
            mpfi_sub(v, a, b);
            if (with_derivative) mpfi_sub(s, da, db);
            return true;
        case Op::Mul:
            mpfi_mul(v, a, b);
            if (with_derivative) {
                mpfi_mul(t0, da, b);
                mpfi_mul(t1, a, db);
                mpfi_add(s, t0, t1);
            }
            return true;
        case Op::Div:
            if (is_zero(b)) return false;
            if (mpfi_has_zero(b)) clipped_ = true;
            mpfi_div(v, a, b);
            if (with_derivative) {  // (a/b)′ = (a′ − (a/b)·b′)/b
                mpfi_mul(t0, v, db);
                mpfi_sub(t0, da, t0);
                mpfi_div(s, t0, b);
            }
            return true;
        case Op::Neg:
            mpfi_neg(v, a);
            if (with_derivative) mpfi_neg(s, da);
            return true;
        case Op::Square:
            mpfi_sqr(v, a);
            if (with_derivative) {
                mpfi_mul(t0, a, da);
                mpfi_mul_2ui(s, t0, 1);
            }
            return true;
        case Op::Sqrt:
            if (mpfr_sgn(hi(a)) < 0) return false;
            if (clip_nonnegative(t0, a)) clipped_ = true;
            mpfi_sqrt(v, t0);
            if (with_derivative) {
                mpfi_mul_2ui(t1, v, 1);
                mpfi_div(s, da, t1);
            }
            return true;
        case Op::Abs:
            mpfi_abs(v, a);
            if (with_derivative) {
                if (mpfr_sgn(lo(a)) >= 0) {
                    mpfi_set(s, da);
                } else if (mpfr_sgn(hi(a)) <= 0) {
                    mpfi_neg(s, da);
                } else {  // the kink: either slope, so ±max|a′|
                    mpfi_abs(t0, da);
                    mpfr_neg(lo(s), hi(t0), MPFR_RNDD);
                    mpfr_set(hi(s), hi(t0), MPFR_RNDU);
                }
            }
            return true;
        case Op::Exp:
            mpfi_exp(v, a);
            if (with_derivative) mpfi_mul(s, v, da);
            return true;
        case Op::Log:
            if (mpfr_sgn(hi(a)) <= 0) return false;  // NaN or −∞ everywhere: never a root
            if (clip_nonnegative(t0, a)) clipped_ = true;
            mpfi_log(v, t0);
            if (with_derivative) mpfi_div(s, da, t0);
            return true;
        case Op::Sin:
            mpfi_sin(v, a);
            if (with_derivative) {
                mpfi_cos(t0, a);
                mpfi_mul(s, t0, da);
            }
            return true;
        case Op::Cos:
            mpfi_cos(v, a);
            if (with_derivative) {
                mpfi_sin(t0, a);
                mpfi_neg(t0, t0);
                mpfi_mul(s, t0, da);
            }
            return true;
        case Op::Tan:
            // MPFI answers ℝ over a pole; the jump makes the interval irregular.
            mpfi_tan(v, a);
            if (!mpfi_bounded_p(v)) clipped_ = true;
            if (with_derivative) {  // tan′ = 1 + tan²
                mpfi_sqr(t0, v);
                mpfi_add_ui(t0, t0, 1);
                mpfi_mul(s, t0, da);
            }
            return true;
        case Op::Atan:
            mpfi_atan(v, a);
            if (with_derivative) {  // atan′ = 1/(1 + a²)
                mpfi_sqr(t0, a);
                mpfi_add_ui(t0, t0, 1);
                mpfi_div(s, da, t0);
            }
            return true;
        case Op::Atan2: {
            // a is y, b is x. Over the cut (x ≤ 0, y ∋ 0) or the origin the
            // angle jumps between −π and π: [−π, π], irregular.
            const bool jumps = mpfi_has_zero(a) && mpfr_sgn(lo(b)) <= 0;
            if (jumps) {
                mpfi_const_pi(t0);
                mpfr_neg(lo(v), hi(t0), MPFR_RNDD);
                mpfr_set(hi(v), hi(t0), MPFR_RNDU);
                clipped_ = true;
            } else {
                mpfi_atan2(v, a, b);
            }
            if (with_derivative) {  // (x y′ − y x′)/(x² + y²)
                mpfi_mul(t0, b, da);
                mpfi_mul(t1, a, db);
                mpfi_sub(t0, t0, t1);
                mpfi_sqr(t1, a);
                mpfi_sqr(t2, b);
                mpfi_add(t1, t1, t2);
                mpfi_div(s, t0, t1);
                if (jumps) set_entire(s);
            }
            return true;
        }
        case Op::Floor: {
            mpfr_floor(lo(v), lo(a));
            mpfr_floor(hi(v), hi(a));
            const bool jumps = !mpfr_equal_p(lo(v), hi(v));
            if (jumps) clipped_ = true;
            if (with_derivative) {
                mpfi_set_si(s, 0);
                if (jumps) set_entire(s);
            }
            return true;
        }
        case Op::Hypot:
            mpfi_hypot(v, a, b);
            if (with_derivative) {  // (a a′ + b b′)/h, each slope a/h, b/h in [−1, 1]
                if (mpfr_sgn(lo(v)) > 0) {
                    mpfi_div(t0, a, v);
                    mpfi_mul(t0, t0, da);
                    mpfi_div(t1, b, v);
                    mpfi_mul(t1, t1, db);
                    mpfi_add(s, t0, t1);
                } else {  // the apex may be inside: every slope in [−1, 1]
                    mpfi_interv_si(t2, -1, 1);
                    mpfi_mul(t0, t2, da);
                    mpfi_mul(t1, t2, db);
                    mpfi_add(s, t0, t1);
                    clipped_ = true;
                }
            }
            return true;
        case Op::LogSumExp:  // ln(eᵃ + eᵇ); MPFR's exponent range does not overflow here
            mpfi_exp(t0, a);
            mpfi_exp(t1, b);
            mpfi_add(t2, t0, t1);
            mpfi_log(v, t2);
            if (with_derivative) {  // (eᵃ a′ + eᵇ b′)/(eᵃ + eᵇ)
                mpfi_mul(t0, t0, da);
                mpfi_mul(t1, t1, db);
                mpfi_add(t0, t0, t1);
                mpfi_div(s, t0, t2);
            }
            return true;
        case Op::Powi:
        case Op::Pow: {
            long n = node.n;
            bool integral = node.op == Op::Powi;
            if (!integral && mpfr_equal_p(lo(b), hi(b)) && mpfr_integer_p(lo(b)) &&
                mpfr_cmpabs_ui(lo(b), 1UL << 30) < 0) {
                // an integer exponent: pow(a, n) = powi(a, n), negative bases included (as std::pow)
                integral = true;
                n = mpfr_get_si(lo(b), MPFR_RNDN);
                if (with_derivative && !is_zero(db)) clipped_ = true;  // b varies: no slope formula for a < 0
            }
            if (integral) {
                if (!integer_power(v, a, n)) return false;
                if (with_derivative) {  // (a^n)′ = n·a^(n−1)·a′
                    if (n == 0) {
                        mpfi_set_si(s, 0);
                    } else if (integer_power(t0, a, n - 1)) {
                        mpfi_mul_si(t0, t0, n);
                        mpfi_mul(s, t0, da);
                    } else {
                        set_entire(s);
                        clipped_ = true;
                    }
                }
                return true;
            }
            // a^b = exp(b·log a) over the part of a where it is defined (a ≥ 0)
            if (mpfr_sgn(hi(a)) < 0) return false;
            if (clip_nonnegative(t0, a)) clipped_ = true;
            mpfi_log(t1, t0);
            mpfi_mul(t2, b, t1);
            mpfi_exp(v, t2);
            if (mpfi_nan_p(v)) {  // 0·∞ in the exponent: all that is known is a^b ≥ 0
                mpfr_set_zero(lo(v), 1);
                mpfr_set_inf(hi(v), 1);
            }
            if (with_derivative) {  // (a^b)′ = a^b·(b′·log a + b·a′/a)
                mpfi_mul(t2, db, t1);
                mpfi_div(t1, da, t0);
                mpfi_mul(t1, b, t1);
                mpfi_add(t2, t2, t1);
                mpfi_mul(s, v, t2);
            }
            return true;
        }
        case Op::Min:
        case Op::Max: {
            const bool is_min = node.op == Op::Min;
            const auto pick = is_min ? mpfr_min : mpfr_max;
            pick(lo(v), lo(a), lo(b), MPFR_RNDD);
            pick(hi(v), hi(a), hi(b), MPFR_RNDU);
            if (with_derivative) {
                // The side that wins all over the interval gives the slope; else either may.
                const bool a_wins = is_min ? mpfr_lessequal_p(hi(a), lo(b)) : mpfr_greaterequal_p(lo(a), hi(b));
                const bool b_wins = is_min ? mpfr_lessequal_p(hi(b), lo(a)) : mpfr_greaterequal_p(lo(b), hi(a));
                if (a_wins) {
                    mpfi_set(s, da);
                } else if (b_wins) {
                    mpfi_set(s, db);
                } else {
                    mpfi_union(s, da, db);
                }
            }
            return true;
        }
        default: break;
    }
    throw std::logic_error("MpfiRayFunction: unhandled op");
}

}  // namespace zeroset::test
