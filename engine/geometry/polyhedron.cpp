// stone_from_planes and triangulate_facets (stone_from_triangles lives in mesh_stone.cpp), and
// the cut builders' planes_that_make_facets, which shares the clipping.
//
// Half-spaces are intersected by clipping a box plane by plane. The clipped polyhedron keeps
// one shared vertex pool, and a cut edge gets one new vertex for both facets that share it,
// so the topology stays consistent however many planes pass through one point (a brilliant's
// culet or star tips meet 5 to 8 planes).

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>

#include "geometry/polyhedron.hpp"
#include "geometry/triangulate.hpp"

#include "geometry/cuts/cut_internal.hpp"

namespace gem {
namespace {

constexpr int kBoxFace = -1;

struct ClipFace {
    int plane = kBoxFace;  // index into the input planes, or kBoxFace
    std::vector<std::uint32_t> loop;
};

struct ClipSolid {
    std::vector<glm::dvec3> vertices;
    std::vector<ClipFace> faces;
};

// An axis-aligned box, loops counter-clockwise seen from outside. Vertex i has x from bit 0,
// y from bit 1 and z from bit 2.
ClipSolid make_box(const glm::dvec3& lo, const glm::dvec3& hi) {
    ClipSolid box;
    for (int i = 0; i < 8; ++i) {
        box.vertices.emplace_back((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y,
                                  (i & 4) ? hi.z : lo.z);
    }
    const std::uint32_t loops[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& loop : loops) box.faces.push_back({kBoxFace, {loop, loop + 4}});
    return box;
}

enum class ClipOutcome { cut, untouched, emptied, failed };

// Keeps the part of `solid` with plane.n·x <= plane.d (vertices within eps count as on the
// plane) and closes it with a cap facet tagged `plane_index`.
ClipOutcome clip(ClipSolid& solid, const Plane& plane, int plane_index, double eps) {
    std::vector<double> s(solid.vertices.size(), 0.0);
    bool any_out = false;
    bool any_in = false;
    for (const ClipFace& face : solid.faces) {
        for (std::uint32_t v : face.loop) {
            s[v] = plane.signed_distance(solid.vertices[v]);
            any_out = any_out || s[v] > eps;
            any_in = any_in || s[v] < -eps;
        }
    }
    if (!any_out) return ClipOutcome::untouched;
    if (!any_in) {
        solid.faces.clear();
        return ClipOutcome::emptied;
    }

    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> edge_vertex;
    std::set<std::pair<std::uint32_t, std::uint32_t>> in_plane;
    std::unordered_map<std::uint32_t, std::uint32_t> cap_next;
    auto on_plane = [&](std::uint32_t v) { return std::abs(s[v]) <= eps; };
    std::vector<ClipFace> kept;
    for (const ClipFace& face : solid.faces) {
        ClipFace out{face.plane, {}};
        const std::size_t n = face.loop.size();
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t a = face.loop[i];
            const std::uint32_t b = face.loop[(i + 1) % n];
            if (s[a] <= eps) out.loop.push_back(a);
            const bool crosses = (s[a] < -eps && s[b] > eps) || (s[a] > eps && s[b] < -eps);
            if (!crosses) continue;
            const auto key = std::minmax(a, b);
            auto it = edge_vertex.find(key);
            if (it == edge_vertex.end()) {
                const double t = s[a] / (s[a] - s[b]);
                solid.vertices.push_back(solid.vertices[a] +
                                         t * (solid.vertices[b] - solid.vertices[a]));
                s.push_back(0.0);
                it = edge_vertex.emplace(key, std::uint32_t(solid.vertices.size() - 1)).first;
            }
            out.loop.push_back(it->second);
        }
        // A facet left with no area, or lying within the plane (it was only a sliver beyond
        // it), gives way to the cap.
        if (out.loop.size() < 3 || std::all_of(out.loop.begin(), out.loop.end(), on_plane))
            continue;
        for (std::size_t i = 0; i < out.loop.size(); ++i) {
            const std::uint32_t p = out.loop[i];
            const std::uint32_t q = out.loop[(i + 1) % out.loop.size()];
            if (on_plane(p) && on_plane(q)) in_plane.insert({p, q});
        }
        kept.push_back(std::move(out));
    }
    solid.faces = std::move(kept);
    // An edge in the plane bounds the cap (traversed the other way) unless two kept facets
    // share it: a sliver edge that only round-off put within eps of the plane.
    for (const auto& [p, q] : in_plane) {
        if (in_plane.count({q, p}) == 0 && !cap_next.emplace(q, p).second) {
            return ClipOutcome::failed;
        }
    }

    if (cap_next.size() < 3) return ClipOutcome::cut;  // the plane only grazes an edge
    ClipFace cap{plane_index, {}};
    const std::uint32_t start = cap_next.begin()->first;
    std::uint32_t v = start;
    do {
        cap.loop.push_back(v);
        auto it = cap_next.find(v);
        if (it == cap_next.end() || cap.loop.size() > cap_next.size()) return ClipOutcome::failed;
        v = it->second;
    } while (v != start);
    if (cap.loop.size() != cap_next.size()) return ClipOutcome::failed;
    solid.faces.push_back(std::move(cap));
    return ClipOutcome::cut;
}

std::string plane_label(const std::vector<FacetPlane>& planes, std::size_t i) {
    std::string label = "plane #" + std::to_string(i);
    if (!planes[i].name.empty()) label += " ('" + planes[i].name + "')";
    return label;
}

Result<ClipSolid> clip_all(const std::vector<FacetPlane>& planes, const glm::dvec3& lo,
                           const glm::dvec3& hi, double eps) {
    ClipSolid solid = make_box(lo, hi);
    for (std::size_t i = 0; i < planes.size(); ++i) {
        switch (clip(solid, planes[i].plane, int(i), eps)) {
            case ClipOutcome::emptied:
                return Error{"half-spaces have an empty intersection (at " +
                             plane_label(planes, i) + ")"};
            case ClipOutcome::failed:
                return Error{"numerical failure clipping by " + plane_label(planes, i)};
            case ClipOutcome::cut:
            case ClipOutcome::untouched:
                break;
        }
    }
    for (const ClipFace& face : solid.faces) {
        if (face.plane == kBoxFace) return Error{"half-spaces do not bound a finite solid"};
    }
    return solid;
}

// Merges vertices closer than `tolerance` and renumbers the loops; drops unused vertices.
void weld(Stone& stone, double tolerance) {
    std::vector<std::uint32_t> remap(stone.vertices.size(), UINT32_MAX);
    std::vector<glm::dvec3> welded;
    for (Facet& facet : stone.facets) {
        std::vector<std::uint32_t> loop;
        for (std::uint32_t v : facet.loop) {
            if (remap[v] == UINT32_MAX) {
                const glm::dvec3& p = stone.vertices[v];
                auto same = std::find_if(welded.begin(), welded.end(), [&](const glm::dvec3& q) {
                    return glm::length(p - q) <= tolerance;
                });
                remap[v] = std::uint32_t(same - welded.begin());
                if (same == welded.end()) welded.push_back(p);
            }
            if (loop.empty() || loop.back() != remap[v]) loop.push_back(remap[v]);
        }
        while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
        facet.loop = std::move(loop);
    }
    stone.vertices = std::move(welded);
}

// Clips in two passes: a first in a huge box finds out whether the solid is bounded and how
// big it is; a second in a snug box gives tolerances relative to the stone's own size.
Result<ClipSolid> intersect(const std::vector<FacetPlane>& planes, double& size) {
    double reach = 0.0;
    for (const FacetPlane& fp : planes) {
        assert(std::abs(glm::length(fp.plane.n) - 1.0) < 1e-9);
        reach = std::max(reach, std::abs(fp.plane.d));
    }
    if (planes.size() < 4 || reach == 0.0) {
        return Error{"half-spaces do not bound a solid of positive volume"};
    }
    const double far = 1e3 * reach;
    auto rough = clip_all(planes, glm::dvec3(-far), glm::dvec3(far), 1e-12 * far);
    if (!rough) return rough;
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const ClipFace& face : rough.value().faces) {
        for (std::uint32_t v : face.loop) {
            lo = glm::min(lo, rough.value().vertices[v]);
            hi = glm::max(hi, rough.value().vertices[v]);
        }
    }
    size = glm::length(hi - lo);
    const glm::dvec3 margin(0.25 * size);
    return clip_all(planes, lo - margin, hi + margin, 1e-11 * size);
}

}  // namespace

