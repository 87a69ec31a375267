#pragma once
// Model import: Wavefront OBJ, STL (ASCII and binary), 3D Studio ASCII (.asc) meshes and
// GemCad text designs (.asc with a "GemCad" header). Errors name the file and the line,
// e.g. "SRB.asc:9: tier angle 'x' is not a number".

#include <filesystem>
#include <optional>
#include <string_view>

#include "geometry/stone.hpp"
#include "util/result.hpp"

namespace gem {

struct ImportOptions {
    // The stone's material. When absent: a GemCad design gets a constant-index material from
    // its "I" line; a mesh gets crown glass.
    std::optional<Material> material;
    // Scale so the girdle (for meshes: the largest extent in the xz plane) is this wide in mm;
    // 0 keeps the file's own units as millimetres.
    double width_mm = 0.0;
};

// Chooses the format by content (a "GemCad" first line, "solid"/binary STL, "Named object"
// for 3D Studio ASCII) and extension (.obj, .stl). The stone is moved into the stone frame
// (centred on the girdle centre, or the bounding-box centre for a mesh without a girdle).
Result<Stone> load_model(const std::filesystem::path& path, const ImportOptions& options = {});

// The format readers, in the file's own units and frame (load_model normalises).
Result<Stone> load_obj(const std::filesystem::path& path);
Result<Stone> load_stl(const std::filesystem::path& path);
Result<Stone> load_3ds_ascii(const std::filesystem::path& path);
Result<Stone> load_gemcad(const std::filesystem::path& path);  // material from its "I" line
// The same from bytes already in memory; `path` names them in errors (the fuzz targets'
// entries).
Result<Stone> parse_obj(std::string_view text, const std::filesystem::path& path);
Result<Stone> parse_stl(std::string_view bytes, const std::filesystem::path& path);
Result<Stone> parse_3ds_ascii(std::string_view text, const std::filesystem::path& path);
Result<Stone> parse_gemcad(std::string_view text, const std::filesystem::path& path);

}  // namespace gem
