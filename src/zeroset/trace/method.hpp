// The ray-intersection methods an object can ask for. Only sphere tracing
// exists so far; `auto` picks the best correct method for the object.
#pragma once

#include <optional>
#include <string_view>

namespace zeroset {

enum class Method { Auto, Sphere };

/// How surface normals are computed: the exact gradient (eq. 33) or forward
/// differences (eq. 34).
enum class NormalMode { Analytic, ForwardDifference };

std::optional<Method> method_from_name(std::string_view name);
std::string_view method_name(Method m);
std::optional<NormalMode> normal_mode_from_name(std::string_view name);
std::string_view normal_mode_name(NormalMode m);

}  // namespace zeroset
