// The POV-Ray token stream: files, macro and function bodies as frames;
// directives carried out as they are met (#declare, #local, #undef,
// #include, #if/#ifdef/#ifndef/#elseif/#else, #while, #for, #switch,
// #macro, #version, #default, #debug, #warning, #error); the symbol scopes.
#include <algorithm>
#include <cmath>

#include "zeroset/pov/pov_parser.hpp"
#include "zeroset/scene/file_text.hpp"

namespace zeroset::pov {

namespace {

/// Includes nested deeper than this are an error (an include cycle, surely).
constexpr int max_include_depth = 64;
/// Macros calling macros deeper than this are an error.
constexpr int max_macro_depth = 200;

bool opens_block(const PovToken& t) {
    static constexpr std::array<std::string_view, 7> openers{"if", "ifdef", "ifndef", "while", "for", "switch", "macro"};
    return t.kind == PovTokenKind::Directive && std::find(openers.begin(), openers.end(), t.text) != openers.end();
}

}  // namespace

PovParser::Nesting::Nesting(PovParser& parser, Kind kind)
    : parser_(parser), depth_(kind == Kind::Directive ? parser.directive_nesting_ : parser.nesting_) {
    if (++depth_ > max_nesting) {
        --depth_;
        // Raw: peek() could run a directive, which nests again.
        parser_.fail(parser_.peek_raw(0), kind == Kind::Directive
                                              ? "directives nested more than 200 deep (a value that begins with another directive)"
                                              : "expressions or objects nested more than 200 deep");
    }
}

PovParser::PovParser(const PovOptions& options) : options_(options) {
    scopes_.emplace_back();
    for (const auto& dir : options.include_paths) include_dirs_.push_back(dir.string());
    if (options.search_installed_includes)
        for (const auto& dir : installed_pov_include_dirs()) include_dirs_.push_back(dir.string());
}

std::size_t PovParser::add_file(std::string name, std::filesystem::path dir, std::string text) {
    auto file = std::make_unique<SourceFile>();
    file->name = std::move(name);
    file->dir = std::move(dir);
    file->text = std::move(text);
    file->tokens = tokenize_pov(file->text, file->name);
    for (PovToken& t : file->tokens) t.file = static_cast<std::uint32_t>(files_.size());
    files_.push_back(std::move(file));
    return files_.size() - 1;
}

const PovToken& PovParser::peek() {
    for (;;) {
        Frame& f = frames_.back();
        const std::vector<PovToken>& tokens = files_[f.file]->tokens;
        const bool ended = f.pos >= f.end || tokens[f.pos].kind == PovTokenKind::End;
        if (ended) {
            if (frames_.size() == 1 || f.kind == Frame::Kind::Function) return tokens[std::min(f.pos, tokens.size() - 1)];
            pop_frame();
            continue;
        }
        const PovToken& t = tokens[f.pos];
        if (t.kind == PovTokenKind::Directive) {
            ++f.pos;
            directive(t);
            continue;
        }
        if (t.kind == PovTokenKind::Name && function_scopes_.empty()) {
            if (const auto m = macros_.find(t.text); m != macros_.end() && !lookup(t.text)) {
                ++f.pos;
                call_macro(t, m->second);
                continue;
            }
        }
        return t;
    }
}

void PovParser::pop_frame() {
    const Frame& f = frames_.back();
    const std::vector<PovToken>& tokens = files_[f.file]->tokens;
    if (blocks_.size() != f.blocks) {
        const Block& open = blocks_.back();
        fail(tokens[std::min(f.pos, tokens.size() - 1)],
             std::string("a #") + (open.kind == Block::Kind::If ? "if" : open.kind == Block::Kind::While ? "while"
                                                                      : open.kind == Block::Kind::For ? "for"
                                                                                                      : "switch") +
                 " is not closed by an #end before here");
    }
    scopes_.resize(f.scopes);
    if (f.kind == Frame::Kind::Macro) --macro_depth_;
    if (f.kind == Frame::Kind::File) --includes_open_;
    frames_.pop_back();
}

void PovParser::leave_finished_macros() {
    while (frames_.size() > 1 && frames_.back().kind == Frame::Kind::Macro && frames_.back().pos >= frames_.back().end)
        pop_frame();
}

PovToken PovParser::next() {
    PovToken t = peek();
    ++frames_.back().pos;
    return t;
}

const PovToken& PovParser::peek_raw(std::size_t ahead) {
    const Frame& f = frames_.back();
    const std::vector<PovToken>& tokens = files_[f.file]->tokens;
    return tokens[std::min({f.pos + ahead, f.end, tokens.size() - 1})];
}

bool PovParser::accept_symbol(std::string_view symbol) {
    if (!peek().is_symbol(symbol)) return false;
    next();
    return true;
}

bool PovParser::accept_name(std::string_view name) {
    if (!peek().is_name(name)) return false;
    next();
    return true;
}

void PovParser::expect_symbol(std::string_view symbol, std::string_view context) {
    if (!accept_symbol(symbol)) fail_expected("'" + std::string(symbol) + "'" + (context.empty() ? "" : " " + std::string(context)));
}

PovToken PovParser::expect_name(std::string_view what) {
    if (peek().kind != PovTokenKind::Name) fail_expected(std::string(what));
    return next();
}

std::string PovParser::located(const PovToken& at) const { return format_location(files_[at.file]->name, at.where); }

void PovParser::fail(const PovToken& at, const std::string& message) const {
    throw SceneError(files_[at.file]->name, at.where, message);
}

void PovParser::fail_expected(const std::string& what) {
    const PovToken& t = peek();
    fail(t, "expected " + what + " but found " + describe(t));
}

void PovParser::report(std::string text, bool warning) {
    if (!captures_.empty()) {
        (warning ? captures_.back().first : captures_.back().second).push_back(std::move(text));
        return;
    }
    if (reported_.insert(text).second) (warning ? result_.scene.warnings : result_.notes).push_back(std::move(text));
}

void PovParser::warn(const PovToken& at, const std::string& message) { report(located(at) + ": " + message, true); }

void PovParser::note(const PovToken& at, const std::string& message) { report(located(at) + ": " + message, false); }

const PovValue* PovParser::use(const std::string& name) {
    const PovValue* v = lookup(name);
    if (v) {
        for (const std::string& w : v->deferred_warnings) report(w, true);
        for (const std::string& n : v->deferred_notes) report(n, false);
    }
    return v;
}

const PovValue* PovParser::lookup(const std::string& name) const {
    for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope)
        if (const auto found = scope->find(name); found != scope->end()) return &found->second;
    return nullptr;
}

