// The ray-intersection methods an object can ask for (survey §§2–5), by name.
// `auto` picks the best correct method for the object (choose_method).
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace zeroset {

enum class Method { Auto, Sphere, Interval, Lg, Polynomial, Newton, RegulaFalsi, Bisection };

/// Every method, `auto` first, in the order help texts list them.
std::span<const Method> all_methods();
/// True for the methods that never miss the first root of a function the
/// evaluator can bound: interval, lg, sphere and (on polynomial surfaces) polynomial.
bool is_guaranteed(Method m);

/// The root solvers of the `polynomial` method (survey §3.4).
enum class PolynomialSolver { Closed, Sturm, Descartes, Laguerre, Fast };

std::span<const PolynomialSolver> all_polynomial_solvers();
std::optional<PolynomialSolver> polynomial_solver_from_name(std::string_view name);
std::string_view polynomial_solver_name(PolynomialSolver s);

/// How surface normals are computed: the exact gradient (eq. 33), forward
/// differences (eq. 34) or central differences.
enum class NormalMode { Analytic, ForwardDifference, CentralDifference };

std::span<const NormalMode> all_normal_modes();

std::optional<Method> method_from_name(std::string_view name);
std::string_view method_name(Method m);
std::optional<NormalMode> normal_mode_from_name(std::string_view name);
std::string_view normal_mode_name(NormalMode m);

}  // namespace zeroset
