// Options that name a ray and an object of a scene — `--origin X,Y,Z`,
// `--dir X,Y,Z`, `--object NAME` — for the commands that look along one ray.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "options.hpp"
#include "zeroset/math/vec3.hpp"
#include "zeroset/render/ray_probe.hpp"
#include "zeroset/scene/scene.hpp"

namespace zeroset::cli {

/// The option's value as one finite number, or nothing when absent.
std::optional<double> number_option(const Options& options, const std::string& name);

/// The option's value as three finite numbers `X,Y,Z`, or nothing when absent.
std::optional<Vec3d> vector_option(const Options& options, const std::string& name);

/// The option's value as a range `MIN,MAX` with MIN < MAX, or nothing when absent.
std::optional<std::pair<double, double>> range_option(const Options& options, const std::string& name);

/// find_placed_object, its complaint a UsageError.
PlacedObject find_object(const Scene& scene, const std::optional<std::string>& name);

}  // namespace zeroset::cli
