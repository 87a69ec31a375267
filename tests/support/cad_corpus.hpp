#pragma once
// A corpus of jewellery glTF files made as other tools make them, not as this project's writer
// does: each reproduces one way real CAD and web-viewer exports were refused or misdrawn
// (docs/gltf.md, "Files from other tools"). They are written byte by byte (glb_writer.hpp) with
// the habits of those tools: every triangle its own three corners with a flat normal (a CAD
// mesh split at its creases), facets fanned from a corner, metres, a node tree, materials named
// by the designer. The geometry is the project's own cuts and solids, so what each file holds
// is known: the tests check what the reader makes of it against that.

#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/cuts.hpp"
#include "glb_writer.hpp"
#include "piece/metal_mesh.hpp"

namespace gem::test_support::cad {

using nlohmann::json;

struct CorpusFile {
    std::string name;  // the file's name, e.g. "uncut-seat.glb"
    std::string what;  // the class of fault it reproduces
    std::filesystem::path path;
    int stones = 0;  // how many stones the file holds
};

inline Stone round_brilliant(double width_mm) {
    CutParams p = default_cut_params(CutShape::round_brilliant);
    p.width_mm = width_mm;
    return make_cut(p, find_material("diamond").value()).value();
}

inline Stone prism(double side_mm, double length_mm) {
    // A triangular prism along z: three side faces and two ends, as a glass sample scene has.
    Stone s;
    const double h = side_mm * std::sqrt(3.0) / 2.0;
    const glm::dvec3 tri[3] = {
        {-side_mm / 2, -h / 3, 0}, {side_mm / 2, -h / 3, 0}, {0, 2 * h / 3, 0}};
    for (int end = 0; end < 2; ++end) {
        for (const glm::dvec3& t : tri) {
            s.vertices.push_back(t + glm::dvec3(0, 0, end ? length_mm / 2 : -length_mm / 2));
        }
    }
    const std::vector<std::array<std::uint32_t, 3>> faces = {
        {0, 2, 1}, {3, 4, 5}, {0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {2, 0, 3}, {2, 3, 5}};
    for (const auto& f : faces) s.triangles.push_back({f, 0});
    return s;
}

// Triangles as an exporter writes them: every triangle its own corners and flat normal, in the
// file's units (`unit` millimetres each; glTF's metres are 1000).
struct Soup {
    std::vector<glm::dvec3> positions, normals;
    std::vector<std::uint32_t> indices;

    void add(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double unit) {
        const glm::dvec3 g = glm::cross(b - a, c - a);
        const double len = glm::length(g);
        const glm::dvec3 n = len > 0.0 ? g / len : glm::dvec3(0, 1, 0);
        for (const glm::dvec3& p : {a, b, c}) {
            indices.push_back(static_cast<std::uint32_t>(positions.size()));
            positions.push_back(p / unit);
            normals.push_back(n);
        }
    }
};

// A stone's facets fanned from their first corner, as CAD triangulates a planar face; `keep`
// says which facets are written (all when empty), `to` moves the corners (mm).
inline Soup stone_soup(const Stone& s, double unit = 1000.0,
                       const std::function<bool(std::size_t)>& keep = {},
                       const std::function<glm::dvec3(glm::dvec3)>& to = {}) {
    Soup soup;
    const auto at = [&](std::uint32_t v) { return to ? to(s.vertices[v]) : s.vertices[v]; };
    if (s.facets.empty()) {  // a stone given by triangles (the prism)
        for (const MeshTriangle& t : s.triangles)
            soup.add(at(t.v[0]), at(t.v[1]), at(t.v[2]), unit);
        return soup;
    }
    for (std::size_t f = 0; f < s.facets.size(); ++f) {
        if (keep && !keep(f)) continue;
        const auto& loop = s.facets[f].loop;
        for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
            soup.add(at(loop[0]), at(loop[i]), at(loop[i + 1]), unit);
        }
    }
    return soup;
}

// A metal mesh as an exporter writes a smooth part: shared corners with their normals.
inline Soup metal_soup(const MetalMesh& m, double unit = 1000.0) {
    Soup soup;
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        soup.positions.push_back(glm::dvec3(m.positions[i]) / unit);
        soup.normals.push_back(glm::dvec3(m.normals[i]));
    }
    soup.indices = m.indices;
    return soup;
}

