#include "piece/gltf_piece.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

#include "geometry/mesh_repair.hpp"
#include "geometry/polyhedron.hpp"
#include "geometry/stone.hpp"
#include "import/gltf_document.hpp"
#include "import/import_text.hpp"
#include "piece/gltf_piece_frame.hpp"
#include "piece/gltf_piece_writer.hpp"
#include "piece/gltf_stone_evidence.hpp"
#include "piece/metal_simplify.hpp"
#include "piece/piece_check.hpp"

namespace gem {

namespace {

// A part with more triangles than this is not a stone: a cut has hundreds, and a scanned or
// subdivided mesh would take the facet recovery minutes. It is drawn as metal.
constexpr std::size_t kMaxStoneTriangles = 100000;

// The stone's material: a built-in one its names give, else diamond; then the file's gem
// extensions over it (Khronos's, else a vendor's).
Material stone_material(const import::GltfPart& part, const import::GltfMaterial* m,
                        double mm_per_unit, std::string& described) {
    Material material = *find_material("diamond");
    bool named = false;
    for (const std::string& name : {m ? m->name : std::string(), part.mesh, part.node}) {
        std::vector<std::string> candidates = words_of(name);
        candidates.insert(candidates.begin(), name);  // the whole name first: "cubic zirconia"
        for (const std::string& w : candidates) {
            if (w.empty()) continue;
            if (auto found = find_material(w)) {
                material = *found;
                named = true;
                break;
            }
        }
        if (named) break;
    }
    described = material.name + (named ? " (by name)" : " (the default)");
    if (m == nullptr) return material;
    const auto& vendor = m->vendor_gem;
    // The index and the fire, from the Khronos extensions or else the vendor's.
    std::optional<double> ior = m->ior;
    std::optional<double> abbe;
    std::string ior_from = "KHR_materials_ior", fire_from = "KHR_materials_dispersion";
    if (m->dispersion && *m->dispersion > 0.0) abbe = 20.0 / *m->dispersion;
    if (vendor && !ior && vendor->ior) {
        ior = vendor->ior;
        ior_from = vendor->extension;
    }
    if (vendor && !abbe && vendor->spread && *vendor->spread > 0.0) {
        // WEBGI's dispersion moves the index by ± that much from green to red and blue, so it
        // is about half n_F − n_C: its default 0.012 gives 0.024, against diamond's 0.025
        // (n_F 2.4354, n_C 2.4100). V_d = (n_d − 1) / (n_F − n_C).
        abbe = ((ior ? *ior : material.index(587.6)) - 1.0) / (2.0 * *vendor->spread);
        fire_from = vendor->extension;
    }
    // A built-in material named by the file, whose index and fire the file repeats (as this
    // project writes them, gltf_piece_writer.hpp, or rounded as designers type them: a
    // "Diamond" of 2.42 or 2.4), keeps its own dispersion curve and colour. Gems a name tells
    // apart differ by more: diamond 2.417, moissanite 2.65, cubic zirconia 2.15.
    constexpr double kTypedIndex = 0.02;
    const bool ior_agrees =
        !ior || std::abs(*ior - material.index(587.6)) < (named ? kTypedIndex : 1e-3);
    const double built_in_vd = abbe_number(material);
    const bool fire_agrees =
        !abbe || (std::isfinite(built_in_vd) && std::abs(*abbe / built_in_vd - 1.0) < 0.01);
    const bool as_built_in = named && ior_agrees && fire_agrees;
    if (as_built_in && (ior || abbe)) {
        described += ", its index and fire as the file gives them";
    }
    if (!as_built_in && m->transmission > 0.0) {
        // glTF tints what a transmissive material lets through by its base colour: the
        // thesis' stone colour.
        material.body_colour = glm::clamp(m->base_colour, 0.0, 1.0);
    }
    if (vendor && vendor->colour && glm::any(glm::lessThan(*vendor->colour, glm::dvec3(0.999)))) {
        material.body_colour = *vendor->colour;
        described += ", its colour from " + vendor->extension;
    }
    char text[200];
    if (!as_built_in && ior && std::abs(*ior - material.index()) > 1e-3) {
        // The file's index over the built-in one: no dispersion unless the file gives it.
        material.dispersion = Dispersion::constant_index(*ior);
        std::snprintf(text, sizeof text, ", n %.3f from %s", *ior, ior_from.c_str());
        described += text;
    }
    if (!as_built_in && abbe) {
        // KHR_materials_dispersion: dispersion = 20 / V_d, and n(λ) = A + B / λ² with
        // B = (n_d − 1) / (V_d (λ_F⁻² − λ_C⁻²)), A = n_d − B / λ_d² (the extension's
        // specification; λ_F 486.1, λ_d 587.6, λ_C 656.3 nm, here in µm).
        const double nd = ior ? *ior : material.index();
        const double vd = *abbe;
        const double f = 0.4861, d = 0.5876, c = 0.6563;
        const double b = (nd - 1.0) / (vd * (1.0 / (f * f) - 1.0 / (c * c)));
        material.dispersion.kind = Dispersion::Kind::cauchy;
        material.dispersion.coef = {nd - b / (d * d), b};
        std::snprintf(text, sizeof text, ", Abbe number %.1f from %s", vd, fire_from.c_str());
        described += text;
    }
    if (std::isfinite(m->attenuation_distance_m) && m->attenuation_distance_m > 0.0) {
        // Beer–Lambert: the colour c left after the distance d, so σ = −ln(c) / d (per mm).
        for (int i = 0; i < 3; ++i) {
            const double c = std::clamp(m->attenuation_colour[i], 1e-6, 1.0);
            material.absorption_per_mm[i] =
                -std::log(c) / (m->attenuation_distance_m * mm_per_unit);
        }
        described += ", absorption from KHR_materials_volume";
    }
    return material;
}

// A part's triangles welded by position (a CAD mesh splits its vertices at every crease) and
// grouped into connected pieces: stones merged into one mesh come apart.
std::vector<std::vector<std::array<std::uint32_t, 3>>> connected_pieces(
    const std::vector<glm::dvec3>& positions,
    const std::vector<std::array<std::uint32_t, 3>>& triangles, std::vector<std::uint32_t>& weld) {
    glm::dvec3 lo(HUGE_VAL), hi(-HUGE_VAL);
    for (const glm::dvec3& p : positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double cell = std::max(glm::length(hi - lo), 1e-30) * 1e-7;
    std::map<std::tuple<long long, long long, long long>, std::uint32_t> seen;
    weld.resize(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const glm::dvec3 q = glm::floor((positions[i] - lo) / cell + 0.5);
        const auto key = std::make_tuple(static_cast<long long>(q.x), static_cast<long long>(q.y),
                                         static_cast<long long>(q.z));
        weld[i] = seen.try_emplace(key, static_cast<std::uint32_t>(i)).first->second;
    }
    std::vector<std::uint32_t> parent(positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto root = [&](std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    for (const auto& t : triangles) {
        for (int c = 1; c < 3; ++c) parent[root(weld[t[c]])] = root(weld[t[0]]);
    }
    std::map<std::uint32_t, std::size_t> piece_of_root;
    std::vector<std::vector<std::array<std::uint32_t, 3>>> pieces;
    for (const auto& t : triangles) {
        const auto [it, fresh] = piece_of_root.try_emplace(root(weld[t[0]]), pieces.size());
        if (fresh) pieces.emplace_back();
        pieces[it->second].push_back(t);
    }
    return pieces;
}

// The coplanarity tolerance, relative to the stone's size, for its corners as the file stores
// them (stone_from_triangles grows each facet against the plane of what it has grown so far,
// which rounding barely tilts, so the tolerance follows the rounding itself):
// - float32, up to `far` from the file's origin: rounding of 2^-24 of the coordinate.
//   Measured (GltfPiece.FacetsSurvive...): a 1.5 mm brilliant stored in metres up to 30 mm
//   from the origin keeps its 89 facets from 1 times that rounding over far / size; 4 is used.
// - quantised (KHR_mesh_quantization, Draco): a grid of `step`. Measured on the halo written
//   here and re-packed by gltfpack at 14 bits (its default: one 1.5 µm grid over the 24.5 mm
//   ring), the 1.3 mm melee keeps its 89 facets at 3 and 5 steps (91 at 2; merged to 86 at 8,
//   44 at 16); 5 is used. Draco at 11 and 14 bits keeps them too (GltfPiece.DracoCompressed...).
// Real facets differ by a degree or more. Never below the default.
constexpr double kQuantisedSteps = 5.0;

double planar_tolerance(const std::vector<glm::dvec3>& stored, double step) {
    double far = 0.0;
    glm::dvec3 lo(HUGE_VAL), hi(-HUGE_VAL);
    for (const glm::dvec3& p : stored) {
        far = std::max(far, glm::length(p));
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double size = glm::length(hi - lo);
    if (!(size > 0.0)) return kPlanarRelative;
    constexpr double kFloatRounding = 1.0 / (1 << 24);
    return std::max(
        {kPlanarRelative, 4.0 * kFloatRounding * far / size, kQuantisedSteps * step / size});
}

// The piece's metal as the parts give it: every metal triangle placed in millimetres, and the
// area each material covers, so that the piece's one metal is the one most of it is made of.
struct MetalParts {
    std::map<int, double> area_by_material;  // material index (-1: the default) → mm²
    std::size_t triangles = 0;
    std::size_t zero_area = 0;
};

void add_metal(const import::GltfPart& part, const std::vector<std::array<std::uint32_t, 3>>& tris,
               double mm_per_unit, MetalMesh& metal, MetalParts& parts) {
    const glm::dmat4& to = part.to_scene;
    const bool mirrored = glm::determinant(glm::dmat3(to)) < 0.0;
    std::vector<glm::dvec3> placed(part.positions.size());
    for (std::size_t i = 0; i < placed.size(); ++i) {
        placed[i] = glm::dvec3(to * glm::dvec4(part.positions[i], 1.0)) * mm_per_unit;
    }
    // The file's normals, taken to the scene by the inverse transpose; without them, corners
    // share an area-weighted average of their faces' normals, per vertex as the file splits
    // them (a crease keeps its edge).
    std::vector<glm::dvec3> normal(placed.size(), glm::dvec3(0.0));
    const bool given = part.normals.size() == placed.size();
    if (given) {
        const glm::dmat3 to_normal = glm::transpose(glm::inverse(glm::dmat3(to)));
        for (std::size_t i = 0; i < placed.size(); ++i) normal[i] = to_normal * part.normals[i];
    }
    // Only the corners the triangles use are kept (a part split into stones and metal, or a
    // mesh whose unused vertices fill a large buffer, adds no more than it draws), in the
    // file's order (what this project writes reads back as it was).
    constexpr std::uint32_t kUnused = ~0u;
    std::vector<std::uint32_t> index(placed.size(), kUnused);
    std::vector<std::array<std::uint32_t, 3>> kept;
    kept.reserve(tris.size());
    double area = 0.0;
    for (auto t : tris) {
        if (mirrored) std::swap(t[1], t[2]);
        const glm::dvec3 g = glm::cross(placed[t[1]] - placed[t[0]], placed[t[2]] - placed[t[0]]);
        // A triangle with no area draws nothing and has no normal to give its corners.
        if (!(glm::length(g) > 1e-12)) {
            ++parts.zero_area;
            continue;
        }
        area += 0.5 * glm::length(g);
        for (std::uint32_t c : t) {
            if (!given) normal[c] += g;
            index[c] = 0;
        }
        kept.push_back(t);
    }
    for (std::size_t from = 0; from < index.size(); ++from) {
        if (index[from] == kUnused) continue;
        index[from] = static_cast<std::uint32_t>(metal.positions.size());
        metal.positions.emplace_back(placed[from]);
        const double len = glm::length(normal[from]);
        metal.normals.emplace_back(len > 0.0 ? glm::vec3(normal[from] / len) : glm::vec3(0, 1, 0));
    }
    for (const auto& t : kept) {
        for (std::uint32_t c : t) metal.indices.push_back(index[c]);
    }
    parts.triangles += kept.size();
    parts.area_by_material[part.material] += area;
}

// The metal's F0 and roughness from a glTF material: F0 mixed from the dielectric's to the base
// colour by the metalness. KHR_materials_specular scales and tints the dielectric's F0 (its
// specification: min(F0 · specularColor, 1) · specular); a clear coat is a second, dielectric
// layer whose 4 % reflection one GGX lobe cannot hold beside the metal's, so it is left out.
void set_metal_material(const import::GltfMaterial* m, MetalMesh& metal) {
    const glm::dvec3 base_colour = m ? m->base_colour : glm::dvec3(1.0);
    const double metallic = std::clamp(m ? m->metallic : 1.0, 0.0, 1.0);
    glm::dvec3 dielectric(0.04);
    if (m != nullptr) {
        const double n = m->ior.value_or(1.5);
        const double f = (n - 1.0) / (n + 1.0);
        dielectric =
            glm::min(glm::dvec3(f * f) * m->specular_colour, glm::dvec3(1.0)) * m->specular;
    }
    metal.f0 = glm::vec3(glm::mix(dielectric, glm::clamp(base_colour, 0.0, 1.0), metallic));
    metal.roughness = static_cast<float>(std::clamp(m ? m->roughness : 1.0, 0.0, 1.0));
}

// A stone from one connected piece of a part's triangles, repaired where CAD left it dirty:
// triangles with no area dropped (T-junctions split), triangles wound against their
// neighbours turned, and an open stone closed: by the planes of the facets it kept where they
// close it as it was (a convex stone that lost a few triangles), else by filling its holes (a
// whole facet lost, or a stone that is not convex). `repairs` says what was done.
// `tolerance` is the facets' (planar_tolerance); `sliver`, the height below which a triangle
// has no area: the float rounding alone, since a quantised melee's girdle triangles are
// thinner than its grid's facet tolerance and are real.
Result<Stone> repaired_stone(const std::vector<glm::dvec3>& corners,
                             std::vector<std::array<std::uint32_t, 3>> tris,
                             const std::string& name, double tolerance, double sliver,
                             std::string& repairs) {
    const auto said = [&](const std::string& what) { repairs += "; " + what; };
    if (const std::size_t n = drop_zero_area_triangles(corners, tris, sliver); n > 0) {
        said(std::to_string(n) + " triangle" + (n == 1 ? "" : "s") + " with no area dropped");
    }
    auto stone = stone_from_triangles(corners, tris, name, 1e-6, tolerance);
    if (!stone && stone.error().starts_with("mesh is not 2-manifold or not consistently wound")) {
        auto turned = orient_consistently(tris);
        if (!turned) return Error{stone.error() + ", and " + turned.error()};
        said(std::to_string(turned.value()) + " triangles turned to wind as their neighbours");
        stone = stone_from_triangles(corners, tris, name, 1e-6, tolerance);
    }
    if (!stone && stone.error().starts_with("mesh is open")) {
        const std::string open = stone.error().substr(stone.error().find(": ") + 2);
        auto by_planes = stone_closed_by_its_planes(corners, tris, name, tolerance);
        if (by_planes) {
            said("open (" + open + "): closed by the planes of its facets");
            return by_planes;
        }
        auto filled = fill_holes(corners, tris);
        if (!filled) return Error{stone.error() + ", and " + filled.error()};
        drop_zero_area_triangles(corners, tris, sliver);
        stone = stone_from_triangles(corners, tris, name, 1e-6, tolerance);
        if (!stone) return Error{"mesh is open (" + open + "), and once filled: " + stone.error()};
        said("open (" + open + "): " + std::to_string(filled.value()) + " hole" +
             (filled.value() == 1 ? "" : "s") + " filled");
    }
    return stone;
}

}  // namespace

Result<Piece> load_gltf_piece(const std::filesystem::path& path, std::vector<std::string>* log) {
    Result<std::string> bytes = import::read_whole_file(path);
    if (!bytes) return Error{bytes.error()};
    auto manifest = load_gltf_manifest(path);
    if (!manifest) return Error{manifest.error()};
    const GltfManifest* beside = manifest.value() ? &*manifest.value() : nullptr;
    return parse_gltf_piece(bytes.value(), path.string(), path.parent_path(), log, beside);
}

Result<Piece> parse_gltf_piece(std::string_view bytes, const std::string& name,
                               const std::filesystem::path& base, std::vector<std::string>* log,
                               const GltfManifest* manifest) {
    auto read = import::parse_gltf(bytes, name, base);
    if (!read) return Error{read.error()};
    const import::GltfDocument& doc = read.value();
    const std::string file = std::filesystem::path(name).filename().string();
    const auto warn = [&](const std::string& what) {
        if (log != nullptr) log->push_back(std::string(kWarningLine) + file + ": " + what);
    };
    for (const std::string& w : doc.warnings) warn(w);
    Piece piece;
    piece.name = std::filesystem::path(name).stem().string();
    std::string units;
    const double mm_per_unit = millimetres_per_unit(doc, units);
    if (!units.empty()) warn(units);
    MetalParts metal_parts;
    // Kinds made from a mesh's own frame, by (mesh, primitive, connected piece, scale).
    std::map<std::tuple<int, int, std::size_t, double>, std::size_t> shared_kinds;
    // Pieces that did not become stones, by mesh and primitive and connected piece: another
    // instance of the same mesh is not tried again.
    std::set<std::tuple<int, int, std::size_t>> not_stones;
    std::string demoted;  // the first stone drawn as metal, and why: said if no stone is left
    struct {
        std::string line;
        std::size_t at = 0, alike = 0;  // where in the log, and how many stones it stands for
    } last_stone;
    // How far quantised positions may stand from where the piece had them: half a step along
    // each axis, for the stone and for the metal against it.
    double rounding_mm = 0.0;
    for (const import::GltfPart& part : doc.parts) {
        const double node_scale = std::cbrt(std::abs(glm::determinant(glm::dmat3(part.to_scene))));
        rounding_mm =
            std::max(rounding_mm, std::sqrt(3.0) * part.position_step * node_scale * mm_per_unit);
        const import::GltfMaterial* material =
            part.material >= 0 ? &doc.materials[static_cast<std::size_t>(part.material)] : nullptr;
        // The manifest beside the file wins over the file's materials and names.
        const std::vector<std::string> names = {part.node, part.mesh,
                                                material ? material->name : std::string()};
        const GltfManifest::Stone* listed = manifest ? manifest->stone_named(names) : nullptr;
        const bool listed_metal = listed == nullptr && manifest && manifest->metal_named(names);
        const StoneEvidence evidence = stone_evidence(part, material);
        std::string reason;
        if (listed != nullptr) {
            reason = "the manifest " + manifest->file.filename().string() + " names it '" +
                     listed->name + "'";
        } else {
            reason = evidence.describe();
        }
        if (listed_metal || (listed == nullptr && evidence.metal())) {
            add_metal(part, part.triangles, mm_per_unit, piece.metal, metal_parts);
            continue;
        }
        std::vector<std::uint32_t> weld;
        const auto pieces = connected_pieces(part.positions, part.triangles, weld);
        const std::string who = "node '" + part.node + "' (mesh '" + part.mesh + "')";
        // A part with signs both ways: its shape decides, piece by piece.
        const bool by_shape = listed == nullptr && !evidence.stone();
        const auto rigid = import::rotation_and_scale(part.to_scene);
        for (std::size_t c = 0; c < pieces.size(); ++c) {
            const auto& tris = pieces[c];
            const auto mesh_key = std::make_tuple(part.mesh_index, part.primitive, c);
            if (not_stones.contains(mesh_key)) {
                add_metal(part, tris, mm_per_unit, piece.metal, metal_parts);
                continue;
            }
            if (tris.size() > kMaxStoneTriangles) {
                if (!by_shape) {
                    warn(who + ": a stone of " + std::to_string(tris.size()) +
                         " triangles is more than a cut has (at most " +
                         std::to_string(kMaxStoneTriangles) + "): drawn as metal");
                }
                not_stones.insert(mesh_key);
                add_metal(part, tris, mm_per_unit, piece.metal, metal_parts);
                continue;
            }
            // Its vertices, in the mesh's frame or, mirrored or unevenly scaled, the piece's.
            std::vector<glm::dvec3> corners;
            std::vector<glm::dvec3> stored;  // as the file stores them, for the tolerance
            std::map<std::uint32_t, std::uint32_t> index;
            std::vector<std::array<std::uint32_t, 3>> local;
            const glm::dmat4 bake = rigid ? glm::dmat4(1.0) : part.to_scene;
            const bool flip = !rigid && glm::determinant(glm::dmat3(bake)) < 0.0;
            for (auto t : tris) {
                std::array<std::uint32_t, 3> out{};
                for (int k = 0; k < 3; ++k) {
                    const std::uint32_t w = weld[t[k]];
                    const auto [it, fresh] =
                        index.try_emplace(w, static_cast<std::uint32_t>(corners.size()));
                    if (fresh) {
                        corners.push_back(glm::dvec3(bake * glm::dvec4(part.positions[w], 1.0)));
                        stored.push_back(part.positions[w]);
                    }
                    out[k] = it->second;
                }
                if (flip) std::swap(out[1], out[2]);  // a mirror turns the winding inside out
                local.push_back(out);
            }
            glm::dvec3 centre(0.0);
            for (const glm::dvec3& p : corners) centre += p;
            centre /= static_cast<double>(corners.size());
            const double scale = (rigid ? rigid->second : 1.0) * mm_per_unit;
            for (glm::dvec3& p : corners) p = (p - centre) * scale;
            Placement at;
            if (rigid) {
                at.rotation = rigid->first;
                at.position = glm::dvec3(part.to_scene * glm::dvec4(centre, 1.0)) * mm_per_unit;
            } else {
                at.position = centre * mm_per_unit;
            }
            // The scale as a key, rounded to float precision: a rotation written as a float
            // quaternion, or a scale of 0.99999994, is the same stone.
            const double scale_key = rigid ? std::round(rigid->second * 1e6) : -1.0;
            const auto key = std::make_tuple(part.mesh_index, part.primitive, c, scale_key);
            std::size_t kind = piece.kinds.size();
            if (auto found = shared_kinds.find(key); rigid && found != shared_kinds.end()) {
                kind = found->second;
            } else {
                std::string stone_name = part.mesh.empty() ? part.node : part.mesh;
                const double tolerance = planar_tolerance(stored, part.position_step);
                std::string repairs;
                auto stone = repaired_stone(corners, local, stone_name, tolerance,
                                            planar_tolerance(stored, 0.0), repairs);
                // A part with signs both ways is a stone when it is shaped as one: closed, and
                // convex or of few facets (a cut has tens; a cast setting thousands).
                const bool shaped =
                    stone && (stone.value().convex || stone.value().facets.size() <= 256);
                if (!stone || (by_shape && !shaped)) {
                    if (!by_shape) {
                        const std::string why = who + ": not a stone that can be traced (" +
                                                stone.error() + "): drawn as metal";
                        warn(why);
                        if (demoted.empty()) demoted = why;
                    }
                    not_stones.insert(mesh_key);
                    add_metal(part, tris, mm_per_unit, piece.metal, metal_parts);
                    continue;
                }
                if (by_shape)
                    reason += "; its shape, closed and " +
                              std::string(stone.value().convex ? "convex" : "of few facets");
                if (!repairs.empty()) warn(who + ": repaired" + repairs);
                std::string described;
                if (listed != nullptr && listed->material) {
                    stone.value().material = *listed->material;
                    described = listed->material->name + " (the manifest)";
                } else {
                    stone.value().material = stone_material(part, material, mm_per_unit, described);
                }
                piece.kinds.push_back(std::move(stone).value());
                if (rigid) shared_kinds[key] = kind;
                if (log != nullptr) {
                    std::string shape;
                    if (!piece.kinds.back().convex) {
                        shape = "; not convex";
                        if (part.position_step > 0.0) {
                            // Quantised corners can blur facets together (docs/gltf.md).
                            char step[160];
                            std::snprintf(step, sizeof step,
                                          " (its corners are quantised to %.2f µm: export them "
                                          "at 16 bits or as floats to keep its facets)",
                                          part.position_step * scale * 1000.0);
                            shape += step;
                        }
                    }
                    char facets[64];
                    std::snprintf(facets, sizeof facets, "; %zu facets",
                                  piece.kinds.back().facets.size());
                    const std::string line = "stone " + who + ": recognised as a stone by " +
                                             reason + "; " + described + facets + shape;
                    // Stones merged into one mesh say the same line each: said once, counted.
                    if (line == last_stone.line && last_stone.at < log->size()) {
                        (*log)[last_stone.at] =
                            line + " (" + std::to_string(++last_stone.alike) + " stones alike)";
                    } else {
                        last_stone = {line, log->size(), 1};
                        log->push_back(line);
                    }
                }
            }
            piece.stones.push_back(
                {kind, at, "stone " + std::to_string(piece.stones.size() + 1) + " (" + who + ")"});
        }
    }
    if (log != nullptr && metal_parts.area_by_material.empty()) {
        log->push_back("metal: none (loose stones)");
    }
    if (piece.stones.empty() && !demoted.empty())
        return Error{name + ": no stone left: " + demoted};
    if (piece.stones.empty()) {
        return Error{name +
                     ": no stone found (see config/pieces/README.md: how a stone is "
                     "recognised; a manifest beside the file can name them)"};
    }
    // The piece's one metal is the material that covers the most of it.
    if (!metal_parts.area_by_material.empty()) {
        const auto most = std::max_element(
            metal_parts.area_by_material.begin(), metal_parts.area_by_material.end(),
            [](const auto& a, const auto& b) { return a.second < b.second; });
        const import::GltfMaterial* m =
            most->first >= 0 ? &doc.materials[static_cast<std::size_t>(most->first)] : nullptr;
        set_metal_material(m, piece.metal);
        const std::string metal_name = m ? "'" + m->name + "'" : std::string("the default");
        if (log != nullptr) {
            char text[200];
            std::snprintf(text, sizeof text,
                          "metal: %zu triangles in %zu material(s), drawn as %s: F0 (%.3f, %.3f, "
                          "%.3f), roughness %.2f",
                          metal_parts.triangles, metal_parts.area_by_material.size(),
                          metal_name.c_str(), piece.metal.f0.x, piece.metal.f0.y, piece.metal.f0.z,
                          piece.metal.roughness);
            log->push_back(text);
        }
        if (metal_parts.area_by_material.size() > 1) {
            warn("the metal is drawn all in material " + metal_name +
                 ", the one that covers most of it (a piece has one metal): " +
                 std::to_string(metal_parts.area_by_material.size() - 1) +
                 " other material(s) drawn as it");
        }
        if (m != nullptr && m->clearcoat > 0.0) {
            warn("material " + metal_name + "'s clear coat is left out (the metal below shows)");
        }
        if (piece.metal.triangle_count() > kSimplifyMetalAbove) {
            const std::size_t had = simplify_metal(piece.metal, kChordToleranceMm);
            char text[200];
            std::snprintf(text, sizeof text,
                          "the metal's %zu triangles simplified to %zu, asking every surface to "
                          "stay within %.4f mm of the file's (about a pixel at the closest view)",
                          had, piece.metal.triangle_count(), kChordToleranceMm);
            warn(text);
        }
        if (metal_parts.zero_area > 0) {
            warn(std::to_string(metal_parts.zero_area) + " metal triangle(s) with no area dropped");
        }
    }
    // The largest stone is the centre, the picture's hero; among stones of one size (within
    // the file's rounding) the first.
    const auto radius = [&](const PieceStone& s) {
        return bounding_radius(piece.kinds[s.kind].vertices);
    };
    const auto hero = std::max_element(piece.stones.begin(), piece.stones.end(),
                                       [&](const PieceStone& a, const PieceStone& b) {
                                           return radius(a) * (1.0 + 1e-6) < radius(b);
                                       });
    std::rotate(piece.stones.begin(), hero, hero + 1);
    if (const std::string turned = turn_table_up(piece); !turned.empty()) warn(turned);
    centre_on_the_centre_stone(piece);
    if (const std::string far = beyond_reach(piece); !far.empty()) return Error{name + ": " + far};
    if (log != nullptr && doc.images_ignored > 0) {
        log->push_back(std::to_string(doc.images_ignored) +
                       " texture image(s) ignored: a piece is shaded by its materials' factors");
    }
    // What a jeweller's check finds is said, not refused: CAD seats are often not cut, and a
    // loose stone has no metal.
    // A band of 52 stones whose seats are all uncut says so once, with a count.
    std::map<PieceProblem::Kind, std::vector<std::string>> alike;
    for (PieceProblem& problem : piece_problems(piece, rounding_mm)) {
        alike[problem.kind].push_back(std::move(problem.message));
    }
    for (const auto& [kind, messages] : alike) {
        warn(messages.front() +
             (messages.size() > 1
                  ? " (and " + std::to_string(messages.size() - 1) + " more stones alike)"
                  : std::string()));
    }
    return piece;
}

}  // namespace gem
