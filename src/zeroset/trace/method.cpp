// Names of methods and normal modes, as written in scenes and on the command line.
#include "zeroset/trace/method.hpp"

namespace zeroset {

std::optional<Method> method_from_name(std::string_view name) {
    if (name == "auto") return Method::Auto;
    if (name == "sphere") return Method::Sphere;
    return std::nullopt;
}

std::string_view method_name(Method m) {
    switch (m) {
        case Method::Auto: return "auto";
        case Method::Sphere: return "sphere";
    }
    return "?";
}

std::optional<NormalMode> normal_mode_from_name(std::string_view name) {
    if (name == "analytic") return NormalMode::Analytic;
    if (name == "fd" || name == "forward-difference") return NormalMode::ForwardDifference;
    return std::nullopt;
}

std::string_view normal_mode_name(NormalMode m) {
    return m == NormalMode::Analytic ? "analytic" : "fd";
}

}  // namespace zeroset
