// Reading ray and object options.
#include "ray_options.hpp"

#include <charconv>
#include <cmath>
#include <vector>

namespace zeroset::cli {

namespace {

/// `text` as comma-separated finite numbers, or nothing if it is not that.
std::optional<std::vector<double>> comma_numbers(const std::string& text) {
    std::vector<double> result;
    const char* p = text.data();
    const char* const end = p + text.size();
    while (true) {
        double value = 0.0;
        const auto [next, error] = std::from_chars(p, end, value);
        if (error != std::errc() || !std::isfinite(value)) return std::nullopt;
        result.push_back(value);
        p = next;
        if (p == end) return result;
        if (*p != ',') return std::nullopt;
        ++p;
    }
}

}  // namespace

std::optional<double> number_option(const Options& options, const std::string& name) {
    const auto text = options.value(name);
    if (!text) return std::nullopt;
    const auto v = comma_numbers(*text);
    if (!v || v->size() != 1) throw UsageError("option " + name + " needs a finite number, got '" + *text + "'");
    return v->front();
}

std::optional<Vec3d> vector_option(const Options& options, const std::string& name) {
    const auto text = options.value(name);
    if (!text) return std::nullopt;
    const auto v = comma_numbers(*text);
    if (!v || v->size() != 3)
        throw UsageError("option " + name + " needs three finite numbers X,Y,Z, got '" + *text + "'");
    return Vec3d{(*v)[0], (*v)[1], (*v)[2]};
}

std::optional<std::pair<double, double>> range_option(const Options& options, const std::string& name) {
    const auto text = options.value(name);
    if (!text) return std::nullopt;
    const auto v = comma_numbers(*text);
    if (!v || v->size() != 2 || !((*v)[0] < (*v)[1]))
        throw UsageError("option " + name + " needs MIN,MAX with MIN < MAX, got '" + *text + "'");
    return std::pair{(*v)[0], (*v)[1]};
}

PlacedObject find_object(const Scene& scene, const std::optional<std::string>& name) {
    try {
        return find_placed_object(scene, name);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
}

}  // namespace zeroset::cli