void PovParser::assign(const std::string& name, PovValue value, bool local) {
    if (!local)  // #declare changes a local of that name if one is visible, else the global
        for (std::size_t i = scopes_.size(); i-- > 1;)
            if (const auto found = scopes_[i].find(name); found != scopes_[i].end()) {
                found->second = std::move(value);
                return;
            }
    scopes_[local ? scopes_.size() - 1 : 0][name] = std::move(value);
}

bool PovParser::condition() {
    // '(' expression ')', read so that nothing past the ')' is looked at:
    // a directive right after it must not be carried out before this one.
    expect_symbol("(", "before the condition");
    const PovToken at = peek();
    const PovValue v = expression();
    if (!v.is_number()) fail(at, "a condition must be a number (0 is false), not " + kind_name(v.kind));
    expect_symbol(")", "after the condition");
    return v.v[0] != 0.0;
}

PovToken PovParser::skip_to(std::initializer_list<std::string_view> stop_at) {
    Frame& f = frames_.back();
    const std::vector<PovToken>& tokens = files_[f.file]->tokens;
    int depth = 0;
    const std::size_t start = f.pos;
    while (f.pos < f.end && tokens[f.pos].kind != PovTokenKind::End) {
        const PovToken& t = tokens[f.pos++];
        if (t.kind != PovTokenKind::Directive) continue;
        if (opens_block(t)) {
            ++depth;
        } else if (t.text == "end") {
            if (depth == 0) return t;
            --depth;
        } else if (depth == 0 && std::find(stop_at.begin(), stop_at.end(), t.text) != stop_at.end()) {
            return t;
        }
    }
    fail(tokens[start > 0 ? start - 1 : 0], "this block is not closed by an #end");
}

