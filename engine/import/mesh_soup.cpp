#include "import/mesh_soup.hpp"

#include "geometry/polyhedron.hpp"
#include "import/default_material.hpp"
#include "import/import_text.hpp"

namespace gem::import {

Result<Stone> stone_from_soup(const std::filesystem::path& path, const TriangleSoup& soup,
                              double weld_tolerance) {
    if (soup.triangles.empty()) return file_error(path, "no triangles in the file");
    auto stone =
        stone_from_triangles(soup.positions, soup.triangles, path.stem().string(), weld_tolerance);
    if (!stone) return file_error(path, stone.error());
    stone.value().material = crown_glass();
    return stone;
}

}  // namespace gem::import
