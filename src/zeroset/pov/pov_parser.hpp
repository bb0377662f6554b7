// PovParser: reads POV-Ray's scene description language into a zeroset
// Scene (pov_import.hpp is its front door). Like POV-Ray's own parser it is
// one pass over a stream of tokens in which directives (#declare, #if,
// #while, #macro, #include, …) and macro calls are carried out as they are
// met, so the statement readers see only the tokens the directives leave.
//
// The parser's parts live in one file each: pov_stream.cpp (the token
// stream, directives, macros, symbols), pov_expressions.cpp (numbers,
// vectors, colours, strings), pov_functions.cpp (function { … } as
// expressions of x, y, z), pov_textures.cpp (textures and materials),
// pov_objects.cpp (modifiers, CSG and transforms), pov_solids.cpp and
// pov_primitives.cpp (the objects themselves) and pov_scene.cpp (camera,
// lights, global settings and the top level).
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "zeroset/expr/expr.hpp"
#include "zeroset/pov/pov_import.hpp"
#include "zeroset/pov/pov_lexer.hpp"
#include "zeroset/pov/pov_values.hpp"

namespace zeroset::pov {

class PovParser {
public:
    explicit PovParser(const PovOptions& options);
    /// Reads a whole scene from `text`, the content of `file_name`.
    PovImport run(std::string text, const std::string& file_name, const std::filesystem::path& base_dir);

private:
    // ---- pov_stream.cpp: tokens, directives, macros, symbols ----
    struct SourceFile {
        std::string name;  // as messages show it
        std::filesystem::path dir;
        std::string text;
        std::vector<PovToken> tokens;
    };
    /// Where tokens are read from: a file (the scene or an include), a
    /// macro's body or a function's body, [pos, end).
    struct Frame {
        enum class Kind { File, Macro, Function };
        Kind kind;
        std::size_t file;
        std::size_t pos;
        std::size_t end;
        std::size_t scopes;  // the symbol scopes open when it started
        std::size_t blocks;  // the open #if/#while/… when it started
    };
    /// An open #if, #while, #for or #switch.
    struct Block {
        enum class Kind { If, While, For, Switch };
        Block(Kind k, std::size_t f, std::size_t r = 0) : kind(k), frame(f), restart(r) {}
        Kind kind;
        std::size_t frame;        // the frame it was opened in
        std::size_t restart = 0;  // #while: the condition's first token; #for: the body's
        std::string variable;     // #for
        double last = 0.0, step = 1.0;
        double switch_value = 0.0;
    };
    struct Macro {
        std::vector<std::string> parameters;
        std::size_t file, begin, end;  // the body's tokens
    };

    std::size_t add_file(std::string name, std::filesystem::path dir, std::string text);
    /// Ends the current frame (its #if blocks must be closed).
    void pop_frame();
    /// Ends the macro frames whose bodies have been read to their end.
    void leave_finished_macros();
    /// What a #declare or a macro's argument may be: an object, texture,
    /// function, transform, a block zeroset does not read, or an expression.
    PovValue any_value();
    /// The next token after carrying out any directives and macro calls before it.
    const PovToken& peek();
    PovToken next();
    /// The token `ahead` places on in the current frame, raw: no directive
    /// or macro call is carried out (for the names #declare, #ifdef, #for
    /// and #macro take, and for telling `Name (` calls apart).
    const PovToken& peek_raw(std::size_t ahead);
    bool accept_symbol(std::string_view symbol);
    bool accept_name(std::string_view name);
    void expect_symbol(std::string_view symbol, std::string_view context);
    PovToken expect_name(std::string_view what);
    [[noreturn]] void fail(const PovToken& at, const std::string& message) const;
    [[noreturn]] void fail_expected(const std::string& what);
    /// "file:line:column" of a token of the current frame's file.
    [[nodiscard]] std::string located(const PovToken& at) const;
    /// Records a warning once ("… is not supported; rendered as …").
    void warn(const PovToken& at, const std::string& message);
    void note(const PovToken& at, const std::string& message);

    void directive(const PovToken& keyword);
    void declare(const PovToken& keyword, bool local);
    void include(const PovToken& keyword);
    void conditional(const PovToken& keyword);
    void loop(const PovToken& keyword);
    void for_loop(const PovToken& keyword);
    void switch_block(const PovToken& keyword);
    void end_of_block(const PovToken& keyword);
    void define_macro(const PovToken& keyword);
    void call_macro(const PovToken& name, const Macro& macro);
    /// Skips tokens of the current frame up to the #else, #elseif, #case,
    /// #range, #break (as `stop_at` allows) or #end that closes the current
    /// level, and returns that directive (consumed).
    PovToken skip_to(std::initializer_list<std::string_view> stop_at);
    /// The number in parentheses after #if, #while, …
    bool condition();

