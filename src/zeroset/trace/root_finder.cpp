// The method factory, status names and scale-relative tolerances.
#include "zeroset/trace/root_finder.hpp"

#include <algorithm>
#include <stdexcept>

#include "zeroset/trace/interval_method.hpp"
#include "zeroset/trace/lg_method.hpp"
#include "zeroset/trace/newton_method.hpp"
#include "zeroset/trace/polynomial_method.hpp"
#include "zeroset/trace/sampling_method.hpp"
#include "zeroset/trace/sphere_method.hpp"

namespace zeroset {

std::string_view hit_status_name(HitStatus status) {
    switch (status) {
        case HitStatus::Ok: return "ok";
        case HitStatus::NoHit: return "no hit";
        case HitStatus::Failed: return "failed";
        case HitStatus::Diverged: return "diverged";
    }
    return "?";
}

RootFinderSettings settings_for_scale(double scale) {
    const double s = std::max(scale, 1e-300);
    RootFinderSettings settings;
    settings.sphere_epsilon = 1e-6 * s;
    settings.tangent_width = 1e-10 * s;
    return settings;
}

std::unique_ptr<RootFinder> make_root_finder(Method method, const Tape& tape, const RootFinderSettings& settings) {
    switch (method) {
        case Method::Sphere: return std::make_unique<SphereMethod>(settings);
        case Method::Interval: return std::make_unique<IntervalMethod>(settings);
        case Method::Lg: return std::make_unique<LgMethod>(settings);
        case Method::Polynomial: return std::make_unique<PolynomialMethod>(tape, settings);
        case Method::Newton: return std::make_unique<NewtonMethod>(settings);
        case Method::RegulaFalsi: return std::make_unique<SamplingMethod>(SamplingMethod::Refinement::RegulaFalsi, settings);
        case Method::Bisection: return std::make_unique<SamplingMethod>(SamplingMethod::Refinement::Bisection, settings);
        case Method::Auto: break;
    }
    throw std::invalid_argument("make_root_finder: method '" + std::string(method_name(method)) + "' is not resolved");
}

}  // namespace zeroset
