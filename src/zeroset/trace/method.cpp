// Names of methods and normal modes, as written in scenes and on the command line.
#include "zeroset/trace/method.hpp"

#include <array>

namespace zeroset {

namespace {
constexpr std::array methods{Method::Auto,   Method::Sphere,      Method::Interval, Method::Lg,
                             Method::Newton, Method::RegulaFalsi, Method::Bisection};
}  // namespace

std::span<const Method> all_methods() { return methods; }

bool is_guaranteed(Method m) { return m == Method::Sphere || m == Method::Interval || m == Method::Lg; }

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
        case Method::Newton: return "newton";
        case Method::RegulaFalsi: return "regula_falsi";
        case Method::Bisection: return "bisection";
    }
    return "?";
}

std::optional<NormalMode> normal_mode_from_name(std::string_view name) {
    if (name == "analytic") return NormalMode::Analytic;
    if (name == "fd" || name == "forward-difference") return NormalMode::ForwardDifference;
    return std::nullopt;
}

std::string_view normal_mode_name(NormalMode m) { return m == NormalMode::Analytic ? "analytic" : "fd"; }

}  // namespace zeroset
