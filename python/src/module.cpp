// PYBIND11_MODULE(zeroset): the module's entry point and its docstring.
#include "bindings.hpp"

PYBIND11_MODULE(zeroset, m) {
    m.doc() =
        "zeroset: ray tracing implicit surfaces f(x, y, z) = 0 (negative inside).\n\n"
        "Build expressions with Python operators and the scene language's functions,\n"
        "load or build scenes, and render them to numpy arrays. See docs/python.md.";
    zeroset::python::bind_errors(m);
    zeroset::python::bind_expressions(m);
    zeroset::python::bind_scenes(m);
    zeroset::python::bind_images(m);
    zeroset::python::bind_meshes(m);
}
