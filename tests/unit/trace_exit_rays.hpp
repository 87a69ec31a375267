#pragma once
// The rays an exit search is checked on against the full search over every facet
// (convex_intersector.cpp), shared by the facet walk's and the fold's tests: internal paths of
// pixel rays (entry refraction, then reflections, as the tracer follows them), rays from
// inside aimed exactly at corners and at points on edges, and rays that start on a corner or an
// edge.

#include <functional>
#include <random>

#include "optics/fresnel.hpp"
#include "picture/camera.hpp"
#include "trace/intersector.hpp"
#include "trace_cut_stones.hpp"

namespace gem::test {

inline glm::dvec3 random_unit(std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    return glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
}

// A point strictly inside: the mean of the corners, nudged toward a random vertex.
inline glm::dvec3 inside_point(const Stone& s, std::mt19937_64& rng) {
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& v : s.vertices) centre += v;
    centre /= static_cast<double>(s.vertices.size());
    std::uniform_int_distribution<std::size_t> pick(0, s.vertices.size() - 1);
    std::uniform_real_distribution<double> share(0.0, 0.95);
    return centre + share(rng) * (s.vertices[pick(rng)] - centre);
}

// Calls check(origin, direction, from_facet) for every ray; `pixel_rays` rays from outside
// followed `depth` segments inside.
inline void for_every_kind_of_exit_ray(
    const Stone& s, int pixel_rays, int depth,
    const std::function<void(const glm::dvec3&, const glm::dvec3&, std::uint32_t)>& check) {
    const auto full = make_convex_intersector(s);
    std::mt19937_64 rng(7);
    const double radius = bounding_radius(s.vertices);
    for (int i = 0; i < pixel_rays; ++i) {
        const glm::dvec3 d = random_unit(rng);
        glm::dvec3 side = glm::normalize(glm::cross(d, random_unit(rng)));
        std::uniform_real_distribution<double> offset(-radius, radius);
        const glm::dvec3 o = -2.0 * radius * d + offset(rng) * side;
        SurfaceHit hit;
        if (!full->next_entry(o, d, kNoFacet, hit)) continue;
        auto in = refract(d, s.facets[hit.facet].plane.n, 1.0, kDiamondIndex);
        if (!in) continue;
        glm::dvec3 p = hit.point;
        glm::dvec3 dir = *in;
        std::uint32_t from = hit.facet;
        for (int k = 0; k < depth; ++k) {
            check(p, dir, from);
            SurfaceHit out;
            if (!full->next_exit(p, dir, from, out)) break;
            p = out.point;
            dir = reflect(dir, s.facets[out.facet].plane.n);
            from = out.facet;
        }
    }
    for (const Facet& f : s.facets) {
        for (std::size_t i = 0; i < f.loop.size(); ++i) {
            const glm::dvec3 a = s.vertices[f.loop[i]];
            const glm::dvec3 b = s.vertices[f.loop[(i + 1) % f.loop.size()]];
            for (double share : {0.0, 0.5, 1.0 / 3.0}) {
                const glm::dvec3 target = a + share * (b - a);
                const glm::dvec3 o = inside_point(s, rng);
                check(o, glm::normalize(target - o), kNoFacet);
            }
        }
    }
    for (std::uint32_t f = 0; f < s.facets.size(); ++f) {
        const auto& loop = s.facets[f].loop;
        const glm::dvec3 a = s.vertices[loop[0]];
        const glm::dvec3 b = s.vertices[loop[1]];
        for (const glm::dvec3& start : {a, 0.5 * (a + b)}) {
            for (int k = 0; k < 8; ++k) {
                const glm::dvec3 d = glm::normalize(inside_point(s, rng) - start);
                check(start, d, f);
            }
        }
    }
}

}  // namespace gem::test
