// The blob segment solver's enclosure of one component's argument u = |q|²
// and its slope u′ over a stretch of the ray, against long double sampling
// (11 more bits than the enclosure works in) with the mapped ray perturbed
// anywhere within its stated error.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "zeroset/trace/blob_segment.hpp"

namespace zeroset {
namespace {

struct LongVec {
    long double x, y, z;
};

long double dot(const LongVec& a, const LongVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// A mapped ray that looks like a component's: q0 and qd of mixed sizes,
/// sometimes with a coordinate of 0 or a line through the kernel's centre.
KernelOnRay random_kernel(std::mt19937_64& rng, bool with_errors) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> scale(-6, 6), pick(0, 9);
    const auto coordinate = [&] { return pick(rng) == 0 ? 0.0 : std::ldexp(unit(rng), scale(rng)); };
    KernelOnRay k{};
    k.qd = {coordinate(), coordinate(), coordinate()};
    if (pick(rng) < 2) {  // through the centre: q0 on the line of qd
        const double s = unit(rng) * 3.0;
        k.q0 = s * k.qd;
    } else {
        k.q0 = {coordinate(), coordinate(), coordinate()};
    }
    if (with_errors) {
        k.q0_error = std::ldexp(std::abs(unit(rng)), -40 + scale(rng));
        k.qd_error = std::ldexp(std::abs(unit(rng)), -40 + scale(rng));
    }
    return k;
}

TEST(BlobSegment, KernelArgumentEnclosesUAndItsSlope) {
    std::mt19937_64 rng(20261203);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    std::uniform_int_distribution<int> corner(0, 1);
    int checked = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const bool with_errors = trial % 2 == 1;
        const KernelOnRay k = random_kernel(rng, with_errors);
        const double t_c = unit(rng) * 4.0;
        double tau_a = unit(rng) * 2.0, tau_b = unit(rng) * 2.0;
        if (tau_a > tau_b) std::swap(tau_a, tau_b);
        if (trial % 7 == 0) tau_b = tau_a;  // a point
        const KernelArgument a = kernel_argument(k, t_c, tau_a, tau_b);
        ASSERT_LE(a.u.lo, a.u.hi);
        ASSERT_LE(a.du.lo, a.du.hi);
        for (int sample = 0; sample < 8; ++sample) {
            // The ray as mapped exactly: q0 and qd anywhere within their errors (corners of the boxes, mostly).
            const auto off = [&](double error) {
                return sample < 6 ? (corner(rng) == 0 ? -error : error) : error * unit(rng);
            };
            const LongVec q0{k.q0.x + static_cast<long double>(off(k.q0_error)),
                             k.q0.y + static_cast<long double>(off(k.q0_error)),
                             k.q0.z + static_cast<long double>(off(k.q0_error))};
            const LongVec qd{k.qd.x + static_cast<long double>(off(k.qd_error)),
                             k.qd.y + static_cast<long double>(off(k.qd_error)),
                             k.qd.z + static_cast<long double>(off(k.qd_error))};
            const long double tau = sample == 0 ? tau_a : sample == 1 ? tau_b : tau_a + fraction(rng) * (tau_b - tau_a);
            const long double t = static_cast<long double>(t_c) + tau;
            const LongVec q{q0.x + t * qd.x, q0.y + t * qd.y, q0.z + t * qd.z};
            const long double u = dot(q, q), du = 2.0L * dot(q, qd);
            ASSERT_TRUE(a.u.lo <= u && u <= a.u.hi)
                << "u " << static_cast<double>(u) << " outside [" << a.u.lo << ", " << a.u.hi << "] at trial " << trial;
            ASSERT_TRUE(a.du.lo <= du && du <= a.du.hi)
                << "u' " << static_cast<double>(du) << " outside [" << a.du.lo << ", " << a.du.hi << "] at trial " << trial;
            ++checked;
        }
        if (!with_errors && tau_a == tau_b) {  // a point and an exact map: only rounding widens it
            const double u = a.u.mid();
            EXPECT_LE(a.u.width(), 1e-13 * (u + dot(k.q0, k.q0) + t_c * t_c * dot(k.qd, k.qd) + 1e-300));
        }
    }
    EXPECT_EQ(checked, 160000);
}

/// A Blinn component of strength 1 and blobbiness −1 (K = e^(1−u)) centred
/// at (c, 0.2, 0) in kernel space, on the ray along x, within its reach.
KernelOnRay blinn_on_x_axis(double c, std::uint32_t component) {
    KernelOnRay k{};
    k.q0 = {-c, 0.2, 0.0};
    k.qd = {1.0, 0.0, 0.0};
    k.strength = 1.0;
    k.blobbiness = -1.0;
    const std::optional<ReachOnRay> reach = reach_on_ray(k.q0, k.qd, 16.0);
    k.t_in = reach->span.t0;
    k.t_out = reach->span.t1;
    k.nearest = reach->nearest;
    k.component = component;
    return k;
}

TEST(BlobSegment, ASegmentIsCutAtItsComponentsNearestApproaches) {
    // f = 0.5 − Σ e^(1−u): each term rises until the ray's nearest approach
    // to its centre and falls after, so f falls monotonically before the
    // first approach, where an enclosure can prove the first root at once.
    const BlobSegmentSolver solver({BlobKernel::Blinn, 0.5, 1e-10, 10000});
    for (const bool two : {false, true}) {
        std::vector<KernelOnRay> kernels{blinn_on_x_axis(3.0, 0)};
        std::vector<std::uint32_t> active{0};
        if (two) {
            kernels.push_back(blinn_on_x_axis(4.5, 1));
            active.push_back(1);
        }
        const double ta = kernels[0].t_in, tb = kernels.back().t_out;
        std::vector<double> roots;
        TraceCounters counters;
        ASSERT_EQ(solver.roots(kernels, active, ta, tb, true, roots, counters), HitStatus::Ok);
        ASSERT_EQ(roots.size(), 1u);
        // With two components the other's rising term keeps f′ below 0 up to the
        // first approach; one alone has f′ = 0 at its approach, the piece's end,
        // so that piece is halved a few times (halving from the start took 5).
        EXPECT_LE(counters.interval_evaluations, two ? 1u : 4u) << (two ? "two components" : "one component");
        // The first root: Σ e^(1−u) = 0.5 on the way in.
        const ValueAndDerivative f = blob_field_at({BlobKernel::Blinn, 0.5, 1e-10, 10000}, kernels, active, roots[0]);
        EXPECT_NEAR(f.value, 0.0, 1e-12);
        EXPECT_LT(f.derivative, 0.0);
        if (!two) {
            EXPECT_NEAR(roots[0], 3.0 - std::sqrt(1.0 + std::log(2.0) - 0.04), 1e-12);
        }
        // Every root, both ways: the spans' path cuts the same way.
        roots.clear();
        ASSERT_EQ(solver.roots(kernels, active, ta, tb, false, roots, counters), HitStatus::Ok);
        EXPECT_EQ(roots.size(), 2u);
    }
}

}  // namespace
}  // namespace zeroset
