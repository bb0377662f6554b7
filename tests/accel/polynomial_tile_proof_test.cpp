// PolynomialTileProof: a tile it proves empty has no ray that meets the
// surface (checked by dense samples along rays through the whole widened
// rectangle), it proves tiles beside a surface and not tiles that see it,
// and its Lebesgue constants bound equispaced interpolation. ProvenTiles
// tries a tile once, after a miss, and stops where proofs spare few rays.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/camera_tiles.hpp"
#include "zeroset/accel/polynomial_tile_proof.hpp"
#include "zeroset/expr/evaluator.hpp"

namespace zeroset {
namespace {

const Expr X = var_x(), Y = var_y(), Z = var_z();

/// A tile of 16 × 16 pixels seen from `eye` along +z, its rectangle's
/// corner at (u0, v0) and 0.01 across.
CameraFrustum tile_at(const Vec3d& eye, double u0, double v0) {
    CameraFrustum f;
    f.origin = eye;
    f.forward = {0, 0, 1};
    f.right = {1, 0, 0};
    f.up = {0, 1, 0};
    f.columns = 16;
    f.rows = 16;
    f.du = 0.01 / f.columns;
    f.dv = -0.01 / f.rows;
    f.u0 = u0;
    f.v0 = v0;
    return f;
}

TEST(PolynomialTileProof, ProvesATileBesideASphereAndNotOneThatSeesIt) {
    const Tape tape(square(X) + square(Y) + square(Z) - 1.0);
    PolynomialTileProof proof(tape);
    const Box3 box{{-1.2, -1.2, -1.2}, {1.2, 1.2, 1.2}};
    TraceCounters counters;
    const Vec3d eye{0, 0, -5};
    EXPECT_TRUE(proof.proves_outside(tile_at(eye, 0.3, 0.1), box, counters));     // passes ~1.5 from the centre
    EXPECT_FALSE(proof.proves_outside(tile_at(eye, -0.005, 0.005), box, counters));  // straight at it
    EXPECT_FALSE(proof.proves_outside(tile_at(eye, 0.195, 0.005), box, counters));   // its rim runs through the tile
    EXPECT_GT(counters.point_evaluations, 0u);
    // A box behind the eye: no camera ray meets it.
    EXPECT_TRUE(proof.proves_outside(tile_at({0, 0, 5}, -0.005, 0.005), box, counters));
    // An eye inside the solid: every ray starts there.
    EXPECT_FALSE(proof.proves_outside(tile_at({0, 0, 0}, 0.3, 0.1), box, counters));
}

/// min over dense samples of f along the rays of the tile's widened
/// rectangle (its corners, edges and inside), at depths through the box.
double least_on_tile(const Tape& tape, const CameraFrustum& tile, const Box3& box) {
    Evaluator<double> f(tape);
    const CameraFrustum::Rectangle r = tile.widened_rectangle();
    double least = std::numeric_limits<double>::infinity();
    constexpr int across = 9, along = 4000;
    for (int i = 0; i < across; ++i)
        for (int j = 0; j < across; ++j) {
            const double u = r.u_lo + (r.u_hi - r.u_lo) * i / (across - 1);
            const double v = r.v_lo + (r.v_hi - r.v_lo) * j / (across - 1);
            const Ray ray{tile.origin, tile.forward + tile.right * u + tile.up * v};
            const auto span = box.clip(ray, 0.0, std::numeric_limits<double>::infinity());
            if (!span) continue;
            for (int k = 0; k <= along; ++k) {
                const Vec3d p = ray.at(span->t0 + (span->t1 - span->t0) * k / along);
                least = std::min(least, f(p.x, p.y, p.z));
            }
        }
    return least;
}

// Random tiles round a torus, a hyperbolic sheet and Steiner's surface
// (which holds whole lines): whatever is proven has f > 0 at every sample
// of every ray; and both verdicts occur, so the check has teeth.
TEST(PolynomialTileProof, NoRayOfAProvenTileMeetsTheSurface) {
    const Expr torus = square(square(X) + square(Y) + square(Z) + 0.6) - 3.2 * (square(X) + square(Y));
    const Expr sheet = square(square(X) + square(Y) - square(Z) + 0.6) - 3.2 * (square(X) + square(Y)) + 0.1;
    const Expr steiner = square(X) * square(Y) + square(Y) * square(Z) + square(Z) * square(X) + X * Y * Z;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> w(-1.0, 1.0);
    int proven = 0, unproven = 0;
    for (const Expr& f : {torus, sheet, steiner}) {
        const Tape tape(f);
        PolynomialTileProof proof(tape);
        const Box3 box{{-2.5, -2.5, -2.5}, {2.5, 2.5, 2.5}};
        TraceCounters counters;
        for (int trial = 0; trial < 60; ++trial) {
            CameraFrustum tile = tile_at({0.5 * w(rng), 0.5 * w(rng), -7.0 + w(rng)}, 0.45 * w(rng), 0.45 * w(rng));
            tile.forward = normalize(Vec3d{0.1 * w(rng), 0.1 * w(rng), 1.0});
            tile.du *= 1.0 + 3.0 * std::abs(w(rng));  // tiles up to 0.04 across
            if (proof.proves_outside(tile, box, counters)) {
                ++proven;
                EXPECT_GT(least_on_tile(tape, tile, box), 0.0) << trial;
            } else {
                ++unproven;
            }
        }
    }
    EXPECT_GT(proven, 40);
    EXPECT_GT(unproven, 20);
}

TEST(PolynomialTileProof, LebesgueConstantsBoundEquispacedInterpolation) {
    for (int n = 1; n <= PolynomialTileProof::max_degree; ++n) {
        double largest = 0.0;
        for (int s = 0; s <= 100000; ++s) {
            const double x = s / 100000.0;
            double sum = 0.0;
            for (int i = 0; i <= n; ++i) {
                double l = 1.0;
                for (int j = 0; j <= n; ++j)
                    if (j != i) l *= (x - static_cast<double>(j) / n) / (static_cast<double>(i - j) / n);
                sum += std::abs(l);
            }
            largest = std::max(largest, sum);
        }
        EXPECT_LE(largest, PolynomialTileProof::lebesgue_bound(n)) << n;
        EXPECT_GE(largest, 0.995 * PolynomialTileProof::lebesgue_bound(n)) << n;  // and close
    }
}

Ray ray_of(const CameraFrustum& tile, double a, double b) {
    Ray ray = test::tile_ray(tile, a, b);
    ray.dir = normalize(ray.dir);
    return ray;
}

TEST(ProvenTiles, ATileIsTriedAfterAMissAndAnswersItsRays) {
    const Tape tape(square(X) + square(Y) + square(Z) - 1.0);
    ProvenTiles tiles(tape);
    const Box3 box{{-1.2, -1.2, -1.2}, {1.2, 1.2, 1.2}};
    TraceCounters counters;
    const CameraFrustum beside = tile_at({0, 0, -5}, 0.3, 0.1);
    ProvenTiles::Entry* e = tiles.entry(beside);
    ASSERT_NE(e, nullptr);
    EXPECT_FALSE(tiles.proven_miss(*e, ray_of(beside, 0.5, 0.5)));  // not tried yet
    tiles.traced(*e, box, false, 1, counters);  // a cheap miss: not worth a proof
    EXPECT_EQ(e->state, ProvenTiles::State::Untried);
    for (std::uint32_t k = 1; k < ProvenTiles::misses_before_proof; ++k) tiles.traced(*e, box, false, 5, counters);
    EXPECT_EQ(e->state, ProvenTiles::State::Untried);
    EXPECT_EQ(counters.point_evaluations, 0u);
    tiles.traced(*e, box, false, 5, counters);  // enough costly ones: tried now
    EXPECT_EQ(e->state, ProvenTiles::State::Proven);
    EXPECT_TRUE(tiles.proven_miss(*tiles.entry(beside), ray_of(beside, 0.2, 0.9)));
    // A ray from elsewhere, or through another part of the image, is not the tile's.
    EXPECT_FALSE(tiles.proven_miss(*e, {{0, 0, -4.9}, ray_of(beside, 0.5, 0.5).dir}));
    EXPECT_FALSE(tiles.proven_miss(*e, ray_of(beside, 1.5, 0.5)));
    // A tile whose first ray hits is never tried.
    const CameraFrustum seeing = tile_at({0, 0, -5}, -0.005, 0.005);
    const std::uint64_t before = counters.point_evaluations;
    ProvenTiles::Entry* s = tiles.entry(seeing);
    tiles.traced(*s, box, true, 5, counters);
    for (std::uint32_t m = 0; m < ProvenTiles::misses_before_proof; ++m) tiles.traced(*s, box, false, 5, counters);
    EXPECT_EQ(s->state, ProvenTiles::State::Unproven);
    EXPECT_EQ(counters.point_evaluations, before);
}

TEST(ProvenTiles, TryingStopsWhenProofsSpareFewRays) {
    const Tape tape(square(X) + square(Y) + square(Z) - 1.0);
    ProvenTiles tiles(tape);
    const Box3 box{{-1.2, -1.2, -1.2}, {1.2, 1.2, 1.2}};
    TraceCounters counters;
    int tried = 0;
    for (int k = 0; k < 100; ++k) {
        // Tiles beside the sphere, each asked once: their proofs spare nothing.
        ProvenTiles::Entry* e = tiles.entry(tile_at({0, 0, -5}, 0.3 + 0.02 * k, 0.1));
        if (!e) break;
        for (std::uint32_t m = 0; m < ProvenTiles::misses_before_proof; ++m) tiles.traced(*e, box, false, 5, counters);
        ++tried;
    }
    EXPECT_EQ(tried, 64);
}

}  // namespace
}  // namespace zeroset
