#pragma once
// One row per measured point: what was rendered (scene, view, method and every setting),
// what it cost and how far it is from the reference. Written as CSV and printed as a table.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "picture/image.hpp"
#include "picture/image_error.hpp"
#include "util/result.hpp"

namespace gem::accuracy {

struct Row {
    std::string study;  // which sweep: base, level, spacing, blend, depth, threshold, ...
    std::string scene;
    std::string view;         // on, between, path
    double offset_deg = 0.0;  // asked direction to the nearest stored view (table); else to the
                              // base database's nearest
    std::string method;       // table, trace, phong, reference
    // Settings: table level/spacing/blend; depth and threshold of the table, trace or
    // reference; dispersion (table) or spectral (reference); reference samples per pixel.
    int level = 0;
    double spacing_deg = 0.0;
    bool blend = false;
    double blend_weight = 1.0;  // table: the nearest view's weight in the frame (1 unless blend)
    int depth = 0;
    double threshold = 0.0;
    bool dispersion = false;
    int samples = 1;
    std::string compared_with = "reference";
    // Cost.
    double frame_ms = 0.0;
    std::uint64_t db_bytes = 0;
    double build_s = 0.0;
    // Error (only_stone, see docs/accuracy.md) against `compared_with`, and against the same
    // deep reference traced at n(D) only (no dispersion): what is left when fire is set aside.
    ImageError error;
    ImageError error_nd;
    bool has_nd = false;
};

// Errors over the stone's pixels: `mask` (row-major, > 0.5 = compare) is written into both
// images' alpha, so compare_images' only_stone uses exactly it.
Result<ImageError> stone_error(Image test, Image reference, const std::vector<float>& mask);

Result<bool> write_csv(const std::vector<Row>& rows, const std::filesystem::path& path);
void print_header();
void print_row(const Row& row);

}  // namespace gem::accuracy