    const PovValue* lookup(const std::string& name) const;
    /// lookup, for a value about to be used: reports its deferred warnings.
    const PovValue* use(const std::string& name);
    /// Gives a warning or note now, or keeps it for the declaration being read.
    void report(std::string text, bool warning);
    /// The warnings and notes of the declarations being read, innermost last.
    std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> captures_;
    void assign(const std::string& name, PovValue value, bool local);

    // ---- pov_expressions.cpp: numbers, vectors, colours, strings ----
    /// An expression: a number, vector, colour or string — or an identifier
    /// naming an object, texture, transform or function.
    PovValue expression();
    PovValue conditional_expression(bool in_vector);
    PovValue logical_or(bool in_vector);
    PovValue logical_and(bool in_vector);
    PovValue comparison(bool in_vector);
    PovValue additive(bool in_vector);
    PovValue multiplicative(bool in_vector);
    PovValue unary(bool in_vector);
    PovValue postfix(bool in_vector);
    PovValue primary(bool in_vector);
    PovValue call_builtin(const PovToken& name);
    /// `rgb …`, `color red … green …`, … after their first keyword.
    PovValue color_value(const PovToken& keyword);
    double number(std::string_view what);
    Vec3d vector3(std::string_view what);
    /// A colour: rgb, filter, transmit.
    std::array<double, 5> color(std::string_view what);
    std::string string_value(std::string_view what);
    /// The numeric value as a vector of `size` components (numbers promoted).
    PovValue promoted(const PovValue& value, int size, const PovToken& at) const;
    PovValue arithmetic(const PovValue& a, const PovValue& b, char op, const PovToken& at) const;
    [[nodiscard]] bool starts_color(const PovToken& t) const;
    /// Whether the '<' coming next opens a vector (with a comma and a '>'
    /// before anything closes) rather than comparing.
    bool opens_vector();

    // ---- pov_functions.cpp: function { … } as expressions ----
    /// `function [(params)] { body }` after the keyword.
    std::shared_ptr<const PovFunction> function_definition(const PovToken& keyword);
    /// A function's body read where it is defined, its parameters as x, y, z;
    /// nothing when it cannot be read there (the state is left as it was).
    std::optional<Expr> read_body(const PovFunction& function);
    /// The function applied to arguments.
    Expr apply(const PovFunction& function, const std::vector<Expr>& arguments, const PovToken& at);
    /// A function body's expression, with names bound to expressions.
    Expr function_expression();
    Expr function_or(), function_and(), function_comparison(), function_additive(), function_multiplicative(),
        function_unary(), function_primary();
    std::vector<Expr> function_arguments();
    /// POV-Ray's internal function `name` (functions.inc) at the arguments.
    Expr internal_function(const PovFunction& function, const std::vector<Expr>& arguments, const PovToken& at);
    std::vector<std::map<std::string, Expr>> function_scopes_;

    // ---- pov_textures.cpp: textures and materials ----
    PovTexture texture_block(const PovToken& keyword);
    void pigment_block(const PovToken& keyword, PovTexture& texture);
    void finish_block(const PovToken& keyword, PovFinish& finish);
    /// Skips a block it does not read, noting it as `what` in the texture (or
    /// as a note, without one).
    void skip_block(const PovToken& keyword, const std::string& what, PovTexture* texture);
    /// Reads the rest of the block `opened` up to its closing '}'
    /// (consumed), keeping the first colour written in it.
    std::optional<std::array<double, 5>> skip_rest(const PovToken& opened);
    /// Notes in the texture that `what` is left out, drawn in its first
    /// colour when it has one and the texture has none yet.
    void left_out(PovTexture& texture, const PovToken& at, const std::string& what,
                  const std::optional<std::array<double, 5>>& first_color);
    /// Reads a texture-like statement (texture, pigment, finish, normal,
    /// interior, material) into `texture`; false when the next token is none.
    bool texture_item(PovTexture& texture);
    /// Layers after a texture (more `texture { … }`s): read, and noted in
    /// it as left out.
    void layers(PovTexture& texture);
    /// The zeroset material of a texture, over the default finish; reports
    /// what the texture could not keep.
    Material material_of(const PovTexture& texture, const PovToken& at);
    PovFinish default_finish_;
    std::optional<std::array<double, 5>> default_color_;

