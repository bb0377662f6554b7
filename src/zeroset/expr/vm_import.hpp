// Import of fidget's .vm text format: one SSA clause per line,
// `name opcode args…`, `#` comments, the last clause is the output.
// The models in ../shared/models (bear.vm, prospero.vm) use it.
#pragma once

#include <istream>
#include <stdexcept>
#include <string>

#include "zeroset/expr/expr.hpp"

namespace zeroset {

/// A malformed .vm file: the message names the 1-based line and column.
class VmImportError : public std::runtime_error {
public:
    VmImportError(int line, int column, const std::string& message)
        : std::runtime_error(message), line_(line), column_(column) {}
    [[nodiscard]] int line() const { return line_; }
    [[nodiscard]] int column() const { return column_; }

private:
    int line_;
    int column_;
};

/// Parses a .vm model into an expression.
Expr import_vm(std::istream& in);

}  // namespace zeroset