// A ring's shank: a torus about the finger (x), its top at y = radius + 1 mm.
inline MetalMesh shank(double radius_mm = 9.0, int segments = 96, int profile = 24) {
    MetalMesh m;
    MeshBuilder(m).torus({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, radius_mm, 1.0, 1.2, segments, profile);
    return m;
}

inline json primitive(Glb& glb, const Soup& soup, int material, int mode = 4) {
    json p = {{"attributes", {{"POSITION", glb.vec3s(soup.positions)}}},
              {"indices", glb.indices(soup.indices)}};
    if (!soup.normals.empty()) p["attributes"]["NORMAL"] = glb.vec3s(soup.normals);
    if (material >= 0) p["material"] = material;
    if (mode != 4) p["mode"] = mode;
    return p;
}

inline int gold(Glb& glb, const std::string& name = "Gold 18K", json extensions = nullptr) {
    json m = {{"name", name},
              {"pbrMetallicRoughness",
               {{"baseColorFactor", {1.0, 0.766, 0.336, 1.0}},
                {"metallicFactor", 1.0},
                {"roughnessFactor", 0.25}}}};
    if (!extensions.is_null()) m["extensions"] = std::move(extensions);
    return glb.material(std::move(m));
}

inline int transmissive(Glb& glb, const std::string& name) {
    return glb.material(
        {{"name", name},
         {"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.0}}},
         {"extensions",
          {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
           {"KHR_materials_ior", {{"ior", 2.42}}}}}});
}

// The height of the stone's culet below its girdle (mm, positive).
inline double pavilion_depth(const Stone& s) {
    double y = 0.0;
    for (const glm::dvec3& v : s.vertices) y = std::min(y, v.y);
    return -y;
}

// A solitaire: a 6.5 mm brilliant on the shank, its culet `sunk_mm` into the metal (CAD leaves
// seats uncut), in a node tree as Blender writes one.
inline void solitaire(Glb& glb, double sunk_mm, double unit = 1000.0,
                      const std::function<glm::dvec3(glm::dvec3)>& frame = {},
                      MetalMesh metal = shank(), int metal_material = -1) {
    const Stone stone = round_brilliant(6.5);
    const double lift = 10.0 + pavilion_depth(stone) - sunk_mm;
    const auto placed = [&](glm::dvec3 p) {
        p += glm::dvec3(0, lift, 0);
        return frame ? frame(p) : p;
    };
    if (frame) {
        for (auto& p : metal.positions) p = glm::vec3(frame(glm::dvec3(p)));
        for (auto& n : metal.normals) n = glm::vec3(frame(glm::dvec3(n)) - frame(glm::dvec3(0.0)));
    }
    const int diamond = transmissive(glb, "Diamond BIG");
    if (metal_material < 0) metal_material = gold(glb);
    const int gem = glb.mesh_of(
        "Brilliant", json::array({primitive(glb, stone_soup(stone, unit, {}, placed), diamond)}));
    const int band =
        glb.mesh_of("Ring", json::array({primitive(glb, metal_soup(metal, unit), metal_material)}));
    const int a = glb.child({{"name", "Diamond BIG"}, {"mesh", gem}});
    const int b = glb.child({{"name", "Shank"}, {"mesh", band}});
    glb.node({{"name", "Solitaire"}, {"children", {a, b}}});
}

// Every file of the corpus, written into `dir`.
inline std::vector<CorpusFile> write_corpus(const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    fs::create_directories(dir);
    std::vector<CorpusFile> out;
    const auto save = [&](Glb& glb, const std::string& name, const std::string& what, int stones) {
        glb.write(dir / name);
        out.push_back({name, what, dir / name, stones});
    };
    {  // A loose stone: no metal at all.
        Glb glb;
        const Stone stone = round_brilliant(6.5);
        const int m = transmissive(glb, "Diamond");
        const int mesh =
            glb.mesh_of("Round 6.5", json::array({primitive(glb, stone_soup(stone), m)}));
        glb.node({{"name", "Round 6.5"}, {"mesh", mesh}});
        save(glb, "loose-stone.glb", "no metal (a loose stone)", 1);
    }
    {  // A sample scene of dispersive prisms in a 5 × 5 grid before a backdrop, no metal.
        Glb glb;
        const Stone p = prism(4.0, 8.0);
        for (int i = 0; i < 25; ++i) {
            const double dispersion = 0.2 * (i % 5) + 0.1 * (i / 5);
            const int m = glb.material(
                {{"name", "Glass " + std::to_string(i)},
                 {"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.0}}},
                 {"extensions",
                  {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                   {"KHR_materials_ior", {{"ior", 1.5 + 0.05 * (i / 5)}}},
                   {"KHR_materials_volume", {{"thicknessFactor", 0.004}}},
                   {"KHR_materials_dispersion", {{"dispersion", dispersion}}}}}});
            const int mesh = glb.mesh_of("Prism", json::array({primitive(glb, stone_soup(p), m)}));
            glb.node({{"name", "Prism." + std::to_string(i)},
                      {"mesh", mesh},
                      {"translation", {0.008 * (i % 5 - 2), 0.006 * (i / 5), 0.0}}});
        }
        Soup backdrop;
        const double w = 60.0, z = -20.0;
        backdrop.add({-w, -w, z}, {w, -w, z}, {w, w, z}, 1000.0);
        backdrop.add({-w, -w, z}, {w, w, z}, {-w, w, z}, 1000.0);
        const int paper = glb.material({{"name", "Backdrop"},
                                        {"pbrMetallicRoughness",
                                         {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}},
                                          {"metallicFactor", 0.0},
                                          {"roughnessFactor", 0.9}}}});
        const int mesh = glb.mesh_of("Backdrop", json::array({primitive(glb, backdrop, paper)}));
        glb.node({{"name", "Backdrop"}, {"mesh", mesh}});
        save(glb, "prism-scene.glb", "no metal (a scene of dispersive prisms)", 25);
    }
    {  // Metal that runs into the stone: an uncut seat.
        Glb glb;
        solitaire(glb, 0.6);
        save(glb, "uncut-seat.glb", "metal runs into a stone", 1);
    }
    {  // Lines and points left beside the triangles.
        Glb glb;
        solitaire(glb, 0.0);
        Soup curve;
        for (int i = 0; i <= 32; ++i) {
            const double a = 2.0 * std::numbers::pi * i / 32.0;
            curve.positions.push_back(glm::dvec3(0, 11.0 * std::cos(a), 11.0 * std::sin(a)) /
                                      1000.0);
            curve.indices.push_back(static_cast<std::uint32_t>(i));
        }
        json& band = glb.doc()["meshes"][1]["primitives"];
        band.push_back(primitive(glb, curve, -1, 3));
        band.push_back(primitive(glb, curve, -1, 0));
        save(glb, "curves-and-points.glb", "primitives that are not triangles", 1);
    }
    {  // Triangles with no area: a T-junction on the table's edge, and repeated corners in the
       // metal.
        Glb glb;
        const Stone stone = round_brilliant(6.5);
        const double lift = 10.0 + pavilion_depth(stone);
        const auto placed = [&](glm::dvec3 p) { return p + glm::dvec3(0, lift, 0); };
        std::size_t table = 0;
        for (std::size_t f = 0; f < stone.facets.size(); ++f) {
            if (stone.facets[f].plane.n.y > stone.facets[table].plane.n.y) table = f;
        }
        Soup soup = stone_soup(
            stone, 1000.0, [&](std::size_t f) { return f != table; }, placed);
        // The table fanned with a corner m in the middle of its edge a → c: (x, a, m), (x, m, c)
        // and the sliver (a, c, m) that closes the T-junction against the star across it.
        const auto& loop = stone.facets[table].loop;
        const glm::dvec3 a = placed(stone.vertices[loop[0]]), c = placed(stone.vertices[loop[1]]);
        const glm::dvec3 m = 0.5 * (a + c);
        const glm::dvec3 x = placed(stone.vertices[loop[loop.size() / 2]]);
        soup.add(x, a, m, 1000.0);
        soup.add(x, m, c, 1000.0);
        soup.add(a, c, m, 1000.0);
        for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
            const std::size_t k = (loop.size() / 2 + i) % loop.size();
            if (k == 0) continue;  // the edge a → c, fanned above
            soup.add(x, placed(stone.vertices[loop[k]]),
                     placed(stone.vertices[loop[(k + 1) % loop.size()]]), 1000.0);
        }
        const int diamond = transmissive(glb, "Diamond");
        const int metal_material = gold(glb);
        Soup metal = metal_soup(shank());
        metal.indices.insert(metal.indices.end(), {0, 0, 1, 5, 5, 5});
        const int gem = glb.mesh_of("Round", json::array({primitive(glb, soup, diamond)}));
        const int band = glb.mesh_of("Ring", json::array({primitive(glb, metal, metal_material)}));
        glb.node({{"name", "Diamond"}, {"mesh", gem}});
        glb.node({{"name", "Shank"}, {"mesh", band}});
        save(glb, "zero-area.glb", "triangles with no area", 1);
    }
    {  // A stone with a whole facet missing: its table.
        Glb glb;
        const Stone stone = round_brilliant(6.5);
        const double lift = 10.0 + pavilion_depth(stone);
        std::size_t table = 0;
        for (std::size_t f = 0; f < stone.facets.size(); ++f) {
            if (stone.facets[f].plane.n.y > stone.facets[table].plane.n.y) table = f;
        }
        const Soup soup = stone_soup(
            stone, 1000.0, [&](std::size_t f) { return f != table; },
            [&](glm::dvec3 p) { return p + glm::dvec3(0, lift, 0); });
        const int diamond = transmissive(glb, "Diamond");
        const int gem = glb.mesh_of("Round", json::array({primitive(glb, soup, diamond)}));
        const int band =
            glb.mesh_of("Ring", json::array({primitive(glb, metal_soup(shank()), gold(glb))}));
        glb.node({{"name", "Centre stone"}, {"mesh", gem}});
        glb.node({{"name", "Shank"}, {"mesh", band}});
        save(glb, "open-stone.glb", "a stone with a facet missing", 1);
    }
    {  // A shank of over 100,000 triangles whose material carries KHR_materials_ior and a clear
       // coat, named as a designer's material library names it.
        Glb glb;
        const int coated = gold(glb, "Yellow 750 polished",
                                {{"KHR_materials_ior", {{"ior", 1.5}}},
                                 {"KHR_materials_clearcoat",
                                  {{"clearcoatFactor", 1.0}, {"clearcoatRoughnessFactor", 0.03}}}});
        solitaire(glb, 0.0, 1000.0, {}, shank(9.0, 1024, 64), coated);
        glb.doc()["meshes"][1]["name"] = "Object_7";
        glb.doc()["nodes"][1]["name"] = "Object_7";
        save(glb, "ior-clearcoat-shank.glb", "metal with KHR_materials_ior taken for a stone", 1);
    }
    {  // A web viewer's band: 52 stones merged into one mesh, marked only by a vendor's diamond
       // material.
        Glb glb;
        const Stone stone = round_brilliant(1.1);
        const double lift = 10.0 + pavilion_depth(stone) * 0.5;
        Soup merged;
        for (int i = 0; i < 52; ++i) {
            const double a = 2.0 * std::numbers::pi * i / 52.0;
            // Around the band's outside, each table facing out from the finger.
            const glm::dvec3 outward(0, std::cos(a), std::sin(a)), along(1, 0, 0);
            const glm::dvec3 side = glm::cross(outward, along);
            const Soup one = stone_soup(stone, 1000.0, {}, [&](glm::dvec3 p) {
                return p.x * along + p.y * outward + p.z * side + lift * outward;
            });
            for (std::uint32_t k : one.indices)
                merged.indices.push_back(k + static_cast<std::uint32_t>(merged.positions.size()));
            merged.positions.insert(merged.positions.end(), one.positions.begin(),
                                    one.positions.end());
            merged.normals.insert(merged.normals.end(), one.normals.begin(), one.normals.end());
        }
        const int webgi =
            glb.material({{"name", "Material_12"},
                          {"extensions",
                           {{"WEBGI_materials_diamond",
                             {{"isDiamond", true},
                              {"color", 16777215},
                              {"refractiveIndex", 2.6},
                              {"dispersion", 0.012},
                              {"boostFactors", {{"x", 0.892}, {"y", 0.892}, {"z", 0.986}}},
                              {"rayBounces", 5}}}}}});
        glb.doc()["extensionsUsed"] = {"WEBGI_materials_diamond"};
        const int gems = glb.mesh_of("Object_3", json::array({primitive(glb, merged, webgi)}));
        const int band = glb.mesh_of(
            "Object_5",
            json::array({primitive(glb, metal_soup(shank()), gold(glb, "Material_4"))}));
        glb.node({{"name", "Object_3"}, {"mesh", gems}});
        glb.node({{"name", "Object_5"}, {"mesh", band}});
        save(glb, "webgi-merged-band.glb", "a vendor's diamond material on 52 merged stones", 52);
    }
    {  // A solitaire written in millimetres with z up, as a CAD tool's plain export does.
        Glb glb;
        solitaire(glb, 0.0, 1.0, [](glm::dvec3 p) { return glm::dvec3(p.x, -p.z, p.y); });
        save(glb, "millimetres-z-up.glb", "CAD's millimetres and z up, unconverted", 1);
    }
    return out;
}

