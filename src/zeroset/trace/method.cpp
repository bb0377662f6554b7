// Names of methods and normal modes, as written in scenes and on the command line.
#include "zeroset/trace/method.hpp"

#include <array>

namespace zeroset {

namespace {
constexpr std::array methods{Method::Auto,       Method::Sphere, Method::Interval,    Method::Lg,
                             Method::Polynomial, Method::Newton, Method::RegulaFalsi, Method::Bisection};
constexpr std::array solvers{PolynomialSolver::Closed, PolynomialSolver::Sturm, PolynomialSolver::Descartes,
                             PolynomialSolver::Laguerre, PolynomialSolver::Fast};
constexpr std::array normal_modes{NormalMode::Analytic, NormalMode::ForwardDifference, NormalMode::CentralDifference};
}  // namespace

std::span<const Method> all_methods() { return methods; }

bool is_guaranteed(Method m) {
    return m == Method::Sphere || m == Method::Interval || m == Method::Lg || m == Method::Polynomial;
}

std::span<const PolynomialSolver> all_polynomial_solvers() { return solvers; }

std::optional<PolynomialSolver> polynomial_solver_from_name(std::string_view name) {
    for (const PolynomialSolver s : solvers)
        if (polynomial_solver_name(s) == name) return s;
    return std::nullopt;
}

std::string_view polynomial_solver_name(PolynomialSolver s) {
    switch (s) {
        case PolynomialSolver::Closed: return "closed";
        case PolynomialSolver::Sturm: return "sturm";
        case PolynomialSolver::Descartes: return "descartes";
        case PolynomialSolver::Laguerre: return "laguerre";
        case PolynomialSolver::Fast: return "fast";
    }
    return "?";
}

std::optional<Method> method_from_name(std::string_view name) {
    for (const Method m : methods)
        if (method_name(m) == name) return m;
    return std::nullopt;
}

std::string_view method_name(Method m) {
    switch (m) {
        case Method::Auto: return "auto";
        case Method::Sphere: return "sphere";
        case Method::Interval: return "interval";
        case Method::Lg: return "lg";
        case Method::Polynomial: return "polynomial";
        case Method::Newton: return "newton";
        case Method::RegulaFalsi: return "regula_falsi";
        case Method::Bisection: return "bisection";
    }
    return "?";
}

std::span<const NormalMode> all_normal_modes() { return normal_modes; }

std::optional<NormalMode> normal_mode_from_name(std::string_view name) {
    for (const NormalMode m : normal_modes)
        if (normal_mode_name(m) == name) return m;
    if (name == "forward-difference") return NormalMode::ForwardDifference;
    if (name == "central-difference") return NormalMode::CentralDifference;
    return std::nullopt;
}

std::string_view normal_mode_name(NormalMode m) {
    switch (m) {
        case NormalMode::Analytic: return "analytic";
        case NormalMode::ForwardDifference: return "fd";
        case NormalMode::CentralDifference: return "central";
    }
    return "?";
}

}  // namespace zeroset
