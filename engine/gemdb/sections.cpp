#include "gemdb/sections.hpp"

#include <cmath>
#include <string>

#include "gemdb/format.hpp"
#include "optics/spectrum.hpp"

namespace gem {

namespace {

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The common ending of every section decoder: truncation and trailing bytes are damage.
template <class T>
Result<T> finish(const ByteReader& in, const char* section, T value) {
    if (in.failed())
        return Error{std::string(section) + " section is truncated or has a bad length"};
    if (in.remaining() != 0) {
        return Error{std::string(section) + " section has " + std::to_string(in.remaining()) +
                     " unexpected trailing bytes"};
    }
    return value;
}

Error bad(const char* section, const std::string& what) {
    return Error{std::string(section) + " section: " + what};
}

}  // namespace

void write_stone_section(ByteWriter& out, const Stone& stone) {
    out.string(stone.name);
    out.u32(static_cast<std::uint32_t>(stone.vertices.size()));
    for (const glm::dvec3& v : stone.vertices) out.vec3(v);
    out.u32(static_cast<std::uint32_t>(stone.facets.size()));
    for (const Facet& f : stone.facets) {
        out.vec3(f.plane.n);
        out.f64(f.plane.d);
        out.u8(static_cast<std::uint8_t>(f.kind));
        out.string(f.name);
        out.u32(static_cast<std::uint32_t>(f.loop.size()));
        for (const std::uint32_t i : f.loop) out.u32(i);
    }
    out.u32(static_cast<std::uint32_t>(stone.triangles.size()));
    for (const MeshTriangle& t : stone.triangles) {
        for (const std::uint32_t i : t.v) out.u32(i);
        out.u32(t.facet);
    }
    out.u8(stone.convex ? 1 : 0);
    out.u32(static_cast<std::uint32_t>(stone.symmetry.size()));
    for (const glm::dmat3& m : stone.symmetry) {
        for (int c = 0; c < 3; ++c) out.vec3(m[c]);  // column-major
    }
}

Result<Stone> read_stone_section(std::span<const std::uint8_t> bytes) {
    constexpr const char* kName = "stone";
    ByteReader in(bytes);
    Stone stone;
    stone.name = in.string();
    if (in.failed()) return finish(in, kName, std::move(stone));
    const std::uint32_t vertices = in.u32();
    if (vertices > gemdb::kMaxVertices || vertices > in.remaining() / 24) {
        return bad(kName, "vertex count " + std::to_string(vertices) + " is absurd");
    }
    stone.vertices.resize(vertices);
    for (glm::dvec3& v : stone.vertices) v = in.vec3();
    const std::uint32_t facets = in.u32();
    if (facets > gemdb::kMaxFacets || facets > in.remaining() / 41) {
        return bad(kName, "facet count " + std::to_string(facets) + " is absurd");
    }
    stone.facets.resize(facets);
    for (std::uint32_t f = 0; f < facets && !in.failed(); ++f) {
        Facet& facet = stone.facets[f];
        facet.plane.n = in.vec3();
        facet.plane.d = in.f64();
        const std::uint8_t kind = in.u8();
        if (kind > static_cast<std::uint8_t>(FacetKind::other)) {
            return bad(kName,
                       "facet " + std::to_string(f) + " has unknown kind " + std::to_string(kind));
        }
        facet.kind = static_cast<FacetKind>(kind);
        facet.name = in.string();
        const std::uint32_t loop = in.u32();
        if (loop < 3 || loop > vertices || loop > in.remaining() / 4) {
            return bad(kName, "facet " + std::to_string(f) + " has a loop of " +
                                  std::to_string(loop) + " vertices");
        }
        facet.loop.resize(loop);
        for (std::uint32_t& i : facet.loop) {
            i = in.u32();
            if (i >= vertices)
                return bad(kName, "facet " + std::to_string(f) + " names a missing vertex");
        }
        if (!finite(facet.plane.n) || !std::isfinite(facet.plane.d)) {
            return bad(kName, "facet " + std::to_string(f) + " has a non-finite plane");
        }
    }
    const std::uint32_t triangles = in.u32();
    if (triangles > gemdb::kMaxTriangles || triangles > in.remaining() / 16) {
        return bad(kName, "triangle count " + std::to_string(triangles) + " is absurd");
    }
    stone.triangles.resize(triangles);
    for (MeshTriangle& t : stone.triangles) {
        for (std::uint32_t& i : t.v) i = in.u32();
        t.facet = in.u32();
        if (t.v[0] >= vertices || t.v[1] >= vertices || t.v[2] >= vertices || t.facet >= facets) {
            if (!in.failed()) return bad(kName, "a triangle names a missing vertex or facet");
        }
    }
    const std::uint8_t convex = in.u8();
    if (convex > 1) return bad(kName, "convex flag is " + std::to_string(convex));
    stone.convex = convex == 1;
    const std::uint32_t symmetry = in.u32();
    if (symmetry == 0 || symmetry > gemdb::kMaxSymmetry || symmetry > in.remaining() / 72) {
        if (!in.failed())
            return bad(kName, "symmetry count " + std::to_string(symmetry) + " is absurd");
    } else {
        stone.symmetry.resize(symmetry);
        for (glm::dmat3& m : stone.symmetry) {
            for (int c = 0; c < 3; ++c) {
                m[c] = in.vec3();
                if (!finite(m[c]) && !in.failed()) {
                    return bad(kName, "a symmetry matrix is not finite");
                }
            }
        }
    }
    for (const glm::dvec3& v : stone.vertices) {
        if (!finite(v)) return bad(kName, "a vertex is not finite");
    }
    return finish(in, kName, std::move(stone));
}

void write_material_section(ByteWriter& out, const Material& material) {
    out.string(material.name);
    out.u8(static_cast<std::uint8_t>(material.dispersion.kind));
    out.u32(static_cast<std::uint32_t>(material.dispersion.coef.size()));
    for (const double c : material.dispersion.coef) out.f64(c);
    out.vec3(material.body_colour);
    out.vec3(material.absorption_per_mm);
}

Result<Material> read_material_section(std::span<const std::uint8_t> bytes) {
    constexpr const char* kName = "material";
    ByteReader in(bytes);
    Material material;
    material.name = in.string();
    const std::uint8_t kind = in.u8();
    if (kind > static_cast<std::uint8_t>(Dispersion::Kind::sellmeier)) {
        if (!in.failed()) return bad(kName, "unknown dispersion kind " + std::to_string(kind));
    }
    material.dispersion.kind = static_cast<Dispersion::Kind>(kind);
    const std::uint32_t count = in.u32();
    if (count > gemdb::kMaxCoefficients) {
        if (!in.failed())
            return bad(kName, "coefficient count " + std::to_string(count) + " is absurd");
    } else {
        material.dispersion.coef.resize(count);
        for (double& c : material.dispersion.coef) {
            c = in.f64();
            if (!std::isfinite(c) && !in.failed()) return bad(kName, "a coefficient is not finite");
        }
    }
    // Each kind needs its coefficients: constant one, Cauchy two, Sellmeier (B, C) pairs.
    const std::size_t have = material.dispersion.coef.size();
    const bool enough = material.dispersion.kind == Dispersion::Kind::constant ? have >= 1
                        : material.dispersion.kind == Dispersion::Kind::cauchy
                            ? have >= 2
                            : have >= 2 && have % 2 == 0;
    if (!enough && !in.failed()) {
        return bad(kName, std::to_string(have) + " coefficients do not fit the dispersion kind");
    }
    if (enough && !in.failed() && !material.dispersion.is_physical()) {
        return bad(kName, "the refractive index is not a finite n >= 1 over " +
                              std::to_string(static_cast<int>(kSpectrumMinNm)) + "-" +
                              std::to_string(static_cast<int>(kSpectrumMaxNm)) + " nm");
    }
    material.body_colour = in.vec3();
    material.absorption_per_mm = in.vec3();
    if (!finite(material.body_colour) || !finite(material.absorption_per_mm)) {
        if (!in.failed()) return bad(kName, "colour or absorption is not finite");
    }
    return finish(in, kName, std::move(material));
}

void write_stone_identity(ByteWriter& out, const Stone& stone) {
    write_stone_section(out, stone);
    write_material_section(out, stone.material);
}

bool same_stored_stone(const Stone& a, const Stone& b) {
    ByteWriter first;
    ByteWriter second;
    write_stone_identity(first, a);
    write_stone_identity(second, b);
    return first.bytes() == second.bytes();
}

void write_camera_section(ByteWriter& out, const CameraModel& camera) {
    out.u8(static_cast<std::uint8_t>(camera.kind));
    out.f64(camera.distance_mm);
    out.f64(camera.field_mm);
}

Result<CameraModel> read_camera_section(std::span<const std::uint8_t> bytes) {
    constexpr const char* kName = "camera";
    ByteReader in(bytes);
    CameraModel camera;
    const std::uint8_t kind = in.u8();
    camera.distance_mm = in.f64();
    camera.field_mm = in.f64();
    if (in.failed()) return finish(in, kName, camera);
    if (kind > 1) return bad(kName, "unknown camera kind " + std::to_string(kind));
    camera.kind = static_cast<CameraModel::Kind>(kind);
    if (!(camera.field_mm > 0.0 && std::isfinite(camera.field_mm))) {
        return bad(kName, "field_mm is not a positive number");
    }
    if (camera.kind == CameraModel::Kind::perspective &&
        !(camera.distance_mm > 0.0 && std::isfinite(camera.distance_mm))) {
        return bad(kName, "distance_mm is not a positive number");
    }
    return finish(in, kName, camera);
}

void write_params_section(ByteWriter& out, const BuildParams& params, const PositionBox& box) {
    out.u32(static_cast<std::uint32_t>(params.levels.size()));
    for (const std::uint32_t side : params.levels) out.u32(side);
    out.f64(params.grid.spacing_rad);
    out.f64(params.grid.min_elevation_rad);
    out.u32(params.max_depth);
    out.f64(params.weight_threshold);
    out.u8(params.dispersion ? 1 : 0);
    out.vec3(box.min);
    out.vec3(box.max);
}

Result<ParamsSection> read_params_section(std::span<const std::uint8_t> bytes) {
    constexpr const char* kName = "params";
    ByteReader in(bytes);
    ParamsSection s;
    const std::uint32_t levels = in.u32();
    if (levels == 0 || levels > gemdb::kMaxLevels) {
        if (!in.failed()) return bad(kName, "level count " + std::to_string(levels) + " is absurd");
        return finish(in, kName, s);
    }
    s.params.levels.resize(levels);
    for (std::uint32_t l = 0; l < levels; ++l) {
        const std::uint32_t side = in.u32();
        if (in.failed()) break;
        if (side == 0 || side > gemdb::kMaxSide || (l > 0 && side <= s.params.levels[l - 1])) {
            return bad(kName, "level " + std::to_string(l) + " has side " + std::to_string(side) +
                                  " (sides must ascend, 1 .. 8192)");
        }
        s.params.levels[l] = side;
    }
    s.params.grid.spacing_rad = in.f64();
    s.params.grid.min_elevation_rad = in.f64();
    s.params.max_depth = in.u32();
    s.params.weight_threshold = in.f64();
    const std::uint8_t dispersion = in.u8();
    s.box.min = in.vec3();
    s.box.max = in.vec3();
    if (in.failed()) return finish(in, kName, s);
    if (dispersion > 1) return bad(kName, "dispersion flag is " + std::to_string(dispersion));
    s.params.dispersion = dispersion == 1;
    if (!(s.params.weight_threshold >= 0.0 && s.params.weight_threshold <= 1.0)) {
        return bad(kName, "weight_threshold is out of range (0 .. 1)");
    }
    if (!finite(s.box.min) || !finite(s.box.max) || !(s.box.max.x > s.box.min.x) ||
        !(s.box.max.y > s.box.min.y) || !(s.box.max.z > s.box.min.z)) {
        return bad(kName, "the position box is empty or not finite");
    }
    return finish(in, kName, s);
}

void write_grid_section(ByteWriter& out, const ViewGrid& grid) {
    out.f64(grid.spec().spacing_rad);
    out.f64(grid.spec().min_elevation_rad);
    out.vec3(grid.key());
    out.u32(grid.sphere_count());
    out.u32(static_cast<std::uint32_t>(grid.group_indices().size()));
    for (const std::uint32_t i : grid.group_indices()) out.u32(i);
    out.u32(static_cast<std::uint32_t>(grid.sphere_indices().size()));
    for (const std::uint32_t i : grid.sphere_indices()) out.u32(i);
}

Result<ViewGrid> read_grid_section(std::span<const std::uint8_t> bytes,
                                   const std::vector<glm::dmat3>& symmetry) {
    constexpr const char* kName = "grid";
    ByteReader in(bytes);
    ViewGridSpec spec;
    spec.spacing_rad = in.f64();
    spec.min_elevation_rad = in.f64();
    const glm::dvec3 key = in.vec3();
    const std::uint32_t sphere_count = in.u32();
    const std::uint32_t group = in.u32();
    if (group == 0 || group > gemdb::kMaxSymmetry || group > in.remaining() / 4) {
        if (!in.failed()) return bad(kName, "group size " + std::to_string(group) + " is absurd");
        return Error{std::string(kName) + " section is truncated"};
    }
    std::vector<std::uint32_t> group_indices(group);
    for (std::uint32_t& i : group_indices) i = in.u32();
    const std::uint32_t views = in.u32();
    if (views > gemdb::kMaxViews || views > in.remaining() / 4) {
        if (!in.failed()) return bad(kName, "view count " + std::to_string(views) + " is absurd");
        return Error{std::string(kName) + " section is truncated"};
    }
    std::vector<std::uint32_t> sphere_indices(views);
    for (std::uint32_t& i : sphere_indices) i = in.u32();
    if (in.failed() || in.remaining() != 0) {
        return Error{std::string(kName) + " section is truncated or has trailing bytes"};
    }
    if (!finite(key)) return bad(kName, "key is not finite");
    auto grid = ViewGrid::from_parts(spec, symmetry, std::move(group_indices), key, sphere_count,
                                     std::move(sphere_indices));
    if (!grid) return bad(kName, grid.error());
    return grid;
}

}  // namespace gem
