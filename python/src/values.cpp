// to_value / from_value (values.hpp).
#include "values.hpp"

namespace zeroset::python {

Value to_value(py::handle item, const std::string& what) {
    if (py::isinstance<Expr>(item)) return item.cast<Expr>();
    const bool sequence = py::isinstance<py::sequence>(item) && !py::isinstance<py::str>(item);
    if (!sequence && PyNumber_Check(item.ptr())) {  // Python's numbers and numpy's scalars alike
        const double number = PyFloat_AsDouble(item.ptr());
        if (number == -1.0 && PyErr_Occurred()) throw py::error_already_set();
        return Expr(number);
    }
    if (sequence) {
        const auto items = py::reinterpret_borrow<py::sequence>(item);
        if (items.size() == 3) {
            ExprVector v;
            for (std::size_t i = 0; i < 3; ++i) {
                const Value component = to_value(items[i], what);
                if (component.is_vector()) throw py::type_error(what + ": a vector's components must be numbers");
                v[i] = component.number();
            }
            return v;
        }
    }
    throw py::type_error(what + " must be a number, an Expr or a vector of three, not " +
                         std::string(py::str(py::type::handle_of(item).attr("__name__"))));
}

py::object from_value(const Value& value) {
    if (!value.is_vector()) return py::cast(value.number());
    const ExprVector& v = value.vector();
    return py::make_tuple(v[0], v[1], v[2]);
}

}  // namespace zeroset::python
