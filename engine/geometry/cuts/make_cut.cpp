// make_cut: checks the parameters, builds the shape's facet planes and sets material and
// symmetry.

#include <cmath>
#include <optional>
#include <sstream>

#include "geometry/cuts/cut_internal.hpp"

namespace gem {
namespace {

struct Range {
    double lo, hi;
};

// The ranges are where every shape still comes out with all its facets (checked by the
// tests at the corners of the ranges) and that cover what the trade grades.
std::optional<Error> out_of_range(const char* field, double value, Range r) {
    if (std::isfinite(value) && value >= r.lo && value <= r.hi) return std::nullopt;
    std::ostringstream text;
    text << "cut parameter '" << field << "' = " << value << " is out of range [" << r.lo << ", "
         << r.hi << "]";
    return Error{text.str()};
}

Range length_to_width_range(CutShape shape) {
    switch (shape) {
        case CutShape::round_brilliant:
            return {1.0, 1.0};
        case CutShape::princess:
        case CutShape::cushion:
            return {1.0, 1.5};
        case CutShape::oval:
            return {1.05, 2.0};
        case CutShape::marquise:
            return {1.6, 2.6};
        case CutShape::pear:
            return {1.3, 2.0};
        case CutShape::emerald:
            return {1.0, 2.0};
        case CutShape::heart:
            return {0.9, 1.2};
    }
    return {1.0, 1.0};
}

std::optional<Error> check(const CutParams& p) {
    const std::pair<const char*, std::pair<double, Range>> fields[] = {
        {"width_mm", {p.width_mm, {0.5, 100.0}}},
        {"length_to_width", {p.length_to_width, length_to_width_range(p.shape)}},
        {"table_pct", {p.table_pct, {45.0, 70.0}}},
        {"crown_angle_deg", {p.crown_angle_deg, {20.0, 45.0}}},
        {"pavilion_angle_deg", {p.pavilion_angle_deg, {30.0, 56.0}}},
        {"girdle_pct", {p.girdle_pct, {1.0, 6.0}}},
        {"star_pct", {p.star_pct, {35.0, 65.0}}},
        {"lower_girdle_pct", {p.lower_girdle_pct, {60.0, 90.0}}},
        {"culet_pct", {p.culet_pct, {0.0, 8.0}}},
    };
    for (const auto& [field, value_range] : fields) {
        if (auto error = out_of_range(field, value_range.first, value_range.second)) return error;
    }
    return std::nullopt;
}

// The brief's girdle is g thick at the main facets; between them the outline bulges beyond
// the upper and lower girdles' chords, so a thin girdle can close to a knife edge there and
// some girdle facets vanish. That is a real (if poor) girdle, not a broken design, so those
// girdle planes are dropped; any other vanishing plane is still an error naming it.
Result<Stone> stone_from_pattern(const std::vector<FacetPlane>& planes, const char* name) {
    auto kept = cuts::planes_that_make_facets(planes);
    if (!kept) return Error{std::string("'") + name + "': " + kept.error()};
    std::size_t girdle_dropped = 0;
    for (const FacetPlane& fp : planes) girdle_dropped += fp.kind == FacetKind::girdle;
    for (const FacetPlane& fp : kept.value()) girdle_dropped -= fp.kind == FacetKind::girdle;
    if (planes.size() - kept.value().size() != girdle_dropped)
        return stone_from_planes(planes, name);
    return stone_from_planes(kept.value(), name);
}

Result<Stone> build(const CutParams& p) {
    const double w = p.width_mm;
    const double length = p.length_to_width * w;
    const int samples = p.faceted_girdle ? 32 : 128;
    switch (p.shape) {
        case CutShape::round_brilliant:
            return stone_from_pattern(
                cuts::brilliant_planes(cuts::round_outline(w / 2), samples, p), "round");
        case CutShape::oval:
            return stone_from_pattern(
                cuts::brilliant_planes(cuts::oval_outline(length, w), samples, p), "oval");
        case CutShape::marquise:
            return stone_from_pattern(
                cuts::brilliant_planes(cuts::marquise_outline(length, w), samples, p), "marquise");
        case CutShape::pear:
            return stone_from_pattern(
                cuts::brilliant_planes(cuts::pear_outline(length, w), samples, p), "pear");
        case CutShape::cushion:
            return stone_from_pattern(
                cuts::brilliant_planes(cuts::cushion_outline(length, w), samples, p), "cushion");
        case CutShape::princess: {
            const cuts::Outline table = cuts::cushion_outline(length, w);
            return stone_from_pattern(
                cuts::brilliant_planes(cuts::princess_outline(length, w), samples, p, &table),
                "princess");
        }
        case CutShape::emerald:
            return cuts::make_emerald(p);
        case CutShape::heart:
            return cuts::make_heart(p);
    }
    return Error{"unknown cut shape"};
}

std::vector<glm::dmat3> symmetry(const CutParams& p) {
    const bool square = p.length_to_width == 1.0;
    switch (p.shape) {
        case CutShape::round_brilliant:
            return cuts::cnv_group(8);
        case CutShape::princess:
        case CutShape::cushion:
            return cuts::cnv_group(square ? 4 : 2);
        case CutShape::oval:
        case CutShape::marquise:
        case CutShape::emerald:
            return cuts::cnv_group(2);
        case CutShape::pear:
            return cuts::mirror_group({0.0, 0.0, 1.0});  // the length axis x lies in the mirror
        case CutShape::heart:
            return cuts::mirror_group({1.0, 0.0, 0.0});  // halves glued across x = 0
    }
    return {glm::dmat3(1.0)};
}

}  // namespace

Result<Stone> make_cut(const CutParams& params, const Material& material) {
    if (auto error = check(params)) return *error;
    Result<Stone> stone = build(params);
    if (!stone) {
        return Error{std::string("cannot build a ") + to_string(params.shape) +
                     " cut: " + stone.error()};
    }
    Stone& s = stone.value();
    s.name = to_string(params.shape);
    s.material = material;
    s.symmetry = symmetry(params);
    return stone;
}

}  // namespace gem
