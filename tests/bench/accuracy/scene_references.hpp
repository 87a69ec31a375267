#pragma once
// A scene's reference frames, rendered once per view direction and shared by every method and
// setting seen from it: the full reference, the same traced at n(D) only, and the mask of the
// pixels compared (the stone's, less those the ring covers).

#include <map>
#include <tuple>
#include <vector>

#include "reference_images.hpp"
#include "scene/environment.hpp"
#include "scenes.hpp"
#include "util/result.hpp"

namespace gem::accuracy {

class SceneReferences {
  public:
    // Keeps references: scene and environment (what surrounds the stone, for the GPU frames
    // and the reference alike) must outlive it.
    SceneReferences(const Scene& scene, const Environment& environment, int image)
        : scene_(scene), environment_(environment), image_(image) {}

    struct Entry {
        CpuFrame reference;
        CpuFrame reference_nd;    // the same, traced at n(D) only
        std::vector<float> mask;  // the stone's pixels, less those the ring covers
    };
    // Needs a current GL context (the ring's coverage is drawn on the GPU).
    Result<const Entry*> get(const glm::dvec3& view);
    const Environment& cpu_environment() const { return environment_; }

  private:
    const Scene& scene_;
    const Environment& environment_;
    int image_;
    std::map<std::tuple<long, long, long>, Entry> entries_;
};

}  // namespace gem::accuracy
