#include "piece/gltf_piece.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <tuple>

#include "geometry/polyhedron.hpp"
#include "import/gltf_document.hpp"
#include "import/import_text.hpp"
#include "piece/gltf_piece_writer.hpp"
#include "piece/piece_check.hpp"
#include "render/camera.hpp"

namespace gem {

const std::vector<std::string> kGemWords = {
    // English, and the abbreviations CAD exports use ("dia045", "CZ_3")
    "diamond", "diamonds", "dia", "gem", "gems", "gemstone", "stone", "stones", "brilliant", "ruby",
    "sapphire", "emerald", "garnet", "spinel", "topaz", "amethyst", "zirconia", "cz", "moissanite",
    "crystal",
    // German, French, Italian, Spanish
    "diamant", "edelstein", "stein", "brillant", "pierre", "gemme", "diamante", "gemma", "pietra",
    "gema", "piedra"};

namespace {

constexpr double kMetresToMm = 1000.0;
// A stone with more triangles than this is refused: a cut has hundreds, and a scanned or
// subdivided mesh would take the facet recovery minutes.
constexpr std::size_t kMaxStoneTriangles = 100000;

// A name's words: lower case, split at anything not a letter or digit and between letters and
// digits ("Diamond_12" → diamond 12, "dia045" → dia 045).
std::vector<std::string> words_of(const std::string& name) {
    std::vector<std::string> out;
    std::string word;
    auto flush = [&] {
        if (!word.empty()) out.push_back(word);
        word.clear();
    };
    for (char ch : name) {
        const auto c = static_cast<unsigned char>(ch);
        if (!std::isalnum(c)) {
            flush();
            continue;
        }
        if (!word.empty() && (std::isdigit(c) != 0) !=
                                 (std::isdigit(static_cast<unsigned char>(word.back())) != 0)) {
            flush();
        }
        word.push_back(static_cast<char>(std::tolower(c)));
    }
    flush();
    return out;
}

// The first gem word in `name`, or empty.
std::string gem_word(const std::string& name) {
    for (const std::string& w : words_of(name)) {
        if (std::find(kGemWords.begin(), kGemWords.end(), w) != kGemWords.end()) return w;
    }
    return {};
}

// Why a part is a stone, or empty when it is metal.
std::string stone_reason(const import::GltfPart& part, const import::GltfMaterial* material) {
    if (material != nullptr) {
        if (material->transmission > 0.0) {
            return "its material '" + material->name + "' is transmissive";
        }
        for (const char* ext :
             {"KHR_materials_ior", "KHR_materials_volume", "KHR_materials_dispersion"}) {
            if (std::find(material->extensions.begin(), material->extensions.end(), ext) !=
                material->extensions.end()) {
                return "its material '" + material->name + "' carries " + ext;
            }
        }
    }
    const std::pair<const char*, std::string> names[] = {
        {"node", part.node}, {"mesh", part.mesh}, {"material", material ? material->name : ""}};
    for (const auto& [what, name] : names) {
        if (!gem_word(name).empty()) return std::string("its ") + what + "'s name '" + name + "'";
    }
    return {};
}

// The stone's material: a built-in one its names give, else diamond; then the file's gem
// extensions over it.
Material stone_material(const import::GltfPart& part, const import::GltfMaterial* m,
                        std::string& described) {
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
    // A built-in material named by the file, whose index and fire the file repeats (as this
    // project writes them, gltf_piece_writer.hpp), keeps its own dispersion curve and colour.
    const bool ior_agrees = !m->ior || std::abs(*m->ior - material.index(587.6)) < 1e-3;
    const double built_in_vd = abbe_number(material);
    const bool fire_agrees =
        !m->dispersion || (std::isfinite(built_in_vd) && *m->dispersion > 0.0 &&
                           std::abs(20.0 / *m->dispersion / built_in_vd - 1.0) < 0.01);
    const bool as_built_in = named && ior_agrees && fire_agrees;
    if (as_built_in && (m->ior || m->dispersion)) {
        described += ", its index and fire as the file gives them";
    }
    if (!as_built_in && m->transmission > 0.0) {
        // glTF tints what a transmissive material lets through by its base colour: the
        // thesis' stone colour.
        material.body_colour = glm::clamp(m->base_colour, 0.0, 1.0);
    }
    char text[160];
    if (!as_built_in && m->ior && std::abs(*m->ior - material.index()) > 1e-3) {
        // The file's index over the built-in one: no dispersion unless the file gives it.
        material.dispersion = Dispersion::constant_index(*m->ior);
        std::snprintf(text, sizeof text, ", n %.3f from KHR_materials_ior", *m->ior);
        described += text;
    }
    if (!as_built_in && m->dispersion && *m->dispersion > 0.0) {
        // KHR_materials_dispersion: dispersion = 20 / V_d, and n(λ) = A + B / λ² with
        // B = (n_d − 1) / (V_d (λ_F⁻² − λ_C⁻²)), A = n_d − B / λ_d² (the extension's
        // specification; λ_F 486.1, λ_d 587.6, λ_C 656.3 nm, here in µm).
        const double nd = m->ior ? *m->ior : material.index();
        const double vd = 20.0 / *m->dispersion;
        const double f = 0.4861, d = 0.5876, c = 0.6563;
        const double b = (nd - 1.0) / (vd * (1.0 / (f * f) - 1.0 / (c * c)));
        material.dispersion.kind = Dispersion::Kind::cauchy;
        material.dispersion.coef = {nd - b / (d * d), b};
        std::snprintf(text, sizeof text, ", Abbe number %.1f from KHR_materials_dispersion", vd);
        described += text;
    }
    if (std::isfinite(m->attenuation_distance_m) && m->attenuation_distance_m > 0.0) {
        // Beer–Lambert: the colour c left after the distance d, so σ = −ln(c) / d (per mm).
        for (int i = 0; i < 3; ++i) {
            const double c = std::clamp(m->attenuation_colour[i], 1e-6, 1.0);
            material.absorption_per_mm[i] =
                -std::log(c) / (m->attenuation_distance_m * kMetresToMm);
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

void add_metal(const import::GltfPart& part, const import::GltfMaterial* m, MetalMesh& metal,
               bool& first_metal, std::vector<std::string>* log) {
    const glm::dmat4& to = part.to_scene;
    const bool mirrored = glm::determinant(glm::dmat3(to)) < 0.0;
    std::vector<glm::dvec3> placed(part.positions.size());
    for (std::size_t i = 0; i < placed.size(); ++i) {
        placed[i] = glm::dvec3(to * glm::dvec4(part.positions[i], 1.0)) * kMetresToMm;
    }
    // The file's normals, taken to the scene by the inverse transpose; without them, corners
    // share an area-weighted average of their faces' normals, per vertex as the file splits
    // them (a crease keeps its edge).
    std::vector<glm::dvec3> normal(placed.size(), glm::dvec3(0.0));
    if (part.normals.size() == placed.size()) {
        const glm::dmat3 to_normal = glm::transpose(glm::inverse(glm::dmat3(to)));
        for (std::size_t i = 0; i < placed.size(); ++i) normal[i] = to_normal * part.normals[i];
    } else {
        for (auto t : part.triangles) {
            if (mirrored) std::swap(t[1], t[2]);
            const glm::dvec3 g =
                glm::cross(placed[t[1]] - placed[t[0]], placed[t[2]] - placed[t[0]]);
            for (std::uint32_t c : t) normal[c] += g;
        }
    }
    const auto base = static_cast<std::uint32_t>(metal.positions.size());
    for (std::size_t i = 0; i < placed.size(); ++i) {
        metal.positions.emplace_back(placed[i]);
        const double len = glm::length(normal[i]);
        metal.normals.emplace_back(len > 0.0 ? glm::vec3(normal[i] / len) : glm::vec3(0, 1, 0));
    }
    for (auto t : part.triangles) {
        if (mirrored) std::swap(t[1], t[2]);
        for (std::uint32_t c : t) metal.indices.push_back(base + c);
    }
    // One metal for the piece (MetalMesh has one F0): the first part's; a second metal is said.
    const glm::dvec3 base_colour = m ? m->base_colour : glm::dvec3(1.0);
    const double metallic = m ? m->metallic : 1.0;
    const glm::vec3 f0 = glm::vec3(glm::mix(glm::dvec3(0.04), base_colour, metallic));
    const float roughness = static_cast<float>(std::clamp(m ? m->roughness : 1.0, 0.0, 1.0));
    if (first_metal) {
        metal.f0 = f0;
        metal.roughness = roughness;
        first_metal = false;
    } else if (log != nullptr && (glm::length(f0 - metal.f0) > 1e-3f ||
                                  std::abs(roughness - metal.roughness) > 1e-3f)) {
        log->push_back("metal of node '" + part.node + "' (material '" +
                       (m ? m->name : std::string("default")) +
                       "') drawn as the piece's first metal: a piece has one metal");
    }
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
    const auto fail = [&](const std::string& why) { return Error{name + ": " + why}; };
    Piece piece;
    piece.name = std::filesystem::path(name).stem().string();
    bool first_metal = true;
    // Kinds made from a mesh's own frame, by (mesh, primitive, connected piece, scale).
    std::map<std::tuple<int, int, std::size_t, double>, std::size_t> shared_kinds;
    // How far quantised positions may stand from where the piece had them: half a step along
    // each axis, for the stone and for the metal against it.
    double rounding_mm = 0.0;
    for (const import::GltfPart& part : doc.parts) {
        const double node_scale = std::cbrt(std::abs(glm::determinant(glm::dmat3(part.to_scene))));
        rounding_mm =
            std::max(rounding_mm, std::sqrt(3.0) * part.position_step * node_scale * kMetresToMm);
        const import::GltfMaterial* material =
            part.material >= 0 ? &doc.materials[static_cast<std::size_t>(part.material)] : nullptr;
        // The manifest beside the file wins over the file's materials and names.
        const std::vector<std::string> names = {part.node, part.mesh,
                                                material ? material->name : std::string()};
        const GltfManifest::Stone* listed = manifest ? manifest->stone_named(names) : nullptr;
        std::string reason;
        if (listed != nullptr) {
            reason = "the manifest " + manifest->file.filename().string() + " names it '" +
                     listed->name + "'";
        } else if (manifest == nullptr || !manifest->metal_named(names)) {
            reason = stone_reason(part, material);
        }
        if (reason.empty()) {
            add_metal(part, material, piece.metal, first_metal, log);
            continue;
        }
        const std::string who = "node '" + part.node + "' (mesh '" + part.mesh + "')";
        std::vector<std::uint32_t> weld;
        const auto pieces = connected_pieces(part.positions, part.triangles, weld);
        const auto rigid = import::rotation_and_scale(part.to_scene);
        for (std::size_t c = 0; c < pieces.size(); ++c) {
            const auto& tris = pieces[c];
            if (tris.size() > kMaxStoneTriangles) {
                return fail(who + ": a stone of " + std::to_string(tris.size()) +
                            " triangles (at most " + std::to_string(kMaxStoneTriangles) + ")");
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
            const double scale = (rigid ? rigid->second : 1.0) * kMetresToMm;
            for (glm::dvec3& p : corners) p = (p - centre) * scale;
            Placement at;
            if (rigid) {
                at.rotation = rigid->first;
                at.position = glm::dvec3(part.to_scene * glm::dvec4(centre, 1.0)) * kMetresToMm;
            } else {
                at.position = centre * kMetresToMm;
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
                auto stone = stone_from_triangles(corners, local, stone_name, 1e-6, tolerance);
                std::string closed;
                if (!stone && stone.error().starts_with("mesh is open")) {
                    // An export that lost a few triangles of a convex stone: closed by the
                    // planes of the facets it kept, said in the log.
                    auto whole = stone_closed_by_its_planes(corners, local, stone_name, tolerance);
                    if (!whole) {
                        return fail(who + ": " + stone.error() + ", and " + whole.error());
                    }
                    const std::string& why = stone.error();  // "mesh is open: N boundary edges"
                    closed = "; open (" + why.substr(why.find(": ") + 2) +
                             "): closed by the planes of its facets";
                    stone = std::move(whole);
                }
                if (!stone) return fail(who + ": " + stone.error());
                std::string described;
                if (listed != nullptr && listed->material) {
                    stone.value().material = *listed->material;
                    described = listed->material->name + " (the manifest)";
                } else {
                    stone.value().material = stone_material(part, material, described);
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
                    log->push_back("stone " + who + ": recognised as " + reason + "; " + described +
                                   shape + closed);
                }
            }
            piece.stones.push_back(
                {kind, at, "stone " + std::to_string(piece.stones.size() + 1) + " (" + who + ")"});
        }
    }
    if (piece.stones.empty())
        return fail("no stone found (see config/pieces/README.md: how a stone is recognised)");
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
    if (log != nullptr && doc.images_ignored > 0) {
        log->push_back(std::to_string(doc.images_ignored) +
                       " texture image(s) ignored: a piece is shaded by its materials' factors");
    }
    if (auto ok = check_piece(piece, rounding_mm); !ok) return fail(ok.error());
    return piece;
}

}  // namespace gem