Result<Stone> stone_from_planes(const std::vector<FacetPlane>& planes, std::string name) {
    double size = 0.0;
    auto clipped = intersect(planes, size);
    if (!clipped) return Error{"'" + name + "': " + clipped.error()};
    ClipSolid& solid = clipped.value();

    Stone stone;
    stone.name = std::move(name);
    stone.vertices = std::move(solid.vertices);
    stone.facets.resize(planes.size());
    std::vector<int> seen(planes.size(), 0);
    for (ClipFace& face : solid.faces) {
        Facet& facet = stone.facets[std::size_t(face.plane)];
        facet.loop = std::move(face.loop);
        ++seen[std::size_t(face.plane)];
    }
    weld(stone, 1e-10 * size);
    for (std::size_t i = 0; i < planes.size(); ++i) {
        Facet& facet = stone.facets[i];
        facet.plane = planes[i].plane;
        facet.kind = planes[i].kind;
        facet.name = planes[i].name;
        if (seen[i] != 1 || loop_area(stone.vertices, facet.loop) <= 1e-10 * size * size) {
            return Error{"'" + stone.name + "': " + plane_label(planes, i) +
                         " makes no facet (redundant or duplicate plane)"};
        }
    }
    stone.convex = true;
    triangulate_facets(stone);
    return stone;
}

namespace cuts {

Result<std::vector<FacetPlane>> planes_that_make_facets(const std::vector<FacetPlane>& planes) {
    double size = 0.0;
    auto clipped = intersect(planes, size);
    if (!clipped) return Error{clipped.error()};
    std::vector<bool> keep(planes.size(), false);
    for (const ClipFace& face : clipped.value().faces) {
        const double area = loop_area(clipped.value().vertices, face.loop);
        keep[std::size_t(face.plane)] = area > 1e-10 * size * size;
    }
    std::vector<FacetPlane> kept;
    for (std::size_t i = 0; i < planes.size(); ++i) {
        if (keep[i]) kept.push_back(planes[i]);
    }
    return kept;
}

}  // namespace cuts

void triangulate_facets(Stone& stone) {
    stone.triangles.clear();
    std::vector<std::array<std::uint32_t, 3>> triangles;
    for (std::size_t f = 0; f < stone.facets.size(); ++f) {
        triangles.clear();
        triangulate_polygon(stone.vertices, stone.facets[f].loop, stone.facets[f].plane.n,
                            triangles);
        for (const auto& t : triangles) stone.triangles.push_back({t, std::uint32_t(f)});
    }
}

}  // namespace gem
