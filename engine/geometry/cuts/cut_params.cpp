// Cut names, customary parameters and their allowed ranges.

#include <array>
#include <cctype>
#include <string>

#include "geometry/cuts.hpp"

namespace gem {
namespace {

struct ShapeName {
    CutShape shape;
    const char* canonical;
    std::array<const char*, 3> aliases;
};

constexpr ShapeName kShapeNames[] = {
    {CutShape::round_brilliant, "round-brilliant", {"round", "brilliant", "round_brilliant"}},
    {CutShape::princess, "princess", {"square", "square-brilliant", ""}},
    {CutShape::emerald, "emerald", {"step", "emerald-cut", ""}},
    {CutShape::oval, "oval", {"", "", ""}},
    {CutShape::marquise, "marquise", {"navette", "", ""}},
    {CutShape::pear, "pear", {"teardrop", "pear-shape", ""}},
    {CutShape::heart, "heart", {"", "", ""}},
    {CutShape::cushion, "cushion", {"", "", ""}},
};

}  // namespace

std::optional<CutShape> parse_cut_shape(std::string_view name) {
    std::string lower;
    for (char c : name) lower.push_back(char(std::tolower(static_cast<unsigned char>(c))));
    for (const ShapeName& entry : kShapeNames) {
        if (lower == entry.canonical) return entry.shape;
        for (const char* alias : entry.aliases) {
            if (*alias != '\0' && lower == alias) return entry.shape;
        }
    }
    return std::nullopt;
}

const char* to_string(CutShape shape) {
    for (const ShapeName& entry : kShapeNames) {
        if (entry.shape == shape) return entry.canonical;
    }
    return "unknown";
}

CutParams default_cut_params(CutShape shape) {
    CutParams p;  // Tolkowsky's round brilliant (see cuts.hpp)
    p.shape = shape;
    // Typical length-to-width ratios of fancy shapes as quoted in the trade; angles stay
    // Tolkowsky's except for the step cut.
    switch (shape) {
        case CutShape::round_brilliant:
        case CutShape::princess:
        case CutShape::cushion:
        case CutShape::heart:
            p.length_to_width = 1.0;
            break;
        case CutShape::oval:
            p.length_to_width = 1.35;
            break;
        case CutShape::marquise:
            p.length_to_width = 2.0;
            break;
        case CutShape::pear:
            p.length_to_width = 1.6;
            break;
        case CutShape::emerald:
            p.length_to_width = 1.4;
            p.table_pct = 60.0;
            p.crown_angle_deg = 35.0;
            p.pavilion_angle_deg = 42.0;
            break;
    }
    return p;
}

}  // namespace gem
