// Options that name a ray and an object of a scene — `--origin X,Y,Z`,
// `--dir X,Y,Z`, `--object NAME` — for the commands that look along one ray.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "options.hpp"
#include "zeroset/math/vec3.hpp"
#include "zeroset/scene/scene.hpp"

namespace zeroset::cli {

/// The survey's ray (§1, eq. 4), with the anchor as its eq. (9) writes it.
/// The direction is used as given — it is not quite unit length, and the
/// survey's t values are for it as it is.
inline constexpr Vec3d survey_origin{-4.905, -0.67, 0.364};
inline constexpr Vec3d survey_dir{0.981, 0.174, 0.0872};

/// The option's value as one finite number, or nothing when absent.
std::optional<double> number_option(const Options& options, const std::string& name);

/// The option's value as three finite numbers `X,Y,Z`, or nothing when absent.
std::optional<Vec3d> vector_option(const Options& options, const std::string& name);

/// The option's value as a range `MIN,MAX` with MIN < MAX, or nothing when absent.
std::optional<std::pair<double, double>> range_option(const Options& options, const std::string& name);

/// find_placed_object, its complaint a UsageError.
PlacedObject find_object(const Scene& scene, const std::optional<std::string>& name);

}  // namespace zeroset::cli
