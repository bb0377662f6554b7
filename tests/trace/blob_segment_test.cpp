// The blob segment solver's enclosure of one component's argument u = |q|²
// and its slope u′ over a stretch of the ray, against long double sampling
// (11 more bits than the enclosure works in) with the mapped ray perturbed
// anywhere within its stated error.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

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

}  // namespace
}  // namespace zeroset
