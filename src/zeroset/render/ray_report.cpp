// Formatting a RayProbe as a table and as JSON.
#include "zeroset/render/ray_report.hpp"

#include <algorithm>
#include <cstdio>

#include "zeroset/io/json_writer.hpp"

namespace zeroset {

namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", v);
    return text;
}

std::string number_list(const std::vector<double>& values) {
    if (values.empty()) return "-";
    std::string text;
    for (const double v : values) text += (text.empty() ? "" : ", ") + number(v);
    return text;
}

std::string vector_text(const Vec3d& v) { return number(v.x) + ", " + number(v.y) + ", " + number(v.z); }

/// `text` padded with spaces to `width` columns (counting UTF-8 code points), left or right aligned.
std::string padded(const std::string& text, std::size_t width, bool right = false) {
    const auto columns = static_cast<std::size_t>(
        std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
    const std::string fill(columns < width ? width - columns : 0, ' ');
    return right ? fill + text : text + fill;
}

void write_vector(JsonWriter& json, const Vec3d& v) { json.begin_array().number(v.x).number(v.y).number(v.z).end_array(); }

void write_optional(JsonWriter& json, const std::optional<double>& v) {
    if (v) json.number(*v);
    else json.null();
}

}  // namespace

std::string ray_report_text(const RaySubject& subject, const RayProbe& probe) {
    std::string out = "scene    " + subject.scene + "\n";
    out += "object   " + (subject.object.empty() ? std::string("(unnamed)") : subject.object) + "\n";
    out += "origin   " + vector_text(probe.ray.origin) + "\n";
    out += "dir      " + vector_text(probe.ray.dir) + "   (used as given: |dir| = " + number(length(probe.ray.dir)) + ")\n";
    if (probe.span)
        out += "span     t0 = " + number(probe.span->t0) + ", t1 = " + number(probe.span->t1) +
               (probe.unbounded ? "   (no bounds: the ray in a box about where it meets the plane, shrunk to its surface; from t = 0)\n"
                                : "   (the ray inside the object's bounds, shrunk to its surface; from t = 0)\n");
    else if (probe.misses_gate)
        out += "span     none: the ray misses the object's gate\n";
    else if (probe.unbounded)
        out += "span     none: the ray does not meet the plane (the object has no bounds)\n";
    else
        out += "span     none: the ray misses the object's bounds (shrunk to its surface)\n";
    if (subject.newton_from) out += "newton   starts at t = " + number(*subject.newton_from) + "\n";

    constexpr std::size_t method_w = 17, t_w = 17, status_w = 10, evals_w = 7;
    out += "\n" + padded("", method_w) + padded("first hit", t_w + status_w + evals_w + 3) + "all hits\n";
    out += padded("method", method_w) + padded("t", t_w) + padded("status", status_w) + padded("evals", evals_w, true) +
           "   " + padded("status", status_w) + padded("evals", evals_w, true) + "   t\n";
    std::string failures;
    for (const MethodOutcome& o : probe.methods) {
        out += padded(method_label(o), method_w) + padded(o.first_hit ? number(*o.first_hit) : "-", t_w) +
               padded(std::string(hit_status_name(o.status)), status_w) +
               padded(std::to_string(o.evaluations), evals_w, true) + "   " +
               padded(std::string(hit_status_name(o.all_hits_status)), status_w) +
               padded(std::to_string(o.all_hits_evaluations), evals_w, true) + "   " + number_list(o.hits) + "\n";
        if (!o.message.empty()) failures += "  " + method_label(o) + ": " + o.message + "\n";
    }
    return failures.empty() ? out : out + "\n" + failures;
}

std::string ray_report_json(const RaySubject& subject, const RayProbe& probe) {
    JsonWriter json;
    json.begin_object();
    json.key("scene").string(subject.scene);
    json.key("object");
    if (subject.object.empty()) json.null();
    else json.string(subject.object);
    json.key("origin");
    write_vector(json, probe.ray.origin);
    json.key("dir");
    write_vector(json, probe.ray.dir);
    json.key("t0");
    write_optional(json, probe.span ? std::optional(probe.span->t0) : std::nullopt);
    json.key("t1");
    write_optional(json, probe.span ? std::optional(probe.span->t1) : std::nullopt);
    json.key("newton_from");
    write_optional(json, subject.newton_from);
    json.key("methods").begin_array();
    for (const MethodOutcome& o : probe.methods) {
        json.begin_object();
        json.key("method").string(method_name(o.method));
        json.key("resolved").string(method_name(o.resolved));
        json.key("first_hit");
        write_optional(json, o.first_hit);
        json.key("status").string(hit_status_name(o.status));
        json.key("evaluations").integer(o.evaluations);
        json.key("hits").begin_array();
        for (const double t : o.hits) json.number(t);
        json.end_array();
        json.key("all_hits_status").string(hit_status_name(o.all_hits_status));
        json.key("all_hits_evaluations").integer(o.all_hits_evaluations);
        json.key("message");
        if (o.message.empty()) json.null();
        else json.string(o.message);
        json.end_object();
    }
    json.end_array();
    json.end_object();
    return json.text();
}

}  // namespace zeroset
