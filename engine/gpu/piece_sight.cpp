#include "gpu/piece_sight.hpp"

#include "gpu/texel_array.hpp"

namespace gem::gpu {

Result<PieceSight> PieceSight::make(const SightMesh& mesh) {
    PieceSight sight;
    sight.triangle_count_ = mesh.triangle_count;
    if (mesh.triangle_count == 0) return sight;
    auto nodes = upload_texel_array(mesh.nodes.data(), mesh.nodes.size() / 4, "piece sight: nodes");
    if (!nodes) return Error{nodes.error()};
    auto triangles = upload_texel_array(mesh.triangles.data(), mesh.triangles.size() / 4,
                                        "piece sight: triangles");
    if (!triangles) return Error{triangles.error()};
    sight.nodes_ = std::move(nodes).value();
    sight.triangles_ = std::move(triangles).value();
    return sight;
}

}  // namespace gem::gpu
