#include "zeroset/roots/sturm.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "zeroset/roots/refine.hpp"

namespace zeroset {

namespace {

/// The Sturm sequence of one polynomial, each member after p itself scaled
/// to a largest coefficient of 1 (only signs matter, and this keeps them in
/// range; p is kept exact, so its zeros are). Beside each member's
/// coefficients runs their magnitude: the same divisions on absolute values
/// (Higham's running error bound), so that a remainder coefficient is taken
/// for 0 only where it is also small beside what cancelled to make it — not
/// where it is merely small beside the dividend (t² − 10⁻¹³'s remainder
/// −10⁻¹³ is exact, and its root 3.2·10⁻⁷ real).
class SturmSequence {
public:
    /// For c of degree n, counted on t with |t| ≤ reach.
    SturmSequence(std::span<const double> c, int n, double reach) : reach_(std::max(reach, 1.0)) {
        auto& p0 = members_[0];
        std::copy_n(c.begin(), n + 1, p0.begin());
        degrees_[0] = n;
        auto& p1 = members_[1];
        for (int i = 0; i < n; ++i) p1[at(i)] = static_cast<double>(i + 1) * p0[at(i + 1)];
        degrees_[1] = n - 1;
        for (int k = 0; k < 2; ++k)
            for (int i = 0; i <= degrees_[at(k)]; ++i) magnitudes_[at(k)][at(i)] = std::abs(members_[at(k)][at(i)]);
        drop_negligible_leading_terms(1);
        normalize(1);
        size_ = 2;
        while (degrees_[at(size_ - 1)] > 0 && append_remainder()) {
        }
    }

    /// Sign changes along the sequence at t (zeros skipped).
    int sign_changes(double t, int& evaluations) const {
        evaluations += size_;
        int changes = 0;
        double previous = 0.0;
        for (int k = 0; k < size_; ++k) {
            const double v = horner(member(k), t).value;
            if (v == 0.0) continue;
            if (previous != 0.0 && (v < 0.0) != (previous < 0.0)) ++changes;
            previous = v;
        }
        return changes;
    }

private:
    static std::size_t at(int i) { return static_cast<std::size_t>(i); }
    [[nodiscard]] std::span<const double> member(int k) const {
        return {members_[at(k)].data(), static_cast<std::size_t>(degrees_[at(k)] + 1)};
    }
    [[nodiscard]] double largest(int k) const {
        double m = 0.0;
        for (int i = 0; i <= degrees_[at(k)]; ++i) m = std::max(m, std::abs(members_[at(k)][at(i)]));
        return m;
    }
    /// Drops member k's leading terms that are negligible where it is
    /// counted (|c_i|·reachⁱ below sturm_leading_tolerance of its largest
    /// term): rounding residue — a term that is 0 in exact arithmetic, left
    /// by cancellation — that the next division would divide by, giving
    /// quotients so large that the remainder is noise. The sequence stays a
    /// Sturm sequence of p where each member keeps its sign at the zeros of
    /// the one before (of p, for p′): a change far below its largest term
    /// over the range moves those signs only where the member is itself at
    /// rounding level. p itself is kept whole. Ranges within [−1, 1] are
    /// weighted as [−1, 1]: weighting them by their own small reach dropped
    /// terms that decide a root near 0.
    void drop_negligible_leading_terms(int k) {
        auto& m = members_[at(k)];
        int& degree = degrees_[at(k)];
        double largest_term = 0.0, power = 1.0;
        std::array<double, max_polynomial_degree + 1> terms{};
        for (int i = 0; i <= degree; ++i, power *= reach_) {
            terms[at(i)] = std::abs(m[at(i)]) * power;
            largest_term = std::max(largest_term, terms[at(i)]);
        }
        // reachⁱ overflowed, or every term underflowed: nothing to compare.
        if (!std::isfinite(largest_term) || !(largest_term > 0.0)) return;
        while (degree > 0 && terms[at(degree)] <= sturm_leading_tolerance * largest_term) m[at(degree--)] = 0.0;
    }
    void normalize(int k) {
        const double m = largest(k);
        for (int i = 0; i <= degrees_[at(k)]; ++i) {
            members_[at(k)][at(i)] /= m;
            magnitudes_[at(k)][at(i)] /= m;
        }
    }
    /// Appends −(p_{k−1} mod p_k); false when that remainder is (numerically) 0.
    bool append_remainder() {
        const int k = size_ - 1;
        const auto& b = members_[at(k)];
        const auto& b_magnitude = magnitudes_[at(k)];
        const int db = degrees_[at(k)];
        PolynomialScratch r = members_[at(k - 1)];
        PolynomialScratch r_magnitude = magnitudes_[at(k - 1)];
        double largest_quotient = 0.0;
        for (int i = degrees_[at(k - 1)]; i >= db; --i) {
            const double q = r[at(i)] / b[at(db)];
            largest_quotient = std::max(largest_quotient, std::abs(q));
            for (int j = 0; j <= db; ++j) {
                r[at(i - db + j)] -= q * b[at(j)];
                r_magnitude[at(i - db + j)] += std::abs(q) * b_magnitude[at(j)];
            }
        }
        // A coefficient is 0 where it is within the tolerance both of the
        // division's scale (the divisor's largest coefficient is 1) and of
        // its own magnitude — what cancelled to make it. The scale alone took
        // exact small remainders for 0; the magnitude alone, which grows
        // faster than the members from one division to the next, took real
        // ones for 0 a few members on and ended the sequence early (a quintic
        // lost its only real root).
        const double scale = largest(k - 1) + largest_quotient;
        const auto is_zero = [&](int i) {
            return std::abs(r[at(i)]) <= sturm_zero_tolerance * std::min(scale, r_magnitude[at(i)]);
        };
        int dr = db - 1;
        while (dr >= 0 && is_zero(dr)) --dr;
        if (dr < 0) return false;
        auto& next = members_[at(size_)];
        auto& next_magnitude = magnitudes_[at(size_)];
        for (int i = 0; i <= dr; ++i) {
            next[at(i)] = -r[at(i)];
            next_magnitude[at(i)] = r_magnitude[at(i)];
        }
        degrees_[at(size_)] = dr;
        drop_negligible_leading_terms(size_);
        normalize(size_);
        ++size_;
        return true;
    }

