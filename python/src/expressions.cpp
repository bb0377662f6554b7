// Expressions from Python: Expr with +, -, *, /, ** and unary minus (numbers
// on either side), the coordinates x, y, z, and every function of the scene
// language. The functions are not bound one by one: a call is handed to the
// language's own parser with its arguments bound as names, so Python and
// scene files share one table, one set of argument checks and one wording.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "values.hpp"
#include "zeroset/expr/evaluator.hpp"
#include "zeroset/expr/tape.hpp"
#include "zeroset/scene/expression_parser.hpp"
#include "zeroset/scene/model_library.hpp"
#include "zeroset/scene/scene_error.hpp"

namespace zeroset::python {

namespace {

/// `name(_0, _1, …)` read by the scene language with _i bound to argument i.
/// Its complaints are about the call, not a place in generated text, so they
/// become ValueError with the message alone.
py::object call_function(const std::string& name, const py::args& args) {
    std::vector<std::pair<std::string, Value>> bindings;
    std::string text = name + "(";
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string bound = "_" + std::to_string(i);
        bindings.emplace_back(bound, to_value(args[i], name + " argument " + std::to_string(i + 1)));
        text += (i ? ", " : "") + bound;
    }
    text += ")";
    try {
        return from_value(evaluate_expression_text(text, bindings, "<python>", std::filesystem::current_path()));
    } catch (const SceneError& e) {
        throw py::value_error(e.message());
    }
}

/// An integer exponent of at most 1024 in size is exact repeated
/// multiplication, as `^` is in the scene language; any other is pow().
Expr power(const Expr& base, const py::object& exponent) {
    constexpr long long exact = 1024;
    if (PyIndex_Check(exponent.ptr())) {
        const auto index = py::reinterpret_steal<py::object>(PyNumber_Index(exponent.ptr()));
        if (!index) throw py::error_already_set();
        int overflow = 0;
        const long long n = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
        if (!overflow && n >= -exact && n <= exact) return powi(base, static_cast<int>(n));
    }
    return pow(base, to_value(exponent, "the exponent").number());
}

/// f at points: numbers give a float, arrays broadcast (numpy's rules) to an
/// array of float64.
py::object evaluate(const Expr& f, const py::object& px, const py::object& py_, const py::object& pz) {
    const Tape tape(f);
    Evaluator<double> eval(tape);
    auto at = [&eval](double x, double y, double z) { return eval(x, y, z); };
    return py::vectorize(at)(px, py_, pz);
}

}  // namespace

void bind_expressions(py::module_& m) {
    py::class_<Expr>(m, "Expr",
                     "An implicit function f(x, y, z): negative inside, zero on the surface. Build it from x, y, z "
                     "with Python's operators and zeroset's functions; call it to evaluate.")
        .def(py::init<double>(), py::arg("constant"), "The constant function.")
        .def("__add__", [](const Expr& a, const Expr& b) { return a + b; }, py::is_operator())
        .def("__radd__", [](const Expr& a, double b) { return Expr(b) + a; }, py::is_operator())
        .def("__sub__", [](const Expr& a, const Expr& b) { return a - b; }, py::is_operator())
        .def("__rsub__", [](const Expr& a, double b) { return Expr(b) - a; }, py::is_operator())
        .def("__mul__", [](const Expr& a, const Expr& b) { return a * b; }, py::is_operator())
        .def("__rmul__", [](const Expr& a, double b) { return Expr(b) * a; }, py::is_operator())
        .def("__truediv__", [](const Expr& a, const Expr& b) { return a / b; }, py::is_operator())
        .def("__rtruediv__", [](const Expr& a, double b) { return Expr(b) / a; }, py::is_operator())
        .def("__pow__", &power, py::is_operator(),
             "An integer exponent up to 1024 in size is exact repeated multiplication; others are pow().")
        .def("__rpow__", [](const Expr& a, double b) { return pow(Expr(b), a); }, py::is_operator())
        .def("__neg__", [](const Expr& a) { return -a; })
        .def("__pos__", [](const Expr& a) { return a; })
        .def("__call__", &evaluate, py::arg("x"), py::arg("y"), py::arg("z"),
             "f at (x, y, z): floats give a float; numpy arrays broadcast and give an array.")
        // A DAG prints as the tree it unfolds to, which can be exponentially
        // larger: the text stops, with "…", at 200 characters in repr() and
        // at 10 million in str().
        .def("__repr__", [](const Expr& e) { return "Expr(" + e.to_string(200) + ")"; })
        .def("__str__", [](const Expr& e) { return e.to_string(10'000'000); })
        .def_property_readonly("is_constant", &Expr::is_constant_valued, "True when no x, y or z occurs in it.")
        .def_property_readonly("node_count", &Expr::node_count, "Distinct nodes of its DAG (shared parts once).");
    py::implicitly_convertible<double, Expr>();
    py::implicitly_convertible<py::int_, Expr>();

    m.attr("x") = var_x();
    m.attr("y") = var_y();
    m.attr("z") = var_z();
    m.attr("pi") = std::numbers::pi;

    for (const std::string& name : function_names()) {
        if (name == "model") continue;  // takes a file name: load_vm() and parse() cover it
        m.def(
            name.c_str(), [name](const py::args& args) { return call_function(name, args); },
            ("The scene language's " + name + "() (docs/scene-language.md, docs/shapes.md).").c_str());
    }

    m.def(
        "parse",
        [](const std::string& text, const py::kwargs& names) {
            std::vector<std::pair<std::string, Value>> bindings;
            double clock = 0.0;
            for (const auto& [key, item] : names) {
                const std::string name = key.cast<std::string>();
                if (name == "clock") {
                    clock = item.cast<double>();
                    continue;
                }
                bindings.emplace_back(name, to_value(item, "'" + name + "'"));
            }
            return from_value(
                evaluate_expression_text(text, bindings, "<expression>", std::filesystem::current_path(), clock));
        },
        py::arg("text"),
        "A scene-language expression, e.g. parse('sd_torus(1, r)', r=0.25); keyword arguments are names it may use, "
        "and clock= the value of `clock` (0 by default). A mistake raises SceneError with its line and column.");
    m.def(
        "load_vm",
        [](const std::string& path) {
            ModelLibrary models;
            return models.load(path, path);
        },
        py::arg("path"), "A model in fidget's .vm format, as an Expr.");
}

}  // namespace zeroset::python
