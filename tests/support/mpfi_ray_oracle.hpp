// The first-hit reference: the smallest root of H(t) = f(o + t·d) in [t0, t1],
// computed rigorously with MPFI (mpfi_ray_function.hpp) — the oracle every
// ray-intersection method is checked against (DESIGN.md, "Testing principles").
//
// The search is the survey's Fig. 9 done in high precision, left to right:
//   - a piece T of [t0, t1] is discarded when 0 ∉ H(T), enclosed both
//     naturally and by the mean-value form H(m) + H′(T)·(T − m) (the latter is
//     what rejects rays that miss a surface by a hair: its overestimate
//     shrinks with the square of T's width);
//   - where 0 ∉ H′(T), H is monotone on T: interval Newton,
//     N = m − H(m)/H′(T) ∩ T, either empties (no root) or contracts to a
//     proven root, refined to `refine_width` × scale (≪ 1e-15 relative) —
//     a `Simple` root;
//   - otherwise T is halved, down to `tangent_width` × scale. Contiguous
//     pieces still containing 0 at that width form a cluster: if H's sign is
//     proven to change across it (and H is continuous there), the crossing is
//     refined by sign bisection and reported as `Multiple` (an odd-order root,
//     or roots too close to separate); otherwise the cluster's left end is
//     reported as `Tangent` (a double root, a kink touching 0, or a miss too
//     narrow to resolve at that width: |H| ≲ |H″|·tangent_width² there).
// H′ is forward-mode (value, derivative) pairs of mpfi intervals. Everything
// is deterministic; a query that needs more than `evaluation_budget`
// evaluations throws rather than answer unproven.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "support/mpfi_ray_function.hpp"
#include "zeroset/math/box3.hpp"

namespace zeroset::test {

enum class RootKind {
    Simple,    // a unique root proven where 0 ∉ H′; |t − root| ≤ refine_width × scale
    Multiple,  // a proven sign change where H′ cannot be separated from 0 at tangent_width
    Tangent,   // 0 not excluded at tangent_width and no sign change: a touching root
};

struct OracleRoot {
    double t;
    RootKind kind;
    double slope;  // |H′(t)| for a simple root (the midpoint of its enclosure); 0 otherwise
};

struct OracleSettings {
    mpfr_prec_t precision = 200;                // bits
    double tangent_width = 1e-13;               // × scale: the finest bisection where 0 ∈ H′
    double refine_width = 1e-30;                // × scale: enclosure width of a reported simple root
    std::size_t cluster_limit = 64;             // pieces in one cluster before it is reported
    std::uint64_t evaluation_budget = 400'000;  // per query
};

class MpfiRayOracle {
public:
    /// `scale`: the size of the scene (its bounds' diagonal); widths are relative to it.
    MpfiRayOracle(const Expr& f, double scale, OracleSettings settings = {});

    /// The first root of H in span, if any.
    std::optional<OracleRoot> first_root(const Ray& ray, Span span);
    /// The roots of H in span in increasing order, at most `cap` of them.
    std::vector<OracleRoot> all_roots(const Ray& ray, Span span, std::size_t cap);

    /// The sign of H at t: ±1 when proven, 0 when H(t) is 0 to within the
    /// precision or undefined.
    int sign(const Ray& ray, double t);
    /// An upper bound on |H(t)|; +∞ where H is undefined.
    double magnitude(const Ray& ray, double t);

    /// Evaluations of H so far (over all queries).
    [[nodiscard]] std::uint64_t evaluations() const { return h_.evaluations(); }

private:
    enum class Verdict { Excluded, Monotone, Split, Unresolved };
    struct Cluster {
        double lo, hi;
        std::size_t pieces;
    };
    /// What a Newton iteration on a monotone piece found: a root, none, or a
    /// narrower piece it could not contract further (to be bisected).
    struct NewtonOutcome {
        enum { Root, NoRoot, Stalled } result;
        OracleRoot root;
        double lo, hi;
    };

    Verdict examine(double a, double b);
    NewtonOutcome newton(double a, double b);
    OracleRoot resolve(const Cluster& cluster);
    /// The width of x, rounded up.
    double width(mpfi_srcptr x);
    /// Sign of H at t: +1 or −1 when proven, 0 when the enclosure holds 0 or H is undefined.
    int sign_at(mpfr_srcptr t);
    /// A root in [lo, hi] where H has sign `sign_lo` at lo and the opposite at hi.
    double bisect_sign(mpfr_srcptr lo, mpfr_srcptr hi, int sign_lo);

    double tangent_width_;
    double refine_width_;
    OracleSettings settings_;
    MpfiRayFunction h_;
    MpfiArray work_;  // intervals and (as endpoints) numbers for the search
};

}  // namespace zeroset::test
