// The parts of the Python module, each binding one concept of the library;
// module.cpp calls them in order (errors first: the others raise them).
#pragma once

#include <pybind11/pybind11.h>

namespace zeroset::python {

namespace py = pybind11;

/// zeroset.SceneError (a ValueError with file, line, column and message)
/// and zeroset.RenderError (a RuntimeError), and the translation of the
/// library's exceptions into them.
void bind_errors(py::module_& m);
/// Expr with Python's operators, x, y, z, pi, every function of the scene
/// language, parse() and load_vm().
void bind_expressions(py::module_& m);
/// Camera, Light, Material, Bounds and Scene; load_scene(), parse_scene(), default_scene().
void bind_scenes(py::module_& m);
/// render(), slice(), ray() and write_image(): numpy arrays and Python objects out.
void bind_images(py::module_& m);
/// mesh(): a surface's triangle mesh as numpy arrays.
void bind_meshes(py::module_& m);

}  // namespace zeroset::python
