// The token cursor.
#include "zeroset/scene/token_stream.hpp"

#include <algorithm>
#include <utility>

#include "zeroset/scene/scene_error.hpp"

namespace zeroset {

TokenStream::TokenStream(std::string file_name, std::string text)
    : file_name_(std::move(file_name)), text_(std::move(text)), tokens_(tokenize(text_, file_name_)) {}

bool TokenStream::accept(TokenKind kind) {
    if (!at(kind)) return false;
    next();
    return true;
}

const Token& TokenStream::expect(TokenKind kind) {
    if (!at(kind)) fail_expected(token_kind_name(kind));
    return next();
}

void TokenStream::fail(SourceLocation where, const std::string& message) const {
    throw SceneError(file_name_, where, message);
}

void TokenStream::fail_expected(std::string_view what) const {
    fail(peek().where, "expected " + std::string(what) + " but found " + describe(peek()));
}

}  // namespace zeroset
