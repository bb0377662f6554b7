// Recognising Blinn's blobby model written out as an expression: what is a
// sum of Gaussians becomes a blob with the same field, and nothing else does.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/gaussian_sum.hpp"

namespace zeroset {
namespace {

const Expr x = var_x(), y = var_y(), z = var_z();

/// f = T − Σ sᵢ·K(uᵢ) of a model, straight from its components.
double field_of(const BlobModel& model, const Vec3d& p) {
    double f = model.threshold();
    for (std::size_t i = 0; i < model.components().size(); ++i) {
        const BlobComponent& c = model.components()[i];
        f -= c.strength * kernel_value_at(model.kernel(), model.u_at(i, p), c.blobbiness);
    }
    return f;
}

/// Expects the model's field to be the expression's at many points near its components.
void expect_same_field(const Expr& f, const BlobModel& model) {
    const Tape tape(f);
    Evaluator<double> eval(tape);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> offset(-1.5, 1.5);
    for (int i = 0; i < 2000; ++i) {
        const Vec3d c = model.components()[static_cast<std::size_t>(i) % model.components().size()].center;
        const Vec3d p = c + Vec3d{offset(rng), offset(rng), offset(rng)};
        const double want = eval(p.x, p.y, p.z), got = field_of(model, p);
        ASSERT_NEAR(got, want, 1e-12 * (1.0 + std::abs(want))) << "at (" << p.x << ", " << p.y << ", " << p.z << ")";
    }
}

TEST(GaussianSum, AMoleculeWrittenOutIsABlinnBlob) {
    // bench/models/molecule.py's form: 1 − Σ exp(−4·(|p − c|² − 0.25)).
    const std::vector<Vec3d> centers{{0, 0, 0}, {-0.2287, -0.2148, 0.4518}, {0.3046, 0.2749, -0.3663}, {0.5, -0.5, 0.25}};
    Expr sum;
    for (const Vec3d& c : centers)
        sum = sum + exp(-4.0 * (square(x - c.x) + square(y - c.y) + square(z - c.z) - 0.25));
    const Expr f = 1.0 - sum;
    const auto model = gaussian_sum_as_blob(f);
    ASSERT_TRUE(model);
    EXPECT_EQ(model->kernel(), BlobKernel::Blinn);
    EXPECT_EQ(model->threshold(), 1.0);
    ASSERT_EQ(model->components().size(), centers.size());
    for (const BlobComponent& c : model->components()) {
        EXPECT_DOUBLE_EQ(c.radius, 0.5);  // 1/√4
        EXPECT_NEAR(c.strength, 1.0, 1e-15);  // e^(4·0.25 − 1)
        bool found = false;
        for (const Vec3d& want : centers) found = found || length(c.center - want) < 1e-15;
        EXPECT_TRUE(found) << c.center.x << ", " << c.center.y << ", " << c.center.z;
    }
    expect_same_field(f, *model);
}

TEST(GaussianSum, ABlobsOwnExpressionComesBackAsTheSameField) {
    // Other radii, blobbiness and strengths (one negative), written as BlobModel::field_expression writes them.
    std::vector<BlobComponent> parts(3);
    parts[0].center = {1, 0, 0}, parts[0].radius = 0.8, parts[0].strength = 2.0, parts[0].blobbiness = -3.0;
    parts[1].center = {-1, 0.5, 0}, parts[1].radius = 1.3, parts[1].strength = 1.0, parts[1].blobbiness = -0.5;
    parts[2].center = {0, 0, 0.25}, parts[2].radius = 0.4, parts[2].strength = -0.5, parts[2].blobbiness = -2.0;
    const BlobModel written(BlobKernel::Blinn, 0.6, parts);
    const Expr f = written.field_expression();
    const auto model = gaussian_sum_as_blob(f);
    ASSERT_TRUE(model);
    ASSERT_EQ(model->components().size(), 3u);
    expect_same_field(f, *model);
}

TEST(GaussianSum, NothingElseIs) {
    const Expr r2 = square(x) + square(y) + square(z);
    const std::vector<std::pair<const char*, Expr>> others{
        {"a lone Gaussian (T = 0)", -exp(-r2)},
        {"a negative threshold", -1.0 - exp(-r2)},
        {"no exponential", 1.0 - r2},
        {"an anisotropic exponent", 1.0 - exp(-(square(x) + 2.0 * square(y) + square(z)))},
        {"a cross term", 1.0 - exp(-(r2 + x * y))},
        {"a growing exponent", 1.0 - exp(r2)},
        {"a cubic exponent", 1.0 - exp(-(r2 + x * square(y)))},
        {"a product of exponentials", 1.0 - exp(-r2) * exp(-square(x - 1.0))},
        {"another op in the sum", 1.0 - exp(-r2) - sin(x)},
        {"a division by a variable", 1.0 - exp(-r2 / (1.0 + square(x)))},
    };
    for (const auto& [what, f] : others) EXPECT_FALSE(gaussian_sum_as_blob(f)) << what;
}

}  // namespace
}  // namespace zeroset
