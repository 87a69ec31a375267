// gemtables verify: every checksum, then a random sample of pixels re-traced with the exact
// tracer and compared with what the database stores, against the format's quantisation
// bounds (gemdb/quantise.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "commands.hpp"
#include "gemdb/quantise.hpp"
#include "gemdb/reader.hpp"
#include "view_trace.hpp"

namespace gem::tables {

namespace {

// The decoded arrays are floats: converting a quantised value to float adds up to 2^-24
// relative (a few 1e-8 rad on a unit direction), so the bounds allow that much on top.
constexpr double kFloatRelative = 1.0 / 16777216.0;
constexpr double kAngleBound = kOctahedralMaxAngle + 1e-6;

struct Errors {
    std::uint64_t pixels = 0;
    std::uint64_t rays = 0;
    std::uint64_t structure = 0;  // hit or ray count differs
    std::uint64_t over_bound = 0;
    double angle = 0.0;            // radians
    double weight_relative = 0.0;  // weights ≥ the smallest normal half
    double weight_absolute = 0.0;  // weights below it
    double path_relative = 0.0;
    double position = 0.0;  // share of the per-axis bound used
};

// Half-precision check of a stored value against the exact one; records the error.
bool check_half(double stored, double exact, Errors& e, bool weight) {
    const double error = std::abs(stored - exact);
    if (std::abs(exact) >= kHalfMinNormal) {
        const double relative = error / std::abs(exact);
        if (weight) e.weight_relative = std::max(e.weight_relative, relative);
        if (!weight) e.path_relative = std::max(e.path_relative, relative);
        return relative <= kHalfMaxRelativeError + 2.0 * kFloatRelative;
    }
    if (weight) e.weight_absolute = std::max(e.weight_absolute, error);
    return error <= kHalfMaxSubnormalError + kFloatRelative * kHalfMinNormal;
}

bool check_ray(const DecodedView& view, std::uint32_t i, const TracedRay& exact,
               const PositionBox& box, Errors& e) {
    ++e.rays;
    bool ok = true;
    const glm::dvec3 stored = glm::normalize(glm::dvec3(view.direction[i]));
    // atan2 of |cross| and dot stays accurate for tiny angles, where acos does not.
    const double angle = std::atan2(glm::length(glm::cross(stored, exact.direction)),
                                    glm::dot(stored, exact.direction));
    e.angle = std::max(e.angle, angle);
    ok &= angle <= kAngleBound;
    ok &= check_half(view.weight[i], exact.weight, e, true);
    ok &= check_half(view.path_mm[i], exact.path_mm, e, false);
    const glm::dvec3 bound = box.max_error();
    for (int axis = 0; axis < 3; ++axis) {
        const double p = glm::clamp(exact.origin[axis], box.min[axis], box.max[axis]);
        const double error = std::abs(view.position[i][axis] - p);
        const double allowed = bound[axis] + kFloatRelative * (std::abs(p) + 1.0);
        e.position = std::max(e.position, error / bound[axis]);
        ok &= error <= allowed;
    }
    ok &= view.bounces[i] == exact.bounces && view.facet[i] == exact.facet;
    return ok;
}

void check_pixel(const DecodedView& view, std::uint32_t pixel, const RayList& exact,
                 double threshold, const PositionBox& box, Errors& e) {
    ++e.pixels;
    const std::uint32_t count = view.ray_count[pixel];
    std::vector<const TracedRay*> kept;
    double dropped = 0.0;
    if (exact.hit) {
        kept.push_back(&exact.reflected);
        for (const TracedRay& r : exact.exits) {
            if (r.weight >= threshold) {
                kept.push_back(&r);
            } else {
                dropped += r.weight;
            }
        }
    }
    if (count != kept.size()) {
        ++e.structure;
        return;
    }
    if (count == 0) return;
    bool ok = check_half(view.truncated_weight[pixel], exact.truncated_weight + dropped, e, true);
    for (std::uint32_t k = 0; k < count; ++k) {
        ok &= check_ray(view, view.ray_offset[pixel] + k, *kept[k], box, e);
    }
    if (!ok) ++e.over_bound;
}

}  // namespace

int run_verify(const VerifyOptions& o) {
    Result<Database> opened = Database::open(o.database);
    if (!opened) return fail(opened.error());
    const Database& db = opened.value();
    const std::uint32_t views = db.view_count();
    const std::uint32_t levels = db.level_count();

    // The sample is drawn up front, so each table is decoded once for both checks.
    std::mt19937_64 rng(o.seed);
    std::vector<std::vector<std::uint64_t>> picks(std::size_t{views} * levels);
    for (std::uint32_t s = 0; s < o.samples; ++s) {
        const std::uint64_t chunk = rng() % picks.size();
        picks[chunk].push_back(rng());
    }

    const ViewTracer tracer(db.stone(), db.camera(), db.grid(), db.params());
    std::uint64_t damaged = 0;
    Errors e;
    RayList exact;
    for (std::uint32_t v = 0; v < views; ++v) {
        for (std::uint32_t l = 0; l < levels; ++l) {
            Result<DecodedView> decoded = db.decode(v, l);
            if (!decoded) {
                if (++damaged <= 10)
                    std::fprintf(stderr, "gemtables: %s\n", decoded.error().c_str());
                continue;
            }
            const DecodedView& view = decoded.value();
            const std::uint32_t side = view.side;
            for (std::uint64_t pick : picks[std::size_t{v} * levels + l]) {
                const auto pixel = static_cast<std::uint32_t>(pick % (std::uint64_t{side} * side));
                tracer.trace_pixel(v, side, pixel % side, pixel / side, exact);
                check_pixel(view, pixel, exact, db.params().weight_threshold, db.position_box(), e);
            }
        }
    }

    std::printf("gemtables: %s: %u tables checked, %llu damaged\n", o.database.c_str(),
                views * levels, static_cast<unsigned long long>(damaged));
    std::printf(
        "gemtables: re-traced %llu pixels (%llu rays, seed %llu): %llu with another "
        "ray count, %llu over the bounds\n",
        static_cast<unsigned long long>(e.pixels), static_cast<unsigned long long>(e.rays),
        static_cast<unsigned long long>(o.seed), static_cast<unsigned long long>(e.structure),
        static_cast<unsigned long long>(e.over_bound));
    std::printf(
        "gemtables: largest direction error %.3g rad (bound %.3g), weight %.3g relative "
        "(bound %.3g) / %.3g absolute below %.3g, path %.3g relative, position %.2f of "
        "its bound\n",
        e.angle, kOctahedralMaxAngle, e.weight_relative, kHalfMaxRelativeError, e.weight_absolute,
        kHalfMinNormal, e.path_relative, e.position);
    if (damaged > 0) return fail(o.database + ": " + std::to_string(damaged) + " damaged tables");
    if (e.structure > 0 || e.over_bound > 0) {
        return fail(o.database +
                    ": stored rays differ from the exact tracer beyond the "
                    "quantisation bounds");
    }
    std::printf("gemtables: %s: OK\n", o.database.c_str());
    return 0;
}

}  // namespace gem::tables