    std::array<PolynomialScratch, max_polynomial_degree + 1> members_{};
    std::array<PolynomialScratch, max_polynomial_degree + 1> magnitudes_{};  // each ≥ |its member|
    std::array<int, max_polynomial_degree + 1> degrees_{};
    int size_ = 0;
    double reach_;
};

/// An interval (a, b] and the sign changes at its ends.
struct CountedInterval {
    double a, b;
    int va, vb;
};

/// The single distinct root in (a, b] of s.
double isolated_root(std::span<const double> p, const SturmSequence& s, CountedInterval i, int& evaluations) {
    PolynomialFunction f(p);
    const double pa = f(i.a).value;
    const double pb = f(i.b).value;
    double root = i.b;
    if (pa != 0.0 && pb != 0.0 && (pa < 0.0) != (pb < 0.0)) {
        root = refine_root(f, i.a, i.b).t;
    } else if (pb != 0.0) {
        // No sign change: a root of even multiplicity. Narrow by counts.
        for (double m = 0.5 * i.a + 0.5 * i.b; i.a < m && m < i.b; m = 0.5 * i.a + 0.5 * i.b) {
            const int vm = s.sign_changes(m, evaluations);
            if (i.va - vm >= 1) {
                i.b = m;
            } else {
                i.a = m;
                i.va = vm;
            }
        }
        root = i.b;
    }
    evaluations += f.evaluations();
    return root;
}

/// When |p(t)| is within its rounding error bound, how far from t towards
/// `toward` that stays so to first order (at most 1e-9 relative, as p′ may
/// vanish there); 0 when p(t) is clearly not 0.
double end_neighbourhood(std::span<const double> p, double t, double toward, int& evaluations) {
    ++evaluations;
    const ValueAndDerivative v = horner(p, t);
    const double bound = horner_error_bound(p, t);
    if (std::abs(v.value) > bound) return 0.0;
    const double cap = std::min(1e-9 * std::max(1.0, std::abs(t)), 0.5 * std::abs(toward - t));
    const double slope = std::abs(v.derivative);
    return slope * cap > 8.0 * bound ? std::max(8.0 * bound / slope, std::abs(std::nextafter(t, toward) - t)) : cap;
}

}  // namespace

PolynomialRoots sturm_roots(std::span<const double> c, double t0, double t1, std::span<double> out) {
    const int n = checked_degree(c, t0, t1);
    PolynomialRoots result;
    if (n < 1 || out.empty()) return result;
    const std::span<const double> p = c.first(static_cast<std::size_t>(n + 1));
    const SturmSequence s(p, n, std::max(std::abs(t0), std::abs(t1)));
    // An end where p is within its rounding error of 0 is a root: the
    // polynomial's own root may lie a rounding error outside the range.
    // Counting starts past the neighbourhood where that holds; otherwise at
    // a0 just below t0, since (a0, t1] holds the roots of [t0, t1].
    const double near = end_neighbourhood(p, t0, t1, result.evaluations);
    double a0 = std::nextafter(t0, -std::numeric_limits<double>::infinity());
    if (near > 0.0) {
        out[0] = t0;
        result.count = 1;
        a0 = std::min(t0 + near, t1);
    }
    const double far = t1 > t0 ? end_neighbourhood(p, t1, t0, result.evaluations) : 0.0;
    // Intervals still to look at, the leftmost on top: each bisection
    // replaces one by two, so the depth bounds the size.
    std::array<CountedInterval, 128> stack{};
    std::size_t top = 0;
    stack[top++] = {a0, t1, s.sign_changes(a0, result.evaluations), s.sign_changes(t1, result.evaluations)};
    const auto emit = [&](double t) { out[static_cast<std::size_t>(result.count++)] = std::clamp(t, t0, t1); };
    while (top > 0 && static_cast<std::size_t>(result.count) < out.size()) {
        const CountedInterval i = stack[--top];
        const int roots = i.va - i.vb;
        if (roots <= 0) continue;
        if (roots == 1) {
            emit(isolated_root(p, s, i, result.evaluations));
            continue;
        }
        const double m = 0.5 * i.a + 0.5 * i.b;
        if (!(i.a < m && m < i.b) || top + 2 > stack.size()) {
            emit(m);  // a cluster bisection cannot split
            continue;
        }
        const int vm = s.sign_changes(m, result.evaluations);
        stack[top++] = {m, i.b, vm, i.vb};
        stack[top++] = {i.a, m, i.va, vm};
    }
    // A root within the neighbourhood of t1 already reported stands for t1.
    const bool reported_near_t1 = result.count > 0 && out[static_cast<std::size_t>(result.count - 1)] >= t1 - far;
    if (far > 0.0 && !reported_near_t1 && static_cast<std::size_t>(result.count) < out.size()) emit(t1);
    return result;
}

}  // namespace zeroset
