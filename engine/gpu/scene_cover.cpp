#include "gpu/scene_cover.hpp"

#include <cmath>
#include <unordered_map>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "picture/camera.hpp"
#include "piece/metal_mesh.hpp"

namespace gem::gpu {

std::vector<CoverBox> metal_cover_boxes(const MetalMesh& mesh, double cell_mm) {
    // A metal of no extent (every vertex at the centre) still has cells to fall in.
    if (!(cell_mm > 1e-6)) cell_mm = 1.0;
    std::vector<CoverBox> boxes;
    std::unordered_map<std::uint64_t, std::size_t> cell_box;
    const auto cell_of = [cell_mm](double v) {
        // 21 bits an axis: the metal's cells (a 24th of its radius, FrameRenderer) number 48
        // across it. Indices further out would alias, merging boxes: still about every triangle.
        return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v / cell_mm)) +
                                          (1 << 20)) &
               0x1fffff;
    };
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 a(mesh.positions[mesh.indices[t]]);
        const glm::dvec3 b(mesh.positions[mesh.indices[t + 1]]);
        const glm::dvec3 c(mesh.positions[mesh.indices[t + 2]]);
        const glm::dvec3 centre = (a + b + c) / 3.0;
        const std::uint64_t key =
            (cell_of(centre.x) << 42) | (cell_of(centre.y) << 21) | cell_of(centre.z);
        const auto [it, is_new] = cell_box.try_emplace(key, boxes.size());
        if (is_new) boxes.push_back({a, a});
        CoverBox& box = boxes[it->second];
        box.lo = glm::min(box.lo, glm::min(a, glm::min(b, c)));
        box.hi = glm::max(box.hi, glm::max(a, glm::max(b, c)));
    }
    return boxes;
}

void mark_cover(const std::vector<CoverBox>& boxes, const Camera& camera, int margin_px,
                TileSet& tiles) {
    tiles.reset(camera.width(), camera.height());
    // The picture's centre where Camera::ray() places it (GL's rows count up); a box's corners
    // reach its centre's pixel ± the half-extent's length along right and up.
    const double w = camera.width(), h = camera.height();
    const glm::dvec2 centre(0.5 * w * (1.0 + camera.shift().x),
                            h - 0.5 * h * (1.0 - camera.shift().y));
    const glm::dvec3 right_abs = glm::abs(camera.right()), up_abs = glm::abs(camera.up());
    for (const CoverBox& box : boxes) {
        // A box about nothing (a stone of no vertices) covers nothing.
        if (!(box.lo.x <= box.hi.x && box.lo.y <= box.hi.y && box.lo.z <= box.hi.z)) continue;
        const glm::dvec3 mid = 0.5 * (box.lo + box.hi), half = 0.5 * (box.hi - box.lo);
        const glm::dvec2 at =
            centre + glm::dvec2(glm::dot(mid, camera.right()), glm::dot(mid, camera.up())) /
                         camera.pixel_size();
        const glm::dvec2 reach =
            glm::dvec2(glm::dot(half, right_abs), glm::dot(half, up_abs)) / camera.pixel_size();
        const glm::dvec2 lo = at - reach, hi = at + reach;
        // Far outside the picture (a zoomed-in piece's far parts): nothing to mark, and no
        // conversion of a huge double to int.
        if (hi.x < 0.0 || hi.y < 0.0 || lo.x > w || lo.y > h) continue;
        tiles.mark({static_cast<int>(std::floor(std::max(lo.x, -1.0))) - margin_px,
                    static_cast<int>(std::floor(std::max(lo.y, -1.0))) - margin_px,
                    static_cast<int>(std::ceil(std::min(hi.x, w + 1.0))) + margin_px,
                    static_cast<int>(std::ceil(std::min(hi.y, h + 1.0))) + margin_px});
    }
}

}  // namespace gem::gpu