    // ---- pov_objects.cpp, pov_solids.cpp, pov_primitives.cpp: objects, CSG, transforms ----
    struct ObjectBuilder;
    [[nodiscard]] bool starts_object(const PovToken& t) const;
    std::shared_ptr<const PovObject> object_statement();
    std::shared_ptr<PovObject> sphere(const PovToken& keyword, ObjectBuilder& b);
    std::shared_ptr<PovObject> box(const PovToken& keyword, ObjectBuilder& b);
    std::shared_ptr<PovObject> plane(const PovToken& keyword, ObjectBuilder& b);
    std::shared_ptr<PovObject> cylinder_or_cone(const PovToken& keyword, ObjectBuilder& b);
    std::shared_ptr<PovObject> torus(const PovToken& keyword, ObjectBuilder& b);
    std::shared_ptr<PovObject> polynomial(const PovToken& keyword, ObjectBuilder& b);
    std::shared_ptr<PovObject> blob(const PovToken& keyword, ObjectBuilder& b);
    std::shared_ptr<PovObject> isosurface(const PovToken& keyword, ObjectBuilder& b);
    std::shared_ptr<PovObject> sphere_sweep(const PovToken& keyword, ObjectBuilder& b);
    std::shared_ptr<PovObject> csg(const PovToken& keyword, ObjectBuilder& b);
    std::shared_ptr<PovObject> object_reference(const PovToken& keyword, ObjectBuilder& b);
    /// Reads the modifiers common to all objects (transforms, textures,
    /// inverse, bounded_by, …) up to the closing '}'; `extra` reads the
    /// object's own ones (open, sturm, threshold, …) and says whether it did.
    void object_modifiers(ObjectBuilder& b, const std::function<bool(const PovToken&)>& extra = {});
    /// A transform statement (translate, rotate, scale, matrix, transform)
    /// after its keyword, as the matrix it multiplies by.
    Mat4 transform_statement(const PovToken& keyword);
    [[nodiscard]] bool is_transform(const PovToken& t) const;
    /// Whether an optional on/off (a number, on, off, true, …) comes next.
    bool starts_optional_switch();
    /// What a clip_region stands for: a clip, a gate (bounded_by on a
    /// sheet), or only bounds for a clip written otherwise.
    enum class RegionUse { Clip, Gate, Bounds };
    /// The solid of a clipping sphere or box, in the space `to_local` maps
    /// its parent's into: exact for a sphere moved, turned and scaled evenly
    /// and a box moved and scaled; else the box around it — with a warning
    /// for a clip or a gate, which it then only approximates.
    std::optional<Bounds> clip_region(const PovObject& clip, const Mat4& to_local, const PovToken& at,
                                      RegionUse use = RegionUse::Clip);
    /// The solid of a plain object (f ≤ 0 within bounds that cut it) as an
    /// expression of the space `to_local` maps its parent's into; nothing
    /// for CSG, blobs and open objects.
    std::optional<Expr> solid_expression(const PovObject& clip, const Mat4& to_local);
    /// Makes `surface`, a plain object, open and clipped by the objects
    /// (each with the map from its parent's space into surface's parent's);
    /// false, leaving it as it was, when it or a clip is not plain.
    bool clip_open(SceneNode& surface, const std::vector<std::pair<const PovObject*, Mat4>>& clips, const PovToken& at);
    /// The node, its transform, texture and flags as the builder has them.
    std::shared_ptr<PovObject> finish_object(ObjectBuilder& b, std::shared_ptr<PovObject> object);

    // ---- pov_scene.cpp: camera, lights, settings ----
    void statement();
    void camera_block(const PovToken& keyword);
    Light light_block(const PovToken& keyword);
    void global_settings(const PovToken& keyword);
    void background(const PovToken& keyword);
    /// The scene's top-level objects get POV-Ray's default texture where they give none.
    void add_top_level(const std::shared_ptr<const PovObject>& object);

    /// Counts one level of nested expressions or objects — or, on a count
    /// of their own, directives — while it lives; past max_nesting the
    /// scene is refused (the parser recurses).
    class Nesting {
    public:
        enum class Kind { ExpressionOrObject, Directive };
        explicit Nesting(PovParser& parser, Kind kind = Kind::ExpressionOrObject);
        ~Nesting() { --depth_; }
        Nesting(const Nesting&) = delete;
        Nesting& operator=(const Nesting&) = delete;

    private:
        PovParser& parser_;
        int& depth_;
    };
    static constexpr int max_nesting = 200;
    int nesting_ = 0;
    int directive_nesting_ = 0;

    PovOptions options_;
    std::vector<std::unique_ptr<SourceFile>> files_;
    std::vector<Frame> frames_;
    std::vector<Block> blocks_;
    std::vector<std::unordered_map<std::string, PovValue>> scopes_;  // [0]: the globals
    std::unordered_map<std::string, Macro> macros_;
    std::vector<std::string> include_dirs_;
    PovImport result_;
    std::set<std::string> reported_;  // warnings and notes given, to give each once
    bool camera_seen_ = false;
    bool gamma_given_ = false;
    int includes_open_ = 0;
    int macro_depth_ = 0;
    std::uint64_t loop_iterations_ = 0;
    int object_count_ = 0;
};

}  // namespace zeroset::pov
