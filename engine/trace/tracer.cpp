// The ray tree of one pixel ray. The entry facet splits the ray into the first reflection
// (RayList.reflected) and the refracted ray inside. Every facet hit inside splits a branch
// into an internal reflection, which is followed, and a refracted exit ray, which is recorded
// (in a convex stone it cannot meet the stone again). In a non-convex stone an exit ray is
// followed outside too: if it meets the stone again (the heart's cleft) it splits once more
// into an outside reflection and a refraction back in. Branches live on a small fixed stack:
// no recursion and no allocation beyond out.exits' reused capacity.
// The first reflection is stored as it leaves the entry facet and not followed further, even
// where a non-convex stone is in its way: the thesis' ray-list has exactly one such ray.
// Depth counts every segment between two surface points, inside or (in a cleft) outside.

#include "trace/tracer.hpp"

#include <array>
#include <cassert>

#include "optics/fresnel.hpp"
#include "trace/intersector.hpp"

namespace gem {
namespace {

struct Branch {
    glm::dvec3 origin;
    glm::dvec3 direction;
    double weight;
    double path_mm;
    std::uint32_t facet;  // facet the branch starts on
    int depth;            // segments followed so far, this one included
    std::uint16_t bounces;
    bool inside;
};

// A convex stone keeps one branch at a time; only re-entries into a non-convex one branch out.
constexpr int kMaxBranches = 64;

struct Split {
    double reflected;    // weight share that reflects
    double transmitted;  // weight share that refracts through
};

// Weights of an interaction at incidence cosine cos_i from index n1 into n2. Total internal
// reflection keeps everything in both models.
Split split_weight(double cos_i, double n1, double n2, const TraceSettings& settings) {
    const double r = fresnel_reflectance(cos_i, n1, n2);
    if (r >= 1.0) return {1.0, 0.0};
    if (settings.weights == WeightModel::thesis_factors) {
        return {settings.r_factor, settings.t_factor};
    }
    return {r, 1.0 - r};
}

}  // namespace

Tracer::Tracer(const Stone& stone) : stone_(&stone), intersector_(make_intersector(stone)) {}
Tracer::~Tracer() = default;
Tracer::Tracer(Tracer&&) noexcept = default;
Tracer& Tracer::operator=(Tracer&&) noexcept = default;

void Tracer::trace(const Ray& ray, double ior, const TraceSettings& settings, RayList& out) const {
    out.clear();
    const Intersector& surface = *intersector_;
    const std::vector<Facet>& facets = stone_->facets;
    constexpr double kAir = 1.0;

    SurfaceHit hit;
    if (!surface.next_entry(ray.origin, ray.direction, kNoFacet, hit)) return;
    out.hit = true;

    const glm::dvec3& entry_normal = facets[hit.facet].plane.n;
    const Split entry = split_weight(-glm::dot(ray.direction, entry_normal), kAir, ior, settings);
    out.reflected = {hit.point, reflect(ray.direction, entry_normal), entry.reflected, 0.0, 0,
                     hit.facet};

    std::array<Branch, kMaxBranches> stack;
    int top = 0;
    auto push = [&](const Branch& branch) {
        if (branch.weight <= 0.0) return;
        if (top == kMaxBranches) {
            out.truncated_weight += branch.weight;
            return;
        }
        stack[top++] = branch;
    };
    auto record_exit = [&](const Branch& b) {
        if (b.weight < settings.min_weight) {
            out.truncated_weight += b.weight;
            return;
        }
        out.exits.push_back({b.origin, b.direction, b.weight, b.path_mm, b.bounces, b.facet});
    };

    const std::optional<glm::dvec3> refracted = refract(ray.direction, entry_normal, kAir, ior);
    if (refracted) {
        push({hit.point, *refracted, entry.transmitted, 0.0, hit.facet, 1, 0, true});
    }

    while (top > 0) {
        const Branch b = stack[--top];
        if (b.weight < settings.min_weight || b.depth > settings.max_depth) {
            out.truncated_weight += b.weight;
            continue;
        }
        if (!b.inside) {
            // Only non-convex stones push outside branches: does the exit ray come back?
            if (!surface.next_entry(b.origin, b.direction, b.facet, hit)) {
                record_exit(b);
                continue;
            }
            const glm::dvec3& n = facets[hit.facet].plane.n;
            const Split s = split_weight(-glm::dot(b.direction, n), kAir, ior, settings);
            push({hit.point, reflect(b.direction, n), b.weight * s.reflected, b.path_mm, hit.facet,
                  b.depth + 1, b.bounces, false});
            if (const auto in = refract(b.direction, n, kAir, ior)) {
                push({hit.point, *in, b.weight * s.transmitted, b.path_mm, hit.facet, b.depth + 1,
                      b.bounces, true});
            }
            continue;
        }
        if (!surface.next_exit(b.origin, b.direction, b.facet, hit)) {
            // A closed solid always has an exit ahead of a ray inside it.
            assert(false && "ray lost inside the stone");
            out.truncated_weight += b.weight;
            continue;
        }
        const glm::dvec3& n = facets[hit.facet].plane.n;
        const double path = b.path_mm + hit.t;
        const Split s = split_weight(glm::dot(b.direction, n), ior, kAir, settings);
        // The reflection goes on the stack first so that, in a non-convex stone, the exit
        // branch is resolved next and the stack stays shallow however deep the tree.
        const auto bounces = static_cast<std::uint16_t>(b.bounces + 1);
        push({hit.point, reflect(b.direction, n), b.weight * s.reflected, path, hit.facet,
              b.depth + 1, bounces, true});
        if (s.transmitted > 0.0) {
            if (const auto out_dir = refract(b.direction, -n, ior, kAir)) {
                const Branch leaving{hit.point, *out_dir,  b.weight * s.transmitted,
                                     path,      hit.facet, b.depth,
                                     b.bounces, false};
                if (surface.can_reenter()) {
                    push(leaving);
                } else {
                    record_exit(leaving);
                }
            }
        }
    }
}

}  // namespace gem
