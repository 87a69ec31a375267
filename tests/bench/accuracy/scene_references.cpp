#include "scene_references.hpp"

#include <cmath>

#include "gpu_frames.hpp"

namespace gem::accuracy {

Result<const SceneReferences::Entry*> SceneReferences::get(const glm::dvec3& view) {
    const auto key = std::make_tuple(std::lround(view.x * 1e9), std::lround(view.y * 1e9),
                                     std::lround(view.z * 1e9));
    auto found = entries_.find(key);
    if (found != entries_.end()) return &found->second;
    auto ref = render_cpu(scene_, environment_, view, image_, full_reference());
    if (!ref) return Error{ref.error()};
    ReferenceSettings nd = full_reference();
    nd.spectral = false;
    auto ref_nd = render_cpu(scene_, environment_, view, image_, nd);
    if (!ref_nd) return Error{ref_nd.error()};
    auto ring = ring_coverage(scene_, environment_, view, image_);
    if (!ring) return Error{ring.error()};
    auto stone_mask = stone_coverage(scene_, view, image_);
    if (!stone_mask) return Error{stone_mask.error()};
    Entry e;
    e.mask.resize(ring.value().size());
    for (std::size_t i = 0; i < e.mask.size(); ++i) {
        const bool stone = stone_mask.value()[i] > 0.5f;
        e.mask[i] = stone && ring.value()[i] < 0.5f ? 1.0f : 0.0f;
    }
    e.reference = std::move(ref).value();
    e.reference_nd = std::move(ref_nd).value();
    return &entries_.emplace(key, std::move(e)).first->second;
}

}  // namespace gem::accuracy
