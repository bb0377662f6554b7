// Rigorous first-root isolation along a ray (see mpfi_ray_oracle.hpp).
#include "support/mpfi_ray_oracle.hpp"

#include <limits>
#include <stdexcept>
#include <utility>

namespace zeroset::test {

namespace {

enum Work : std::size_t { piece, point, newton_step, slope, number, saved, measure, work_count };

mpfr_ptr lo(mpfi_ptr x) { return &x->left; }
mpfr_ptr hi(mpfi_ptr x) { return &x->right; }

/// A Newton step that keeps more than this fraction of the piece is stalling.
constexpr double stall_ratio = 0.75;

}  // namespace

MpfiRayOracle::MpfiRayOracle(const Expr& f, double scale, OracleSettings settings)
    : tangent_width_(settings.tangent_width * scale),
      refine_width_(settings.refine_width * scale),
      settings_(settings),
      h_(f, settings.precision),
      work_(work_count, settings.precision) {}

std::optional<OracleRoot> MpfiRayOracle::first_root(const Ray& ray, Span span) {
    const auto roots = all_roots(ray, span, 1);
    if (roots.empty()) return std::nullopt;
    return roots.front();
}

std::vector<OracleRoot> MpfiRayOracle::all_roots(const Ray& ray, Span span, std::size_t cap) {
    h_.set_ray(ray);
    const std::uint64_t budget_end = h_.evaluations() + settings_.evaluation_budget;
    std::vector<OracleRoot> roots;
    std::optional<Cluster> cluster;
    const auto flush = [&] {
        if (cluster && roots.size() < cap) roots.push_back(resolve(*cluster));
        cluster.reset();
    };
    const auto unresolved = [&](double a, double b) {
        if (cluster && cluster->hi != a) flush();  // a gap: the cluster before it is complete
        if (!cluster) cluster = Cluster{a, b, 0};
        cluster->hi = b;
        if (++cluster->pieces >= settings_.cluster_limit) flush();
    };
    // Pieces still to examine, the leftmost on top; together with what has
    // been examined they always cover [t0, t1] in order.
    std::vector<std::pair<double, double>> stack{{span.t0, span.t1}};
    const auto split = [&](double a, double b) {
        const double m = a + 0.5 * (b - a);
        if (!(a < m && m < b)) return false;
        stack.emplace_back(m, b);
        stack.emplace_back(a, m);
        return true;
    };
    while (!stack.empty() && roots.size() < cap) {
        if (h_.evaluations() > budget_end) throw std::runtime_error("MpfiRayOracle: evaluation budget exceeded");
        const auto [a, b] = stack.back();
        stack.pop_back();
        const Verdict verdict = examine(a, b);
        if (verdict == Verdict::Split && split(a, b)) continue;
        if (verdict == Verdict::Split || verdict == Verdict::Unresolved) {
            unresolved(a, b);
            continue;
        }
        flush();
        if (verdict == Verdict::Excluded || roots.size() >= cap) continue;
        const NewtonOutcome outcome = newton(a, b);
        if (outcome.result == NewtonOutcome::Root) {
            roots.push_back(outcome.root);
        } else if (outcome.result == NewtonOutcome::Stalled) {
            if (outcome.hi - outcome.lo <= tangent_width_ || !split(outcome.lo, outcome.hi))
                unresolved(outcome.lo, outcome.hi);
        }
    }
    flush();
    return roots;
}

MpfiRayOracle::Verdict MpfiRayOracle::examine(double a, double b) {
    mpfi_ptr t = work_[piece];
    mpfi_interv_d(t, a, b);
    const Enclosure whole = h_.evaluate(t, true);
    if (!whole.defined || !mpfi_has_zero(h_.value())) return Verdict::Excluded;
    if (whole.regular) {
        mpfi_ptr d = work_[slope];
        mpfi_set(d, h_.derivative());
        const double m = a + 0.5 * (b - a);
        mpfi_set_d(work_[point], m);
        if (h_.evaluate(work_[point], false).defined) {
            // The mean-value form H(m) + H′(T)·(T − m).
            mpfi_ptr mv = work_[newton_step];
            mpfi_sub_d(mv, t, m);
            mpfi_mul(mv, mv, d);
            mpfi_add(mv, mv, h_.value());
            if (!mpfi_has_zero(mv)) return Verdict::Excluded;
        }
        if (!mpfi_has_zero(d)) return Verdict::Monotone;
    }
    return b - a > tangent_width_ ? Verdict::Split : Verdict::Unresolved;
}

MpfiRayOracle::NewtonOutcome MpfiRayOracle::newton(double a, double b) {
    mpfi_ptr t = work_[piece];
    mpfi_ptr p = work_[point];
    mpfi_ptr n = work_[newton_step];
    mpfi_ptr d = work_[slope];
    mpfr_ptr m = lo(work_[number]);
    mpfi_interv_d(t, a, b);
    const auto stalled = [&](mpfi_ptr left) {  // what is left of the piece, rounded outward to doubles
        return NewtonOutcome{
            NewtonOutcome::Stalled, {}, mpfr_get_d(lo(left), MPFR_RNDD), mpfr_get_d(hi(left), MPFR_RNDU)};
    };
    for (int iteration = 0; width(t) > refine_width_; ++iteration) {
        if (iteration == 200) return stalled(t);
        const Enclosure e = h_.evaluate(t, true);
        if (!e.regular || mpfi_has_zero(h_.derivative())) return stalled(t);
        mpfi_set(d, h_.derivative());
        mpfi_mid(m, t);
        mpfi_set_fr(p, m);
        if (!h_.evaluate(p, false).defined) return stalled(t);
        mpfi_div(n, h_.value(), d);
        mpfi_fr_sub(n, m, n);  // N = m − H(m)/H′(T) holds every root in T
        mpfi_intersect(n, n, t);
        if (mpfi_is_empty(n)) return {NewtonOutcome::NoRoot, {}, 0.0, 0.0};
        const bool stalling = width(n) > stall_ratio * width(t);
        mpfi_set(t, n);
        if (stalling && width(t) > refine_width_) return stalled(t);
    }
    // t is narrower than refine_width: a root is proven when H's sign changes
    // weakly across it; H of one sign at both ends means none.
    mpfi_set_fr(p, lo(t));
    h_.evaluate(p, false);
    mpfi_set(work_[saved], h_.value());
    mpfi_set_fr(p, hi(t));
    h_.evaluate(p, false);
    mpfi_srcptr left = work_[saved];
    mpfi_srcptr right = h_.value();
    const bool same_sign = (mpfi_is_strictly_pos(left) && mpfi_is_strictly_pos(right)) ||
                           (mpfi_is_strictly_neg(left) && mpfi_is_strictly_neg(right));
    if (same_sign) return {NewtonOutcome::NoRoot, {}, 0.0, 0.0};
    // Otherwise the root is in t, or within the 2^-precision noise of H of its end.
    mpfi_mid(m, t);
    mpfi_abs(d, d);
    mpfr_ptr slope_mid = lo(work_[saved]);
    mpfi_mid(slope_mid, d);
    return {
        NewtonOutcome::Root, {mpfr_get_d(m, MPFR_RNDN), RootKind::Simple, mpfr_get_d(slope_mid, MPFR_RNDN)}, 0.0, 0.0};
}

OracleRoot MpfiRayOracle::resolve(const Cluster& cluster) {
    mpfi_ptr t = work_[piece];
    mpfi_interv_d(t, cluster.lo, cluster.hi);
    if (h_.evaluate(t, true).regular) {  // H is continuous on the cluster: a sign change proves a root
        mpfr_ptr a = lo(work_[number]);
        mpfr_ptr b = hi(work_[number]);
        mpfr_set_d(a, cluster.lo, MPFR_RNDN);
        mpfr_set_d(b, cluster.hi, MPFR_RNDN);
        const int sign_a = sign_at(a);
        if (sign_a != 0 && sign_at(b) == -sign_a) return {bisect_sign(a, b, sign_a), RootKind::Multiple, 0.0};
    }
    return {cluster.lo, RootKind::Tangent, 0.0};
}

int MpfiRayOracle::sign(const Ray& ray, double t) {
    h_.set_ray(ray);
    mpfr_ptr at = lo(work_[number]);
    mpfr_set_d(at, t, MPFR_RNDN);
    return sign_at(at);
}

double MpfiRayOracle::magnitude(const Ray& ray, double t) {
    h_.set_ray(ray);
    mpfi_set_d(work_[point], t);
    if (!h_.evaluate(work_[point], false).defined) return std::numeric_limits<double>::infinity();
    mpfr_ptr m = lo(work_[measure]);
    mpfi_mag(m, h_.value());
    return mpfr_get_d(m, MPFR_RNDU);
}

double MpfiRayOracle::width(mpfi_srcptr x) {
    mpfr_ptr w = lo(work_[measure]);
    mpfi_diam_abs(w, x);
    return mpfr_get_d(w, MPFR_RNDU);
}

int MpfiRayOracle::sign_at(mpfr_srcptr t) {
    mpfi_set_fr(work_[point], t);
    if (!h_.evaluate(work_[point], false).defined) return 0;
    if (mpfi_is_strictly_pos(h_.value())) return 1;
    if (mpfi_is_strictly_neg(h_.value())) return -1;
    return 0;
}

double MpfiRayOracle::bisect_sign(mpfr_srcptr lo_end, mpfr_srcptr hi_end, int sign_lo) {
    mpfi_ptr range = work_[newton_step];
    mpfi_interv_fr(range, lo_end, hi_end);
    mpfr_ptr m = lo(work_[saved]);
    for (int iteration = 0; iteration < 400 && width(range) > refine_width_; ++iteration) {
        mpfi_mid(m, range);
        const int sign = sign_at(m);
        if (sign == sign_lo) {
            mpfr_set(lo(range), m, MPFR_RNDD);
        } else if (sign == -sign_lo) {
            mpfr_set(hi(range), m, MPFR_RNDU);
        } else {
            return mpfr_get_d(m, MPFR_RNDN);  // H(m) is 0 to within its enclosure
        }
    }
    mpfi_mid(m, range);
    return mpfr_get_d(m, MPFR_RNDN);
}

}  // namespace zeroset::test
