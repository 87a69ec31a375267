#pragma once
// Metal from a Wavefront OBJ: a ring drawn in CAD, in millimetres, in the frame of the stone or
// piece it carries. v, vn and f statements (f: v, v/vt, v//vn, v/vt/vn; polygons fanned);
// vertex normals are taken from vn or, without them, averaged from the faces around each
// vertex. Errors name the file and the line.

#include <filesystem>
#include <string_view>

#include "piece/metal.hpp"
#include "piece/metal_mesh.hpp"
#include "util/result.hpp"

namespace gem {

Result<MetalMesh> load_metal_obj(const std::filesystem::path& path, Metal metal, double roughness);
// The same from text in memory; `path` names it in errors (the fuzz target's entry).
Result<MetalMesh> parse_metal_obj(std::string_view text, const std::filesystem::path& path,
                                  Metal metal, double roughness);

}  // namespace gem
