#pragma once
// Seeds for the OBJ, STL and 3D Studio ASCII readers' fuzz targets: real cuts (a round
// brilliant with a faceted girdle, a heart) written as CAD tools write them (an OBJ with
// groups, materials and v/vt/vn n-gons, and one with relative indices; ASCII STL with CRLF
// and e-notation; binary STL whose header starts with "solid"; 3ds Max's ASCII export).

#include <filesystem>

namespace gem::fuzz {

// Writes the seeds into `dir`; how many, or -1 when a cut could not be made.
int write_model_seeds(const std::filesystem::path& dir);

}  // namespace gem::fuzz
