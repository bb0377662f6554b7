// The library's exceptions as Python exceptions: a scene mistake keeps its
// file, line and column as attributes, so a notebook can point at it.
#include <exception>

#include "bindings.hpp"
#include "zeroset/io/image_writer.hpp"
#include "zeroset/render/render_settings.hpp"
#include "zeroset/scene/file_text.hpp"
#include "zeroset/scene/scene_error.hpp"

namespace zeroset::python {

namespace {

/// The exception types, made once and kept for the process's life (Python
/// owns them; a static py::object would be released after the interpreter).
PyObject* scene_error_type = nullptr;
PyObject* render_error_type = nullptr;

void raise_scene_error(const SceneError& e) {
    py::object error = py::reinterpret_borrow<py::object>(scene_error_type)(e.what());
    error.attr("file") = e.file();
    error.attr("line") = e.line();
    error.attr("column") = e.column();
    error.attr("message") = e.message();
    PyErr_SetObject(scene_error_type, error.ptr());
}

}  // namespace

void bind_errors(py::module_& m) {
    scene_error_type = PyErr_NewExceptionWithDoc(
        "zeroset.SceneError",
        "A mistake in a scene or an expression text: str() is 'file:line:column: message'; the attributes file, "
        "line, column (1-based; 0 when the error concerns a whole file) and message hold the parts.",
        PyExc_ValueError, nullptr);
    render_error_type = PyErr_NewExceptionWithDoc(
        "zeroset.RenderError", "A render that cannot be done: bad settings, a surface that evaluates to NaN, a spent budget.",
        PyExc_RuntimeError, nullptr);
    m.attr("SceneError") = py::handle(scene_error_type);
    m.attr("RenderError") = py::handle(render_error_type);
    py::register_exception_translator([](std::exception_ptr thrown) {
        try {
            if (thrown) std::rethrow_exception(thrown);
        } catch (const SceneError& e) {
            raise_scene_error(e);
        } catch (const RenderError& e) {
            PyErr_SetString(render_error_type, e.what());
        } catch (const FileReadError& e) {
            PyErr_SetString(PyExc_OSError, e.what());
        } catch (const ImageWriteError& e) {
            PyErr_SetString(PyExc_OSError, e.what());
        }
    });
}

}  // namespace zeroset::python