// Two large files, for load times and frame times (bench_gltf_corpus): a solitaire whose shank
// is a CAD mesh of 901,120 triangles, and a ring of 121 stones (a 6.5 mm centre, two rows of
// 60 melee of 1 mm around the shank, each a node placing one shared mesh, as rendering tools
// export them).
inline std::vector<CorpusFile> write_large(const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    fs::create_directories(dir);
    std::vector<CorpusFile> out;
    {
        Glb glb;
        solitaire(glb, 0.0, 1000.0, {}, shank(9.0, 1024, 440));
        glb.write(dir / "shank-900k.glb");
        out.push_back(
            {"shank-900k.glb", "a shank of 901,120 triangles", dir / "shank-900k.glb", 1});
    }
    {
        Glb glb;
        solitaire(glb, 0.0);
        const Stone melee = round_brilliant(1.0);
        const int m = transmissive(glb, "Diamond melee");
        const int mesh =
            glb.mesh_of("Melee 1.0", json::array({primitive(glb, stone_soup(melee), m)}));
        int placed = 0;
        for (int row = 0; row < 2; ++row) {
            for (int i = 0; i < 60; ++i) {
                const double a = 2.0 * std::numbers::pi * (i + 0.5 * row) / 60.0;
                const double r = 10.0 + pavilion_depth(melee) - 0.02;
                glb.node({{"name", "Melee " + std::to_string(++placed)},
                          {"mesh", mesh},
                          {"translation",
                           {(row ? 0.55 : -0.55) / 1000.0, r * std::cos(a) / 1000.0,
                            r * std::sin(a) / 1000.0}},
                          {"rotation", {std::sin(a / 2.0), 0.0, 0.0, std::cos(a / 2.0)}}});
            }
        }
        glb.write(dir / "ring-121-stones.glb");
        out.push_back({"ring-121-stones.glb", "121 stones, a mesh placed by 120 nodes",
                       dir / "ring-121-stones.glb", 121});
    }
    return out;
}

}  // namespace gem::test_support::cad