void PovParser::directive(const PovToken& keyword) {
    const Nesting nesting(*this, Nesting::Kind::Directive);  // one met while a #declare looks ahead runs inside it
    const std::string& d = keyword.text;
    if (d == "declare" || d == "local") {
        declare(keyword, d == "local");
    } else if (d == "include") {
        include(keyword);
    } else if (d == "if" || d == "ifdef" || d == "ifndef") {
        conditional(keyword);
    } else if (d == "else" || d == "elseif" || d == "case" || d == "range" || d == "break") {
        // Met while reading a taken branch: the rest up to its #end is
        // skipped. In a #switch, a case runs on into the next one's body
        // until a #break, as in POV-Ray.
        if (blocks_.empty() || blocks_.back().frame != frames_.size() - 1) fail(keyword, "#" + d + " without an open block");
        if (blocks_.back().kind == Block::Kind::Switch && d != "break" && d != "elseif") {
            if (d != "else") {  // the case's own values are not looked at
                expect_symbol("(", "after #" + d);
                (void)number("the case's value");
                if (d == "range") {
                    accept_symbol(",");
                    (void)number("the range's end");
                }
                expect_symbol(")", "to close the case");
            }
            return;
        }
        if (d == "break")  // out of a loop too: first out of the #if blocks inside it
            while (blocks_.back().kind == Block::Kind::If) {
                skip_to({});
                blocks_.pop_back();
                if (blocks_.empty() || blocks_.back().frame != frames_.size() - 1) fail(keyword, "#break outside a loop or #switch");
            }
        else if (blocks_.back().kind != Block::Kind::If && blocks_.back().kind != Block::Kind::Switch)
            fail(keyword, "#" + d + " outside an #if or #switch");
        skip_to({});
        blocks_.pop_back();
    } else if (d == "while") {
        loop(keyword);
    } else if (d == "for") {
        for_loop(keyword);
    } else if (d == "switch") {
        switch_block(keyword);
    } else if (d == "end") {
        end_of_block(keyword);
    } else if (d == "macro") {
        define_macro(keyword);
    } else if (d == "undef") {
        const PovToken name = peek_raw(0);  // raw: a macro's name is not a call here
        if (name.kind != PovTokenKind::Name) fail_expected("a name after #undef");
        ++frames_.back().pos;
        bool found = false;
        for (auto scope = scopes_.rbegin(); scope != scopes_.rend() && !found; ++scope) found = scope->erase(name.text) > 0;
        if (!found) macros_.erase(name.text);
    } else if (d == "version") {
        (void)number("the version");
        accept_symbol(";");
    } else if (d == "default") {
        expect_symbol("{", "after #default");
        PovTexture t;
        while (!accept_symbol("}"))
            if (!texture_item(t)) fail_expected("a texture, pigment or finish in #default");
        default_finish_.merge(t.finish);
        if (t.color) default_color_ = t.color;
    } else if (d == "debug" || d == "warning") {
        (void)string_value("the message");
    } else if (d == "error") {
        fail(keyword, "#error: " + string_value("the message"));
    } else {
        fail(keyword, "#" + d + " is not supported (file input and output, arrays of directives, …)");
    }
}

void PovParser::declare(const PovToken& keyword, bool local) {
    if (peek_raw(0).is_name("deprecated")) {  // #declare deprecated [once] ["message"] Name = …
        ++frames_.back().pos;
        if (peek_raw(0).is_name("once")) ++frames_.back().pos;
        if (peek_raw(0).kind == PovTokenKind::String) ++frames_.back().pos;
    }
    const PovToken name = peek_raw(0);
    if (name.kind != PovTokenKind::Name) fail_expected("a name after #" + keyword.text);
    ++frames_.back().pos;
    if (peek().is_symbol("[")) fail(peek(), "arrays are not supported");
    expect_symbol("=", "after #" + keyword.text + " " + name.text);
    captures_.emplace_back();
    PovValue value = any_value();
    if (value.kind == PovValue::Kind::Function && value.function->name.empty()) {
        auto named = std::make_shared<PovFunction>(*value.function);
        named->name = name.text;
        value.function = std::move(named);
    }
    // The ';' read raw: peeking past it would carry out the next directive
    // (another #declare, say) before this one is assigned. A macro whose
    // body was the value has run out: its ';' is in the caller's text.
    leave_finished_macros();
    if (peek_raw(0).is_symbol(";")) ++frames_.back().pos;
    value.deferred_warnings = std::move(captures_.back().first);
    value.deferred_notes = std::move(captures_.back().second);
    captures_.pop_back();
    assign(name.text, std::move(value), local);
}

