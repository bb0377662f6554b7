// What `zeroset ray` prints for one ray: a readable table, or one line of
// JSON (docs/ray-command.md describes both, field by field).
#pragma once

#include <optional>
#include <string>

#include "zeroset/render/ray_probe.hpp"

namespace zeroset {

/// Where the ray was cast, for the report's header.
struct RaySubject {
    std::string scene;   // the scene file as given, or "<default>"
    std::string object;  // the object's name; may be empty
    std::optional<double> newton_from;
};

/// The report as text, ending in a newline; numbers with 10 significant digits.
std::string ray_report_text(const RaySubject& subject, const RayProbe& probe);

/// The report as one JSON object on one line (no newline); numbers with 17
/// significant digits, null where there is no value.
std::string ray_report_json(const RaySubject& subject, const RayProbe& probe);

}  // namespace zeroset
