#include "piece/gltf_piece_writer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "import/gltf_document.hpp"
#include "util/atomic_file.hpp"

namespace gem {

namespace {

constexpr double kMmToMetres = 1e-3;
// KHR_materials_dispersion's wavelengths (nm).
constexpr double kLineF = 486.1, kLineD = 587.6, kLineC = 656.3;

import::GltfMaterial stone_material(const Stone& stone){const Material& m = stone.material;
import::GltfMaterial out;
out.name = m.name;
out.base_colour = m.body_colour;
out.metallic = 0.0;
out.roughness = 0.0;
out.transmission = 1.0;
out.ior = m.index(kLineD);
const double vd = abbe_number(m);
if (std::isfinite(vd)) out.dispersion = 20.0 / vd;
double lo = HUGE_VAL, hi = -HUGE_VAL;
for (const glm::dvec3& v : stone.vertices) {
    lo = std::min(lo, v.y);
    hi = std::max(hi, v.y);
}
out.thickness_m = (hi - lo) * kMmToMetres;
// Beer–Lambert over a distance d leaves c = exp(−σ d): d is where the most absorbed
// channel keeps 1/e, so every channel's colour is well above the file's rounding.
const double strongest =
    std::max({m.absorption_per_mm.x, m.absorption_per_mm.y, m.absorption_per_mm.z});
if (strongest > 0.0) {
    const double d_mm = 1.0 / strongest;
    out.attenuation_distance_m = d_mm * kMmToMetres;
    out.attenuation_colour = glm::exp(-m.absorption_per_mm * d_mm);
}
return out;
}  // namespace

// The stone split at its facets: each facet's corners its own, with the facet's normal.
void stone_mesh(const Stone& stone, import::GltfPart& part) {
    part.positions.clear();
    part.normals.clear();
    part.triangles.clear();
    for (const MeshTriangle& t : stone.triangles) {
        const auto base = static_cast<std::uint32_t>(part.positions.size());
        for (std::uint32_t v : t.v) {
            part.positions.push_back(stone.vertices[v] * kMmToMetres);
            part.normals.push_back(stone.facets[t.facet].plane.n);
        }
        part.triangles.push_back({base, base + 1, base + 2});
    }
}

}  // namespace gem

double abbe_number(const Material& material) {
    const double spread = material.index(kLineF) - material.index(kLineC);
    if (!(spread > 0.0)) return std::numeric_limits<double>::infinity();
    return (material.index(kLineD) - 1.0) / spread;
}

Result<std::string> piece_glb(const Piece& piece) {
    import::GltfDocument doc;
    // The metal: material 0, mesh 0.
    import::GltfMaterial metal;
    metal.name = "metal";
    metal.base_colour = glm::dvec3(piece.metal.f0);
    metal.metallic = 1.0;
    metal.roughness = piece.metal.roughness;
    doc.materials.push_back(metal);
    if (!piece.metal.indices.empty()) {
        import::GltfPart part;
        part.node =
            "metal";  // no gem word: the piece's name may hold one (the reader goes by names)
        part.mesh = "metal";
        part.mesh_index = 0;
        part.material = 0;
        for (const glm::vec3& p : piece.metal.positions) {
            part.positions.push_back(glm::dvec3(p) * kMmToMetres);
        }
        part.normals.assign(piece.metal.normals.begin(), piece.metal.normals.end());
        for (std::size_t i = 0; i + 2 < piece.metal.indices.size(); i += 3) {
            part.triangles.push_back(
                {piece.metal.indices[i], piece.metal.indices[i + 1], piece.metal.indices[i + 2]});
        }
        doc.parts.push_back(std::move(part));
    }
    // Each kind: material 1 + k, mesh 1 + k; a node per placed stone.
    std::vector<import::GltfPart> kind_parts(piece.kinds.size());
    for (std::size_t k = 0; k < piece.kinds.size(); ++k) {
        doc.materials.push_back(stone_material(piece.kinds[k]));
        kind_parts[k].mesh = "gem " + std::to_string(k + 1) + " " + piece.kinds[k].name;
        kind_parts[k].mesh_index = static_cast<int>(k) + 1;
        kind_parts[k].material = static_cast<int>(k) + 1;
        stone_mesh(piece.kinds[k], kind_parts[k]);
    }
    // A kind's mesh data goes with its first stone; the others name the same mesh.
    std::vector<bool> written(piece.kinds.size(), false);
    for (const PieceStone& s : piece.stones) {
        import::GltfPart& kind = kind_parts[s.kind];
        import::GltfPart part;
        part.mesh_index = kind.mesh_index;
        part.material = kind.material;
        if (!written[s.kind]) {
            part.mesh = kind.mesh;
            part.positions = std::move(kind.positions);
            part.normals = std::move(kind.normals);
            part.triangles = std::move(kind.triangles);
            written[s.kind] = true;
        }
        part.node = s.role;
        glm::dmat4 to(s.placement.rotation);
        to[3] = glm::dvec4(s.placement.position * kMmToMetres, 1.0);
        part.to_scene = to;
        doc.parts.push_back(std::move(part));
    }
    return import::glb_bytes(doc, "gemkiosk gemtables piece");
}

Result<bool> write_piece_glb(const Piece& piece, const std::filesystem::path& path) {
    auto bytes = piece_glb(piece);
    if (!bytes) return Error{path.string() + ": " + bytes.error()};
    auto written = write_file_atomic(path, bytes.value().data(), bytes.value().size());
    if (!written) return Error{written.error()};
    return true;
}

}  // namespace gem
