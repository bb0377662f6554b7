// The method factory and status names.
#include "zeroset/trace/root_finder.hpp"

#include <stdexcept>

#include "zeroset/trace/interval_method.hpp"
#include "zeroset/trace/lg_method.hpp"
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

std::unique_ptr<RootFinder> make_root_finder(Method method, const Tape& tape, const RootFinderSettings& settings) {
    switch (method) {
        case Method::Sphere: return std::make_unique<SphereMethod>(tape, settings);
        case Method::Interval: return std::make_unique<IntervalMethod>(settings);
        case Method::Lg: return std::make_unique<LgMethod>(settings);
        default: break;
    }
    throw std::invalid_argument("make_root_finder: method '" + std::string(method_name(method)) + "' is not resolved");
}

}  // namespace zeroset
