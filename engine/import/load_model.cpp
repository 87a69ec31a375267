// load_model: picks the reader, then moves the stone into the stone frame (docs/design.md,
// "Contracts": y up through the table, girdle in the xz plane, centred on the girdle centre,
// millimetres).

#include "import/load_model.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "import/default_material.hpp"
#include "import/import_text.hpp"

namespace gem {
namespace {

enum class Format { obj, stl, asc3ds, gemcad, unknown };

// Whether one of the first lines starts with `keyword`, as a prefix of its first word or as
// the whole first word.
bool has_line_keyword(std::string_view text, std::string_view keyword, bool whole_word) {
    import::LineCursor cursor(text);
    std::string_view line;
    for (int n = 0; n < 200 && cursor.next(line); ++n) {
        const auto tokens = import::split_tokens(line);
        if (tokens.empty()) continue;
        if (whole_word ? tokens[0] == keyword : import::istarts_with(tokens[0], keyword)) {
            return true;
        }
    }
    return false;
}

// Content first (it cannot lie), then the extension; ".asc" is both GemCad and 3D Studio.
Format detect(const std::filesystem::path& path, std::string_view bytes) {
    std::string_view head = bytes.substr(0, 1 << 16);
    if (head.substr(0, 3) == "\xEF\xBB\xBF") head.remove_prefix(3);
    const std::size_t first = head.find_first_not_of(" \t\r\n");
    const std::string_view start = first == std::string_view::npos ? "" : head.substr(first);
    if (import::istarts_with(start, "GemCad")) return Format::gemcad;
    if (has_line_keyword(head, "Named", false) || has_line_keyword(head, "Tri-mesh", false)) {
        return Format::asc3ds;
    }
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".obj") return Format::obj;
    if (ext == ".stl") return Format::stl;
    if (import::istarts_with(start, "solid")) return Format::stl;
    if (has_line_keyword(head, "v", true) && has_line_keyword(head, "f", true)) return Format::obj;
    if (bytes.size() >= 84) {
        const auto* b = reinterpret_cast<const unsigned char*>(bytes.data() + 80);
        const std::uint64_t count = b[0] | b[1] << 8 | b[2] << 16 | std::uint64_t(b[3]) << 24;
        if (bytes.size() == 84 + 50 * count) return Format::stl;
    }
    return Format::unknown;
}

// Moves `centre` to the origin, then scales by `scale`: points, planes and nothing else, since
// loops and triangles are indices. Symmetry about the y axis survives a shift along y.
void shift_and_scale(Stone& stone, const glm::dvec3& centre, double scale) {
    for (auto& v : stone.vertices) v = scale * (v - centre);
    for (auto& f : stone.facets) f.plane.d = scale * (f.plane.d - glm::dot(f.plane.n, centre));
}

// 3D Studio's world is z-up; the stone frame is y-up. A rotation of −90° about x keeps the
// handedness and so the winding.
void z_up_to_y_up(Stone& stone) {
    auto turn = [](const glm::dvec3& p) { return glm::dvec3(p.x, p.z, -p.y); };
    for (auto& v : stone.vertices) v = turn(v);
    for (auto& f : stone.facets) f.plane.n = turn(f.plane.n);
}

}  // namespace

Result<Stone> load_model(const std::filesystem::path& path, const ImportOptions& options) {
    if (!(options.width_mm >= 0.0) || !std::isfinite(options.width_mm)) {
        return Error{"width_mm: must be zero or a positive number of millimetres"};
    }
    auto bytes = import::read_whole_file(path);
    if (!bytes) return Error{bytes.error()};
    if (bytes.value().find_first_not_of(" \t\r\n") == std::string::npos) {
        return import::file_error(path, "empty file");
    }
    const Format format = detect(path, bytes.value());
    Result<Stone> loaded = Error{""};
    switch (format) {
        case Format::obj:
            loaded = load_obj(path);
            break;
        case Format::stl:
            loaded = load_stl(path);
            break;
        case Format::asc3ds:
            loaded = load_3ds_ascii(path);
            break;
        case Format::gemcad:
            loaded = load_gemcad(path);
            break;
        case Format::unknown:
            return import::file_error(path,
                                      "unknown model format (expected Wavefront OBJ, STL, "
                                      "3D Studio ASCII or a GemCad design)");
    }
    if (!loaded) return loaded;
    Stone& stone = loaded.value();
    if (format == Format::asc3ds) z_up_to_y_up(stone);

    glm::dvec3 lo(HUGE_VAL), hi(-HUGE_VAL);
    for (const auto& v : stone.vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    glm::dvec3 centre = 0.5 * (lo + hi);
    // A design's girdle centre: on its axis, halfway up the girdle facets.
    const bool has_girdle = std::any_of(stone.facets.begin(), stone.facets.end(),
                                        [](const Facet& f) { return f.kind == FacetKind::girdle; });
    if (format == Format::gemcad && has_girdle) {
        double y_lo = HUGE_VAL, y_hi = -HUGE_VAL;
        for (const Facet& f : stone.facets) {
            if (f.kind != FacetKind::girdle) continue;
            for (std::uint32_t i : f.loop) {
                y_lo = std::min(y_lo, stone.vertices[i].y);
                y_hi = std::max(y_hi, stone.vertices[i].y);
            }
        }
        centre = glm::dvec3(0.0, 0.5 * (y_lo + y_hi), 0.0);
    }
    // Width: the larger extent in the girdle (xz) plane.
    const double width = std::max(hi.x - lo.x, hi.z - lo.z);
    const double scale = options.width_mm > 0.0 ? options.width_mm / width : 1.0;
    shift_and_scale(stone, centre, scale);

    if (options.material) {
        stone.material = *options.material;
    } else if (format != Format::gemcad) {
        stone.material = import::crown_glass();
    }
    return loaded;
}

}  // namespace gem
