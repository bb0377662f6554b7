// Qef (the dual-contouring vertex) and the cell patches: planes meeting at a
// corner or an edge put the vertex there, nearly flat planes leave it at the
// crossings' mean, the cell clamps it; patches are marching cubes' pieces
// and a flipped face splits a patch that wraps round it.
#include "zeroset/mesh/qef.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "zeroset/mesh/cell_patches.hpp"

namespace zeroset {
namespace {

const Box3 unit{{0, 0, 0}, {1, 1, 1}};

void expect_point(const Vec3d& got, const Vec3d& want, double tolerance = 1e-12) {
    EXPECT_NEAR(got.x, want.x, tolerance);
    EXPECT_NEAR(got.y, want.y, tolerance);
    EXPECT_NEAR(got.z, want.z, tolerance);
}

TEST(Qef, ThreePlanesMeetAtTheirCorner) {
    Qef q;
    q.add({0.3, 0.1, 0.9}, {1, 0, 0});  // x = 0.3
    q.add({0.8, 0.6, 0.2}, {0, 1, 0});  // y = 0.6
    q.add({0.1, 0.2, 0.45}, {0, 0, -1});  // z = 0.45
    expect_point(q.solve(unit), {0.3, 0.6, 0.45});
}

TEST(Qef, TwoPlanesGiveTheNearestPointOfTheirEdgeToTheMean) {
    Qef q;
    const double s = std::sqrt(0.5);
    q.add({0.2, 0.5, 0.1}, {s, s, 0});  // x + y = 0.7
    q.add({0.2, 0.5, 0.9}, {s, s, 0});
    q.add({0.6, 0.4, 0.3}, {0, 1, 0});  // y = 0.4
    const Vec3d v = q.solve(unit);
    expect_point(v, {0.3, 0.4, (0.1 + 0.9 + 0.3) / 3});  // along the edge (z) the mean stays
}

TEST(Qef, NearlyParallelPlanesDoNotMakeAFeature) {
    // Two planes 2° apart, crossing at x = 0.8: a fit to both would go
    // there, but planes so close make no feature — the vertex stays near
    // the crossings' mean, moved (almost) only across the planes.
    Qef q;
    const double a = 2.0 * 3.14159265358979 / 180.0;
    q.add({0.2, 0.5, 0.5}, {0, 0, 1});
    q.add({0.8, 0.5, 0.5}, {std::sin(a), 0, std::cos(a)});
    const Vec3d v = q.solve(unit);
    EXPECT_NEAR(v.x, 0.5, 1e-3);
    EXPECT_NEAR(v.z, 0.5, 0.01);
}

TEST(Qef, TheVertexIsClampedAndAnEmptyOneIsTheCentre) {
    Qef q;
    q.add({0.9, 0.5, 0.5}, {1, 0, 0});
    q.add({0.5, 0.9, 0.5}, {0, 1, 0});
    q.add({0.5, 0.5, 0.1}, {std::sqrt(0.5), 0, std::sqrt(0.5)});  // x + z = 0.6 with x = 0.9: z = −0.3
    const Vec3d v = q.solve(unit);
    EXPECT_EQ(v.z, 0.0);
    expect_point(Qef{}.solve(unit), {0.5, 0.5, 0.5});
}

TEST(CellPatches, AreTheCyclesOfMarchingCubes) {
    for (int signs = 0; signs < 256; ++signs) {
        const cell::Patches& p = cell::unflipped[static_cast<std::size_t>(signs)];
        int sizes[4] = {0, 0, 0, 0};
        for (int e = 0; e < 12; ++e) {
            const int patch = p.of_edge[static_cast<std::size_t>(e)];
            EXPECT_EQ(patch >= 0, cell::crosses(signs, e)) << signs << " edge " << e;
            if (patch >= 0) ++sizes[patch];
        }
        for (int k = 0; k < p.count; ++k) EXPECT_GE(sizes[k], 3) << signs;  // a patch's boundary: 3 edges or more
    }
    EXPECT_EQ(cell::unflipped[0b00000001].count, 1);  // one corner in
    EXPECT_EQ(cell::unflipped[0b00000011].count, 1);  // an edge in
    EXPECT_EQ(cell::unflipped[0b00001001].count, 2);  // two corners diagonal on a face: kept apart
    EXPECT_EQ(cell::unflipped[0b10000001].count, 2);  // opposite corners of the cube
    EXPECT_EQ(cell::unflipped[0b01111110].count, 2);  // all but those: two caps around them
}

TEST(CellPatches, FlippingAWrappedFaceSplitsItsPatch) {
    // Inside: corners 1 and 7 (diagonal on the face x = 1), joined through
    // 0, 4 and 6 on the far side: one patch wraps round the face.
    const int signs = 0b11010011, face = 1;  // face 1: x = 1
    const cell::Patches plain = cell::unflipped[signs];
    ASSERT_TRUE(cell::wraps_round(plain, signs, face));
    const cell::Patches flipped = cell::patches_of(signs, 1 << face);
    EXPECT_EQ(flipped.count, plain.count + 1);
    EXPECT_FALSE(cell::wraps_round(flipped, signs, face));
}

}  // namespace
}  // namespace zeroset

namespace zeroset {
namespace {

TEST(CellPatches, FlipsNeverLeaveAFaceWrapped) {
    // Every sign pattern, every set of the faces its surface wraps round:
    // flipped, none of them wraps any more, no other face starts to, and a
    // cell never has more than four patches — so two cells that flip their
    // shared face alike leave it wrapped from neither side.
    for (int signs = 0; signs < 256; ++signs) {
        const cell::Patches& plain = cell::unflipped[static_cast<std::size_t>(signs)];
        int wrapped = 0;
        for (int face = 0; face < 6; ++face) wrapped |= cell::wraps_round(plain, signs, face) ? 1 << face : 0;
        for (int flipped = wrapped; flipped > 0; flipped = (flipped - 1) & wrapped) {
            const cell::Patches p = cell::patches_of(signs, flipped);
            EXPECT_LE(p.count, 4) << signs;
            for (int face = 0; face < 6; ++face) EXPECT_FALSE(cell::wraps_round(p, signs, face)) << signs << " face " << face;
        }
    }
}

}  // namespace
}  // namespace zeroset
