// Saving a Mesh by the file's extension — binary STL (3-D printing), OBJ
// (text, for every modeller), binary PLY — written atomically like images.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "zeroset/io/path_error.hpp"
#include "zeroset/mesh/mesh.hpp"

namespace zeroset {

class MeshWriteError : public PathError {
public:
    using PathError::PathError;
};

enum class MeshFormat { Stl, Obj, Ply };

/// By extension: .stl, .obj or .ply (any case).
std::optional<MeshFormat> mesh_format_for(const std::filesystem::path& path);

/// Why `path` cannot name a mesh file ("unsupported mesh format '.x' (use .stl, .obj or .ply)"), or nothing.
std::optional<std::string> mesh_format_problem(const std::filesystem::path& path);

/// The mesh's bytes: STL with a facet normal per triangle, float
/// coordinates; OBJ with 1-based faces and %.9g coordinates; PLY binary
/// little-endian with float vertices and int faces.
std::vector<std::uint8_t> encode_mesh(const Mesh& mesh, MeshFormat format);

/// Encodes and replaces `path` atomically. Throws MeshWriteError.
void write_mesh(const Mesh& mesh, const std::filesystem::path& path);

}  // namespace zeroset
