// STL, OBJ and PLY encoders (mesh_writer.hpp), all little-endian where binary.
#include "zeroset/io/mesh_writer.hpp"

#include <array>
#include <bit>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "zeroset/io/atomic_file.hpp"
#include "zeroset/io/lowercase.hpp"

namespace zeroset {

namespace {

static_assert(std::endian::native == std::endian::little, "the binary encoders write the machine's little-endian bytes");

void put_bytes(std::vector<std::uint8_t>& out, const void* data, std::size_t size) {
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out.insert(out.end(), bytes, bytes + size);
}
template <class T>
void put(std::vector<std::uint8_t>& out, T value) {
    put_bytes(out, &value, sizeof value);
}
void put_text(std::vector<std::uint8_t>& out, const std::string& text) { put_bytes(out, text.data(), text.size()); }
void put_point(std::vector<std::uint8_t>& out, const Vec3d& p) {
    put(out, static_cast<float>(p.x));
    put(out, static_cast<float>(p.y));
    put(out, static_cast<float>(p.z));
}

std::vector<std::uint8_t> encode_stl(const Mesh& mesh) {
    std::vector<std::uint8_t> out;
    out.reserve(84 + 50 * mesh.triangles.size());
    std::array<char, 80> header{};  // free text, but not starting "solid" (that would read as ASCII STL)
    const char name[] = "zeroset mesh";
    std::memcpy(header.data(), name, sizeof name - 1);
    put_bytes(out, header.data(), header.size());
    put(out, static_cast<std::uint32_t>(mesh.triangles.size()));
    for (const auto& t : mesh.triangles) {
        const Vec3d& a = mesh.vertices[t[0]];
        const Vec3d& b = mesh.vertices[t[1]];
        const Vec3d& c = mesh.vertices[t[2]];
        const Vec3d n = cross(b - a, c - a);
        const double len = length(n);
        put_point(out, len > 0.0 ? n / len : Vec3d{});
        put_point(out, a);
        put_point(out, b);
        put_point(out, c);
        put(out, std::uint16_t{0});
    }
    return out;
}

std::vector<std::uint8_t> encode_obj(const Mesh& mesh) {
    std::vector<std::uint8_t> out;
    put_text(out, "# zeroset mesh: " + std::to_string(mesh.vertices.size()) + " vertices, " +
                      std::to_string(mesh.triangles.size()) + " triangles\n");
    char line[128];
    for (const Vec3d& v : mesh.vertices) {
        const int n = std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", v.x, v.y, v.z);
        put_bytes(out, line, static_cast<std::size_t>(n));
    }
    for (const auto& t : mesh.triangles) {
        const int n = std::snprintf(line, sizeof line, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
        put_bytes(out, line, static_cast<std::size_t>(n));
    }
    return out;
}

std::vector<std::uint8_t> encode_ply(const Mesh& mesh) {
    std::vector<std::uint8_t> out;
    put_text(out, "ply\nformat binary_little_endian 1.0\ncomment zeroset mesh\nelement vertex " +
                      std::to_string(mesh.vertices.size()) +
                      "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                      std::to_string(mesh.triangles.size()) + "\nproperty list uchar int vertex_indices\nend_header\n");
    for (const Vec3d& v : mesh.vertices) put_point(out, v);
    for (const auto& t : mesh.triangles) {
        put(out, std::uint8_t{3});
        for (const std::uint32_t index : t) put(out, static_cast<std::int32_t>(index));
    }
    return out;
}

}  // namespace

std::optional<MeshFormat> mesh_format_for(const std::filesystem::path& path) {
    const std::string extension = lowercase_ascii(path.extension().string());
    if (extension == ".stl") return MeshFormat::Stl;
    if (extension == ".obj") return MeshFormat::Obj;
    if (extension == ".ply") return MeshFormat::Ply;
    return std::nullopt;
}

std::optional<std::string> mesh_format_problem(const std::filesystem::path& path) {
    if (mesh_format_for(path)) return std::nullopt;
    const std::string extension = path.extension().string();
    if (extension.empty() || extension == ".") return "no file extension to choose the mesh format (use .stl, .obj or .ply)";
    return "unsupported mesh format '" + extension + "' (use .stl, .obj or .ply)";
}

std::vector<std::uint8_t> encode_mesh(const Mesh& mesh, MeshFormat format) {
    if (mesh.triangles.size() > std::numeric_limits<std::int32_t>::max())
        throw std::invalid_argument("the mesh has too many triangles for its formats");
    switch (format) {
        case MeshFormat::Stl: return encode_stl(mesh);
        case MeshFormat::Obj: return encode_obj(mesh);
        case MeshFormat::Ply: return encode_ply(mesh);
    }
    throw std::invalid_argument("unknown mesh format");
}

void write_mesh(const Mesh& mesh, const std::filesystem::path& path) {
    const auto format = mesh_format_for(path);
    if (!format) throw MeshWriteError(path, *mesh_format_problem(path));
    std::vector<std::uint8_t> bytes;
    try {
        bytes = encode_mesh(mesh, *format);
    } catch (const std::invalid_argument& e) {
        throw MeshWriteError(path, e.what());
    }
    try {
        write_file_atomically(path, bytes);
    } catch (const FileWriteError& e) {
        throw MeshWriteError(path, e.reason());
    }
}

}  // namespace zeroset
