// Mat4: inverse, products and the point/vector transforms.
#include "zeroset/math/mat4.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace zeroset {
namespace {

Mat4 random_matrix(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    Mat4 m;
    for (auto& row : m.m)
        for (double& v : row) v = u(rng);
    return m;
}

double max_abs_difference(const Mat4& a, const Mat4& b) {
    double d = 0.0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) d = std::max(d, std::abs(a.m[i][j] - b.m[i][j]));
    return d;
}

double max_abs(const Mat4& a) {
    double d = 0.0;
    for (const auto& row : a.m)
        for (const double v : row) d = std::max(d, std::abs(v));
    return d;
}

void expect_near(const Vec3d& a, const Vec3d& b, double tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Mat4, InverseOfRandomMatricesIsTwoSided) {
    std::mt19937_64 rng(42);
    int tested = 0;
    for (int i = 0; i < 500; ++i) {
        const Mat4 m = random_matrix(rng);
        const auto inv = m.inverse();
        ASSERT_TRUE(inv.has_value());
        // Random matrices are occasionally ill-conditioned: scale the tolerance by ‖M‖‖M⁻¹‖.
        const double tolerance = 1e-13 * max_abs(m) * max_abs(*inv) * 16.0;
        EXPECT_LT(max_abs_difference(m * *inv, Mat4::identity()), tolerance) << "matrix " << i;
        EXPECT_LT(max_abs_difference(*inv * m, Mat4::identity()), tolerance) << "matrix " << i;
        ++tested;
    }
    EXPECT_EQ(tested, 500);
}

TEST(Mat4, InverseOfTransforms) {
    const Mat4 m = Mat4::translate({1, -2, 3}) * Mat4::rotate({1, 1, 0}, 0.7) * Mat4::scale({2, 0.5, 4});
    const auto inv = m.inverse();
    ASSERT_TRUE(inv.has_value());
    EXPECT_LT(max_abs_difference(m * *inv, Mat4::identity()), 1e-14);
    // The inverse undoes the transform on points.
    const Vec3d p{0.3, -1.2, 2.5};
    expect_near(inv->transform_point(m.transform_point(p)), p, 1e-14);
    // Wildly different scales per axis are fine (not mistaken for singular).
    const auto s = Mat4::scale({1e-8, 1e8, 1}).inverse();
    ASSERT_TRUE(s.has_value());
    EXPECT_DOUBLE_EQ(s->m[0][0], 1e8);
    EXPECT_DOUBLE_EQ(s->m[1][1], 1e-8);
}

TEST(Mat4, SingularHasNoInverse) {
    EXPECT_FALSE(Mat4{}.inverse().has_value());
    EXPECT_FALSE(Mat4::scale({1, 0, 1}).inverse().has_value());
    // Rows 1..3 of the classic 1…9 matrix are dependent (row 3 = 2·row 2 − row 1),
    // though elimination in floating point leaves a rounding-error-sized pivot.
    Mat4 m = Mat4::identity();
    m.m[0] = {1, 2, 3, 0};
    m.m[1] = {4, 5, 6, 0};
    m.m[2] = {7, 8, 9, 0};
    EXPECT_FALSE(m.inverse().has_value());
    // A random rank-3 matrix: the last row is a combination of the others.
    std::mt19937_64 rng(7);
    for (int i = 0; i < 100; ++i) {
        Mat4 r = random_matrix(rng);
        for (int j = 0; j < 4; ++j) r.m[3][j] = 0.5 * r.m[0][j] - 0.25 * r.m[1][j] + 2.0 * r.m[2][j];
        EXPECT_FALSE(r.inverse().has_value()) << "matrix " << i;
    }
}

TEST(Mat4, TransformPointAndVector) {
    const Mat4 t = Mat4::translate({1, 2, 3});
    EXPECT_EQ(t.transform_point({1, 1, 1}), (Vec3d{2, 3, 4}));
    EXPECT_EQ(t.transform_vector({1, 1, 1}), (Vec3d{1, 1, 1}));  // vectors ignore translation
    const Mat4 s = Mat4::scale({2, 3, 4});
    EXPECT_EQ(s.transform_point({1, 1, 1}), (Vec3d{2, 3, 4}));
    EXPECT_EQ(s.transform_vector({1, -1, 0.5}), (Vec3d{2, -3, 2}));
    // Right-handed rotation: a quarter turn about z takes x to y.
    const Mat4 r = Mat4::rotate({0, 0, 2}, std::numbers::pi / 2);
    expect_near(r.transform_vector({1, 0, 0}), {0, 1, 0}, 1e-15);
    expect_near(r.transform_point({0, 1, 5}), {-1, 0, 5}, 1e-15);
    // Composition applies the right-hand factor first.
    expect_near((t * s).transform_point({1, 1, 1}), {3, 5, 7}, 0.0);
    expect_near((s * t).transform_point({1, 1, 1}), {4, 9, 16}, 0.0);
}

TEST(Mat4, Transpose) {
    Mat4 m;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) m.m[i][j] = 4.0 * i + j;
    const Mat4 t = m.transpose();
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_EQ(t.m[i][j], m.m[j][i]);
    // A rotation's inverse is its transpose.
    const Mat4 r = Mat4::rotate({0.3, -1, 2}, 1.1);
    EXPECT_LT(max_abs_difference(*r.inverse(), r.transpose()), 1e-15);
}

}  // namespace
}  // namespace zeroset
