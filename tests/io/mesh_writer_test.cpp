// STL, OBJ and PLY: exact layouts (sizes, headers, counts, indices), files
// chosen by extension and written atomically, clear errors.
#include "zeroset/io/mesh_writer.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "support/temp_dir.hpp"

namespace zeroset {
namespace {

/// A tetrahedron, faces outward.
Mesh tetrahedron() {
    Mesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

template <class T>
T read_at(const std::vector<std::uint8_t>& bytes, std::size_t offset) {
    T value;
    std::memcpy(&value, bytes.data() + offset, sizeof value);
    return value;
}

TEST(MeshWriter, StlIsBinaryWithUnitNormals) {
    const std::vector<std::uint8_t> stl = encode_mesh(tetrahedron(), MeshFormat::Stl);
    ASSERT_EQ(stl.size(), 84u + 50u * 4u);
    EXPECT_NE(std::string(stl.begin(), stl.begin() + 5), "solid");  // would read as ASCII STL
    EXPECT_EQ(read_at<std::uint32_t>(stl, 80), 4u);
    // The first facet (0, 2, 1) lies in z = 0 facing −z.
    EXPECT_EQ(read_at<float>(stl, 84 + 8), -1.0f);
    EXPECT_EQ(read_at<float>(stl, 84 + 12 + 12 + 4), 1.0f);  // its second vertex, (0, 1, 0): y
}

TEST(MeshWriter, ObjAndPlyListTheSameMesh) {
    const std::vector<std::uint8_t> obj = encode_mesh(tetrahedron(), MeshFormat::Obj);
    const std::string text(obj.begin(), obj.end());
    EXPECT_NE(text.find("\nv 1 0 0\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\nf 1 3 2\n"), std::string::npos) << text;  // 1-based
    const std::vector<std::uint8_t> ply = encode_mesh(tetrahedron(), MeshFormat::Ply);
    const std::string header(ply.begin(), ply.begin() + static_cast<std::ptrdiff_t>(std::string(ply.begin(), ply.end()).find("end_header\n") + 11));
    EXPECT_NE(header.find("format binary_little_endian 1.0\n"), std::string::npos);
    EXPECT_NE(header.find("element vertex 4\n"), std::string::npos);
    EXPECT_NE(header.find("element face 4\n"), std::string::npos);
    EXPECT_EQ(ply.size(), header.size() + 4 * 12 + 4 * 13);
    EXPECT_EQ(read_at<std::int32_t>(ply, header.size() + 48 + 1 + 4), 2);  // face 0's second index
}

TEST(MeshWriter, ByExtensionAtomicallyWithClearErrors) {
    const test::TempDir dir;
    write_mesh(tetrahedron(), dir / "t.STL");
    EXPECT_EQ(std::filesystem::file_size(dir / "t.STL"), 284u);
    EXPECT_THROW(write_mesh(tetrahedron(), dir / "t.fbx"), MeshWriteError);
    EXPECT_THROW(write_mesh(tetrahedron(), dir / "missing" / "t.obj"), MeshWriteError);
    EXPECT_EQ(dir.entries().size(), 1u);
    EXPECT_EQ(mesh_format_problem("x"), "no file extension to choose the mesh format (use .stl, .obj or .ply)");
}

}  // namespace
}  // namespace zeroset