PovValue PovParser::any_value() {
    PovValue value;
    const PovToken& first = peek();
    if (starts_object(first)) {
        value.kind = PovValue::Kind::Object;
        value.object = object_statement();
    } else if (first.is_name("texture") || first.is_name("pigment") || first.is_name("finish") ||
               first.is_name("normal") || first.is_name("interior") || first.is_name("material")) {
        value.kind = PovValue::Kind::Texture;
        PovTexture t;
        texture_item(t);
        layers(t);
        value.texture = std::make_shared<const PovTexture>(std::move(t));
    } else if (first.is_name("function")) {
        const PovToken k = next();
        value.kind = PovValue::Kind::Function;
        value.function = function_definition(k);
    } else if (first.is_name("transform")) {
        const PovToken k = next();
        value.kind = PovValue::Kind::Transform;
        value.transform = transform_statement(k);
    } else if (first.is_name("camera") || first.is_name("light_source") || first.is_name("array")) {
        fail(first, "declaring a " + first.text + " is not supported");
    } else if (first.kind == PovTokenKind::Name && peek_raw(1).is_symbol("{") && !lookup(first.text)) {
        // color_map, normal_map, density, spline, …: kept by name only, an error where used.
        const PovToken k = next();
        next();
        (void)skip_rest(k);
        value.kind = PovValue::Kind::Other;
        value.text = k.text;
    } else {
        value = expression();
    }
    return value;
}

void PovParser::include(const PovToken& keyword) {
    const std::string written = string_value("the file to include");
    if (includes_open_ >= max_include_depth) fail(keyword, "includes nested more than 64 deep (an include cycle?)");
    // The including file's folder, the scene's, the extra ones, POV-Ray's: each once.
    std::vector<std::filesystem::path> places;
    const auto add = [&](const std::filesystem::path& dir) {
        if (std::find(places.begin(), places.end(), dir) == places.end()) places.push_back(dir);
    };
    add(files_[frames_.back().file]->dir);
    add(files_[0]->dir);
    for (const std::string& dir : include_dirs_) add(dir);
    for (const auto& dir : places) {
        const std::filesystem::path path = resolve_path(dir, written);
        if (!regular_file_exists(path)) continue;
        std::string text;
        try {
            text = read_text_file(path);
        } catch (const FileReadError& e) {
            fail(keyword, "cannot read the include file \"" + written + "\": " + e.what());
        }
        const std::size_t file = add_file(path.string(), path.parent_path(), std::move(text));
        frames_.push_back({Frame::Kind::File, file, 0, files_[file]->tokens.size() - 1, scopes_.size(), blocks_.size()});
        scopes_.emplace_back();  // the include's own #local names, gone at its end
        ++includes_open_;
        return;
    }
    std::string searched;
    for (const auto& dir : places) searched += (searched.empty() ? "" : ", ") + dir.string();
    fail(keyword, "cannot find the include file \"" + written + "\" (searched " + searched + ")");
}

void PovParser::conditional(const PovToken& keyword) {
    bool taken;
    if (keyword.text == "if") {
        taken = condition();
    } else {  // #ifdef (Name), #ifndef (Name): read raw, a macro's name is not called
        expect_symbol("(", "after #" + keyword.text);
        const PovToken name = peek_raw(0);
        if (name.kind != PovTokenKind::Name) fail_expected("a name");
        ++frames_.back().pos;
        expect_symbol(")", "after the name");
        const bool defined = lookup(name.text) != nullptr || macros_.contains(name.text);
        taken = keyword.text == "ifdef" ? defined : !defined;
    }
    while (!taken) {
        const PovToken stop = skip_to({"else", "elseif"});
        if (stop.text == "end") return;
        if (stop.text == "else") break;
        taken = condition();  // #elseif
    }
    blocks_.push_back({Block::Kind::If, frames_.size() - 1});
}

void PovParser::loop(const PovToken& keyword) {
    (void)keyword;
    const std::size_t restart = frames_.back().pos;
    if (condition()) blocks_.push_back({Block::Kind::While, frames_.size() - 1, restart});
    else skip_to({});
}

void PovParser::for_loop(const PovToken& keyword) {
    expect_symbol("(", "after #for");
    const PovToken name = peek_raw(0);
    if (name.kind != PovTokenKind::Name) fail_expected("the loop variable's name");
    ++frames_.back().pos;
    expect_symbol(",", "after the loop variable");
    const double first = number("the first value");
    expect_symbol(",", "after the first value");
    const double last = number("the last value");
    double step = 1.0;
    if (accept_symbol(",")) step = number("the step");
    expect_symbol(")", "to close #for");
    if (step == 0.0 || !std::isfinite(step)) fail(keyword, "the #for step must be a nonzero number");
    assign(name.text, PovValue::number(first), false);
    if (step > 0.0 ? first > last : first < last) {
        skip_to({});
        return;
    }
    Block b{Block::Kind::For, frames_.size() - 1, frames_.back().pos};
    b.variable = name.text;
    b.last = last;
    b.step = step;
    blocks_.push_back(std::move(b));
}

