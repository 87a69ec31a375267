#include "model_seeds.hpp"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "geometry/cuts.hpp"
#include "optics/material.hpp"

namespace gem::fuzz {

namespace fs = std::filesystem;

namespace {

void write_file(const fs::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

// A cut as CAD tools export it, each facet its own polygon: Rhino and Blender write a
// header comment, a material library, an object and a group, texture coordinates and normals
// with every corner (v/vt/vn), and n-gons left as they are.
std::string obj_as_cad_writes(const Stone& stone, bool relative_indices) {
    std::ostringstream out;
    out << "# Rhino\n\nmtllib gem.mtl\no " << stone.name << "\ng stone\nusemtl Diamond\n";
    for (const glm::dvec3& v : stone.vertices)
        out << "v " << v.x << " " << v.y << " " << v.z << "\n";
    out << "vt 0 0\n";
    for (const Facet& f : stone.facets) {
        out << "vn " << f.plane.n.x << " " << f.plane.n.y << " " << f.plane.n.z << "\n";
    }
    out << "s off\n";
    const long long vertices = static_cast<long long>(stone.vertices.size());
    const long long normals = static_cast<long long>(stone.facets.size());
    for (std::size_t i = 0; i < stone.facets.size(); ++i) {
        out << "f";
        for (const std::uint32_t corner : stone.facets[i].loop) {
            const long long v = relative_indices ? static_cast<long long>(corner) - vertices
                                                 : static_cast<long long>(corner) + 1;
            const long long n = relative_indices ? static_cast<long long>(i) - normals
                                                 : static_cast<long long>(i) + 1;
            out << " " << v << "/" << (relative_indices ? -1 : 1) << "/" << n;
        }
        out << "\n";
    }
    return out.str();
}

// ASCII STL as many CAD tools write it: CRLF lines, normals and vertices in e-notation,
// each facet fanned into triangles.
std::string ascii_stl(const Stone& stone) {
    std::ostringstream out;
    out.setf(std::ios::scientific);
    out << "solid " << stone.name << "\r\n";
    for (const Facet& f : stone.facets) {
        for (std::size_t k = 1; k + 1 < f.loop.size(); ++k) {
            out << "  facet normal " << f.plane.n.x << " " << f.plane.n.y << " " << f.plane.n.z
                << "\r\n    outer loop\r\n";
            for (const std::uint32_t c : {f.loop[0], f.loop[k], f.loop[k + 1]}) {
                const glm::dvec3& v = stone.vertices[c];
                out << "      vertex " << v.x << " " << v.y << " " << v.z << "\r\n";
            }
            out << "    endloop\r\n  endfacet\r\n";
        }
    }
    out << "endsolid " << stone.name << "\r\n";
    return out.str();
}

void put_u32(std::string& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}
void put_f32(std::string& out, double v) {
    put_u32(out, std::bit_cast<std::uint32_t>(float(v)));
}

// Binary STL whose 80-byte header starts with "solid", as SolidWorks writes it.
std::string binary_stl(const Stone& stone) {
    std::string out = "solid " + stone.name;
    out.resize(80, ' ');
    std::uint32_t count = 0;
    std::string body;
    for (const Facet& f : stone.facets) {
        for (std::size_t k = 1; k + 1 < f.loop.size(); ++k, ++count) {
            put_f32(body, f.plane.n.x);
            put_f32(body, f.plane.n.y);
            put_f32(body, f.plane.n.z);
            for (const std::uint32_t c : {f.loop[0], f.loop[k], f.loop[k + 1]}) {
                for (int a = 0; a < 3; ++a) put_f32(body, stone.vertices[c][a]);
            }
            body.append(2, '\0');
        }
    }
    put_u32(out, count);
    return out + body;
}

// 3D Studio's ASCII export (3ds Max "ASCII Scene Export" of old), triangles fanned.
std::string asc_3ds(const Stone& stone) {
    std::ostringstream out;
    std::uint32_t faces = 0;
    for (const Facet& f : stone.facets) faces += static_cast<std::uint32_t>(f.loop.size() - 2);
    out << "Ambient light color: Red=0.3 Green=0.3 Blue=0.3\r\n\r\nNamed object: \"Gem01\"\r\n"
        << "Tri-mesh, Vertices: " << stone.vertices.size() << "     Faces: " << faces
        << "\r\nVertex list:\r\n";
    for (std::size_t i = 0; i < stone.vertices.size(); ++i) {
        const glm::dvec3& v = stone.vertices[i];
        out << "Vertex " << i << ":  X:" << v.x << "     Y:" << v.y << "     Z:" << v.z << "\r\n";
    }
    out << "Face list:\r\n";
    std::uint32_t face = 0;
    for (const Facet& f : stone.facets) {
        for (std::size_t k = 1; k + 1 < f.loop.size(); ++k) {
            out << "Face " << face++ << ":    A:" << f.loop[0] << " B:" << f.loop[k]
                << " C:" << f.loop[k + 1] << " AB:1 BC:1 CA:1\r\nSmoothing:  1\r\n";
        }
    }
    return out.str();
}

}  // namespace

int write_model_seeds(const fs::path& dir) {
    fs::create_directories(dir);
    int written = 0;
    for (const CutShape shape : {CutShape::round_brilliant, CutShape::heart}) {
        CutParams params = default_cut_params(shape);
        params.faceted_girdle = shape == CutShape::round_brilliant;
        auto stone = make_cut(params, *find_material("diamond"));
        if (!stone) {
            std::fprintf(stderr, "gem_fuzz_seeds: %s\n", stone.error().c_str());
            return -1;
        }
        const std::string name = to_string(shape);
        write_file(dir / (name + ".obj"), obj_as_cad_writes(stone.value(), false));
        write_file(dir / (name + "-relative.obj"), obj_as_cad_writes(stone.value(), true));
        write_file(dir / (name + "-ascii.stl"), ascii_stl(stone.value()));
        write_file(dir / (name + "-binary.stl"), binary_stl(stone.value()));
        write_file(dir / (name + "-3ds.asc"), asc_3ds(stone.value()));
        written += 5;
    }
    return written;
}

}  // namespace gem::fuzz
