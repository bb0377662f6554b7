// `auto` resolves to the polynomial method on polynomials and to sphere
// tracing on everything else; explicit methods pass through.
#include <gtest/gtest.h>
#include "support/models.hpp"

#include <fstream>

#include "zeroset/expr/vm_import.hpp"
#include "zeroset/trace/choose_method.hpp"

namespace zeroset {
namespace {

TEST(ChooseMethod, AutoPicksPolynomialForPolynomialsAndSphereForTheRest) {
    const Tape quartic(square(square(var_x()) + square(var_y()) + square(var_z()) + 0.75) - 4.0 * (square(var_x()) + square(var_y())));
    EXPECT_EQ(resolve_method(Method::Auto, quartic), Method::Polynomial);
    const Tape blob(Expr(1.0) - exp(-(square(var_x() - 1.2) + square(var_y()) + square(var_z()) - 1.0)));
    EXPECT_EQ(resolve_method(Method::Auto, blob), Method::Sphere);
    ZEROSET_SKIP_WITHOUT_MODEL("bear.vm");
    std::ifstream in(ZEROSET_MODELS_DIR "/bear.vm");
    const Tape bear(import_vm(in));
    EXPECT_EQ(resolve_method(Method::Auto, bear), Method::Sphere);
}

TEST(ChooseMethod, ExplicitMethodsAreKept) {
    const Tape sphere(square(var_x()) + square(var_y()) + square(var_z()) - 1.0);
    for (const Method m : all_methods()) {
        if (m == Method::Auto) continue;
        EXPECT_EQ(resolve_method(m, sphere), m);
    }
}

}  // namespace
}  // namespace zeroset