void PovParser::switch_block(const PovToken& keyword) {
    (void)keyword;
    expect_symbol("(", "after #switch");
    const double value = number("the #switch value");
    expect_symbol(")", "after the #switch value");
    Block b{Block::Kind::Switch, frames_.size() - 1};
    b.switch_value = value;
    for (;;) {  // to the first case that holds
        const PovToken stop = skip_to({"case", "range", "else"});
        if (stop.text == "end") return;
        if (stop.text == "else") break;
        expect_symbol("(", "after #" + stop.text);
        const double a = number("the case's value");
        double z = a;
        if (stop.text == "range") {
            expect_symbol(",", "between the range's ends");
            z = number("the range's end");
        }
        expect_symbol(")", "to close the case");
        if (stop.text == "case" ? value == a : (value >= a && value <= z)) break;
    }
    blocks_.push_back(std::move(b));
}

void PovParser::end_of_block(const PovToken& keyword) {
    if (blocks_.empty() || blocks_.back().frame != frames_.size() - 1) fail(keyword, "#end without an open block");
    Block& b = blocks_.back();
    if ((b.kind == Block::Kind::While || b.kind == Block::Kind::For) && ++loop_iterations_ > options_.max_loop_iterations)
        fail(keyword, "the scene's loops ran more than " + std::to_string(options_.max_loop_iterations) + " times");
    if (b.kind == Block::Kind::While) {
        frames_.back().pos = b.restart;
        if (!condition()) {
            blocks_.pop_back();
            skip_to({});
        }
        return;
    }
    if (b.kind == Block::Kind::For) {
        const PovValue* v = lookup(b.variable);
        const double value = (v && v->is_number() ? v->v[0] : b.last) + b.step;
        const std::string variable = b.variable;
        const bool again = b.step > 0.0 ? value <= b.last : value >= b.last;
        if (again) {
            frames_.back().pos = b.restart;
        } else {
            blocks_.pop_back();
        }
        assign(variable, PovValue::number(value), false);
        return;
    }
    blocks_.pop_back();
}

void PovParser::define_macro(const PovToken& keyword) {
    const PovToken name = peek_raw(0);
    if (name.kind != PovTokenKind::Name) fail_expected("the macro's name");
    ++frames_.back().pos;
    Macro m;
    expect_symbol("(", "after the macro's name");
    if (!accept_symbol(")")) {
        do {
            accept_name("optional");
            const PovToken p = peek_raw(0);
            if (p.kind != PovTokenKind::Name) fail_expected("a parameter name");
            ++frames_.back().pos;
            m.parameters.push_back(p.text);
        } while (accept_symbol(","));
        expect_symbol(")", "to close the parameters");
    }
    const Frame& f = frames_.back();
    m.file = f.file;
    m.begin = f.pos;
    (void)keyword;
    skip_to({});
    m.end = frames_.back().pos - 1;  // the #end
    macros_[name.text] = std::move(m);
}

void PovParser::call_macro(const PovToken& name, const Macro& macro) {
    if (macro_depth_ >= max_macro_depth) fail(name, "macros call each other more than 200 deep");
    // The arguments are read before the body runs, so a call in a call's
    // arguments recurses here without a macro depth: it counts as nesting.
    if (nesting_ >= max_nesting) fail(name, "macro calls nested in their arguments more than 200 deep");
    ++nesting_;
    const struct Unnest {
        int& nesting;
        ~Unnest() { --nesting; }
    } unnest{nesting_};
    std::unordered_map<std::string, PovValue> arguments;
    expect_symbol("(", "after the macro " + name.text);
    for (std::size_t i = 0; i < macro.parameters.size(); ++i) {
        if (i > 0) expect_symbol(",", "between the arguments of " + name.text);
        arguments[macro.parameters[i]] = any_value();
    }
    expect_symbol(")", "to close the arguments of " + name.text + " (it takes " +
                           std::to_string(macro.parameters.size()) + ")");
    const Macro copy = macro;  // the table may change while the body runs
    frames_.push_back({Frame::Kind::Macro, copy.file, copy.begin, copy.end, scopes_.size(), blocks_.size()});
    scopes_.push_back(std::move(arguments));
    ++macro_depth_;
}

}  // namespace zeroset::pov
