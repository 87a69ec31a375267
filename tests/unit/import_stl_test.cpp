// STL import, ASCII and binary: a tetrahedron with corners (0,0,0), (2,0,0), (0,2,0), (0,0,2),
// whose volume is 2·2·2/6 = 4/3 and whose slanted face is x + y + z = 2.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/validate.hpp"
#include "import/load_model.hpp"
#include "import_test_files.hpp"

namespace gem {
namespace {

using import_test::contains;

void put_u32(std::string& out, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xFF));
}
void put_f32(std::string& out, float v) {
    put_u32(out, std::bit_cast<std::uint32_t>(v));
}

// The binary STL layout written byte by byte: 80-byte header, little-endian triangle count,
// then per triangle a normal, three corners (float32) and a 2-byte attribute.
std::string binary_tetra(const std::string& header_start) {
    const float c[4][3] = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}};
    const int tris[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    std::string out = header_start;
    out.resize(80, ' ');
    put_u32(out, 4);
    for (const auto& t : tris) {
        for (int k = 0; k < 3; ++k) put_f32(out, 0.0f);  // normals are not trusted anyway
        for (int v : t) {
            for (int k = 0; k < 3; ++k) put_f32(out, c[v][k]);
        }
        out.push_back(0);
        out.push_back(0);
    }
    return out;
}

std::filesystem::path write_artifact(const std::string& name, const std::string& bytes) {
    const auto path = std::filesystem::path(GEM_ARTIFACT_DIR) / "import" / name;
    std::filesystem::create_directories(path.parent_path());
    std::FILE* f = std::fopen(path.c_str(), "wb");
    EXPECT_NE(f, nullptr);
    if (f) {
        std::fwrite(bytes.data(), 1, bytes.size(), f);
        std::fclose(f);
    }
    return path;
}

void expect_tetra(const Stone& s) {
    EXPECT_EQ(s.vertices.size(), 4u);
    ASSERT_EQ(s.facets.size(), 4u);
    EXPECT_TRUE(s.convex);
    const SolidReport r = check_solid(s);
    EXPECT_TRUE(r.valid()) << (r.problems.empty() ? "" : r.problems.front());
    EXPECT_NEAR(r.volume, 4.0 / 3.0, 1e-12);
    // Three right triangles of area 2 and an equilateral one with side 2√2: (√3/4)·8.
    EXPECT_NEAR(r.area, 6.0 + 2.0 * std::sqrt(3.0), 1e-12);
    int slanted = 0;
    for (const Facet& f : s.facets) {
        if (f.plane.n.x > 0.5) {
            ++slanted;
            EXPECT_NEAR(f.plane.d, 2.0 / std::sqrt(3.0), 1e-12);
        }
    }
    EXPECT_EQ(slanted, 1);
}

TEST(ImportStl, AsciiTetrahedron) {
    auto result = load_stl(std::filesystem::path(GEM_FIXTURES_DIR) / "models" / "tetra_ascii.stl");
    ASSERT_TRUE(result.ok()) << result.error();
    expect_tetra(result.value());
}

TEST(ImportStl, BinaryTetrahedron) {
    const std::string bytes = binary_tetra("binary tetrahedron");
    ASSERT_EQ(bytes.size(), 84u + 4u * 50u);
    auto result = load_stl(write_artifact("tetra_binary.stl", bytes));
    ASSERT_TRUE(result.ok()) << result.error();
    expect_tetra(result.value());
}

TEST(ImportStl, BinaryWhoseHeaderStartsWithSolidIsReadAsBinary) {
    auto result = load_stl(write_artifact("tetra_solid_header.stl", binary_tetra("solid tetra")));
    ASSERT_TRUE(result.ok()) << result.error();
    expect_tetra(result.value());
}

TEST(ImportStl, TruncatedBinaryIsAnError) {
    std::string bytes = binary_tetra("binary tetrahedron");
    bytes.resize(bytes.size() - 30);
    auto result = load_stl(write_artifact("tetra_truncated.stl", bytes));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(),
                         "tetra_truncated.stl: truncated binary STL: header says 4 "
                         "triangles (284 bytes) but the file has 254 bytes"))
        << result.error();
}

TEST(ImportStl, ShorterThanAHeaderIsAnError) {
    auto result = load_stl(write_artifact("tiny.stl", std::string(40, '\x01')));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(), "tiny.stl: truncated binary STL")) << result.error();
}

TEST(ImportStl, TruncatedAsciiNamesTheLastLine) {
    auto result = load_stl(std::filesystem::path(GEM_FIXTURES_DIR) / "models" / "bad" /
                           "truncated_ascii.stl");
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(), "truncated_ascii.stl:22: truncated ASCII STL"))
        << result.error();
}

TEST(ImportStl, AsciiMalformedNumberNamesLineAndToken) {
    auto result = load_stl(write_artifact("bad_number.stl",
                                          "solid x\n facet normal 0 0 1\n  outer loop\n"
                                          "   vertex 0 0 0\n   vertex 1 0,5 0\n"));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(
        contains(result.error(), "bad_number.stl:5: vertex coordinate '0,5' is not a number"))
        << result.error();
}

}  // namespace
}  // namespace gem
