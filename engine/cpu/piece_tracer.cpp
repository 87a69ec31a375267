#include "cpu/piece_tracer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "optics/fresnel.hpp"
#include "optics/microfacet.hpp"
#include "picture/camera.hpp"
#include "scene/lights.hpp"

namespace gem {

namespace {

// How far a ray that leaves a surface starts off it, so it does not meet that surface again.
constexpr double kOffsetMm = 1e-7;

// A 64-bit mixing step (splitmix64), one uniform number in [0, 1) a call.
double uniform(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * (1.0 / 9007199254740992.0);
}

}  // namespace

Stone metal_as_solid(const MetalMesh& metal) {
    Stone s;
    s.name = "metal";
    s.convex = false;
    for (const glm::vec3& p : metal.positions) s.vertices.emplace_back(p);
    for (std::size_t t = 0; t + 2 < metal.indices.size(); t += 3) {
        const std::uint32_t a = metal.indices[t], b = metal.indices[t + 1],
                            c = metal.indices[t + 2];
        glm::dvec3 n = glm::cross(s.vertices[b] - s.vertices[a], s.vertices[c] - s.vertices[a]);
        const double length = glm::length(n);
        if (!(length > 0.0)) continue;  // a triangle without area cannot be hit
        n /= length;
        if (glm::dot(n, glm::dvec3(metal.normals[a] + metal.normals[b] + metal.normals[c])) < 0.0) {
            n = -n;
        }
        const auto facet = static_cast<std::uint32_t>(s.facets.size());
        s.facets.push_back({Plane{n, glm::dot(n, s.vertices[a])}, {a, b, c}, FacetKind::other, ""});
        s.triangles.push_back({{a, b, c}, facet});
    }
    return s;
}

struct PieceTracer::Nearest {
    double t = std::numeric_limits<double>::infinity();
    int stone = -1;  // -1: the metal, if `metal_hit`
    bool metal_hit = false;
    SurfaceHit metal;
};

PieceTracer::PieceTracer(const Piece& piece, const Environment& environment,
                         const ShadingSettings& shading, const TraceSettings& trace,
                         PieceSight sight)
    : piece_(piece), environment_(environment), shading_(shading), trace_(trace), sight_(sight) {
    for (const Stone& kind : piece.kinds) {
        tracers_.emplace_back(kind);
        entries_.push_back(make_intersector(kind));
        radii_.push_back(bounding_radius(kind.vertices));
    }
    metal_solid_ = metal_as_solid(piece.metal);
    if (!metal_solid_.triangles.empty()) metal_ = make_bvh_intersector(metal_solid_);
}

PieceTracer::~PieceTracer() = default;

PieceTracer::Nearest PieceTracer::nearest(const Ray& ray, int skip_stone, bool stones) const {
    Nearest n;
    for (std::size_t i = 0; stones && i < piece_.stones.size(); ++i) {
        if (static_cast<int>(i) == skip_stone) continue;
        const PieceStone& s = piece_.stones[i];
        // The bounding sphere first: most rays pass most stones by.
        const glm::dvec3 to_centre = s.placement.position - ray.origin;
        const double along = glm::dot(to_centre, ray.direction);
        const double r = radii_[s.kind];
        if (glm::dot(to_centre, to_centre) - along * along > r * r) continue;
        if (along + r < 0.0) continue;
        SurfaceHit hit;
        if (entries_[s.kind]->next_entry(s.placement.to_stone(ray.origin),
                                         s.placement.direction_to_stone(ray.direction), kNoFacet,
                                         hit) &&
            hit.t > 0.0 && hit.t < n.t) {
            n.t = hit.t;
            n.stone = static_cast<int>(i);
        }
    }
    SurfaceHit hit;
    if (metal_ && metal_->next_entry(ray.origin, ray.direction, kNoFacet, hit) && hit.t > 0.0 &&
        hit.t < n.t) {
        n.t = hit.t;
        n.stone = -1;
        n.metal_hit = true;
        n.metal = hit;
    }
    return n;
}

glm::dvec3 PieceTracer::radiance(const Ray& ray, const std::vector<double>& iors, Scratch& scratch,
                                 bool* hit) const {
    const Nearest n = nearest(ray, -1);
    if (hit != nullptr) *hit = n.stone >= 0 || n.metal_hit;
    // A ray straight from the eye that meets nothing sees the surroundings, not the lights.
    if (n.stone < 0 && !n.metal_hit) return environment_.radiance(ray.direction);
    return follow(ray, n, iors, kPasses, 1.0, scratch);
}

glm::dvec3 PieceTracer::onward(const Ray& ray, int from_stone, const glm::dvec3& from_normal,
                               double k, const glm::dvec3& weight, const std::vector<double>& iors,
                               int pass, double share, Scratch& scratch) const {
    const double w = std::max({weight.x, weight.y, weight.z}) * share;
    if (w < kMinShare) return weight * escaped(ray, from_stone, from_normal, k);
    const Nearest next = nearest(ray, from_stone, sight_ != PieceSight::metal_only);
    if (next.stone < 0 && !next.metal_hit) {
        return weight * escaped(ray, from_stone, from_normal, k);
    }
    if (pass == 0) return weight * environment_.radiance(ray.direction);
    return weight * follow(ray, next, iors, pass, w, scratch);
}

// A ray that leaves the piece: the environment, and each light whose lobe it lies in (times
// `k`, the shading's k_s for a first reflection and k_st for an exit) unless the piece stands
// between it and the light (a convex stone's own facet blocks only when it faces away), as
// Shader::light_specular has it for a loose stone. `piece_blocks` false: no part of the piece
// blocks a light (PieceSight::metal_sees_environment, the GPU's metal).
glm::dvec3 PieceTracer::escaped(const Ray& ray, int from_stone, const glm::dvec3& from_normal,
                                double k, bool piece_blocks) const {
    glm::dvec3 sum = environment_.radiance(ray.direction);
    if (k == 0.0) return sum;
    for (const Light& light : shading_.lights) {
        const glm::dvec3 to_light = direction_to_light(light, ray.origin);
        const double lobe = specular_lobe(ray.direction, to_light, shading_.h);
        if (lobe == 0.0) continue;
        if (from_stone >= 0 && glm::dot(from_normal, to_light) < 0.0) continue;
        if (!piece_blocks) {
            sum += light.colour * (k * lobe);
            continue;
        }
        const Nearest block =
            nearest({ray.origin, to_light}, from_stone, sight_ != PieceSight::metal_only);
        const double reach = light.directional ? std::numeric_limits<double>::infinity()
                                               : glm::length(light.position - ray.origin);
        if ((block.stone >= 0 || block.metal_hit) && block.t < reach) continue;
        sum += light.colour * (k * lobe);
    }
    return sum;
}

glm::dvec3 PieceTracer::follow(const Ray& ray, const Nearest& n, const std::vector<double>& iors,
                               int pass, double share, Scratch& scratch) const {
    if (n.metal_hit) return metal(ray, n.metal, iors, pass, share, scratch);
    const PieceStone& s = piece_.stones[static_cast<std::size_t>(n.stone)];
    const Stone& stone = piece_.kinds[s.kind];
    // Each pass has its own list: the passes below it use theirs while this one is read.
    RayList& list = scratch.lists[static_cast<std::size_t>(pass)];
    tracers_[s.kind].trace(
        {s.placement.to_stone(ray.origin), s.placement.direction_to_stone(ray.direction)},
        iors[s.kind], trace_, list);
    if (!list.hit) return environment_.radiance(ray.direction);  // grazing: the tracer missed
    // A convex stone cannot be met again by a ray that has left it.
    const int skip = stone.convex ? n.stone : -1;
    auto out = [&](const TracedRay& r) {
        const glm::dvec3 d = s.placement.direction_to_piece(r.direction);
        return Ray{s.placement.to_piece(r.origin) + kOffsetMm * d, d};
    };
    auto normal = [&](const TracedRay& r) {
        return s.placement.direction_to_piece(stone.facets[r.facet].plane.n);
    };
    const TracedRay& r = list.reflected;
    glm::dvec3 colour = onward(out(r), skip, normal(r), shading_.k_s, glm::dvec3(r.weight), iors,
                               pass - 1, share, scratch);
    for (const TracedRay& e : list.exits) {
        const glm::dvec3 weight =
            e.weight * beer_lambert(stone.material.absorption_per_mm, e.path_mm);
        colour +=
            onward(out(e), skip, normal(e), shading_.k_st, weight, iors, pass - 1, share, scratch);
    }
    return colour;
}

glm::dvec3 PieceTracer::metal(const Ray& ray, const SurfaceHit& hit,
                              const std::vector<double>& iors, int pass, double share,
                              Scratch& scratch) const {
    // The shading normal, interpolated from the vertex normals across the triangle.
    const MeshTriangle& tri = metal_solid_.triangles[hit.facet];
    const glm::dvec3 a = metal_solid_.vertices[tri.v[0]], b = metal_solid_.vertices[tri.v[1]],
                     c = metal_solid_.vertices[tri.v[2]];
    const glm::dvec3 face = metal_solid_.facets[hit.facet].plane.n;
    const glm::dvec3 area = glm::cross(b - a, c - a);
    const double whole = glm::dot(area, face);
    const double wa = glm::dot(glm::cross(c - b, hit.point - b), face) / whole;
    const double wb = glm::dot(glm::cross(a - c, hit.point - c), face) / whole;
    const double wc = 1.0 - wa - wb;
    glm::dvec3 n = wa * glm::dvec3(piece_.metal.normals[tri.v[0]]) +
                   wb * glm::dvec3(piece_.metal.normals[tri.v[1]]) +
                   wc * glm::dvec3(piece_.metal.normals[tri.v[2]]);
    n = glm::normalize(n);
    const glm::dvec3 v = -ray.direction;
    if (glm::dot(n, v) <= 1e-6) n = face;  // a shading normal facing away: the face's own

    // A microfacet normal from GGX's distribution, weighted as drawn (optics/microfacet.hpp).
    const double alpha = ggx_alpha(piece_.metal.roughness);
    const double u1 = uniform(scratch.random), u2 = uniform(scratch.random);
    const glm::dvec3 m = sample_ggx_normal(n, alpha, u1, u2);
    const GgxReflection reflected = ggx_reflect(glm::dvec3(piece_.metal.f0), n, v, m, alpha);
    if (reflected.weight == glm::dvec3(0.0)) return glm::dvec3(0.0);
    const Ray out{hit.point + kOffsetMm * face, reflected.direction};
    // As the GPU's metal: what it reflects is the environment and the lights, nothing of the
    // piece.
    if (sight_ == PieceSight::metal_sees_environment) {
        return reflected.weight * escaped(out, -1, glm::dvec3(0.0), 1.0, false);
    }
    return onward(out, -1, glm::dvec3(0.0), 1.0, reflected.weight, iors, pass - 1, share, scratch);
}

}  // namespace gem
