#include "gemmology/face_up_images.hpp"

#include <algorithm>

namespace gem {

Image light_return_image(const FaceUpAnalysis& analysis) {
    Image image(analysis.resolution, analysis.resolution, glm::vec4(0.0f));
    for (int y = 0; y < analysis.resolution; ++y) {
        for (int x = 0; x < analysis.resolution; ++x) {
            const FaceUpPixel& px = analysis.at(x, y);
            if (!px.stone) continue;
            const float v = std::clamp(px.light_return, 0.0f, 1.0f);
            image.at(x, y) = glm::vec4(v, v, v, 1.0f);
        }
    }
    return image;
}

Image aset_image(const FaceUpAnalysis& analysis) {
    Image image(analysis.resolution, analysis.resolution, glm::vec4(0.0f));
    for (int y = 0; y < analysis.resolution; ++y) {
        for (int x = 0; x < analysis.resolution; ++x) {
            const FaceUpPixel& px = analysis.at(x, y);
            if (!px.stone) continue;
            // Light from inside the stone only: the first reflection is left out.
            std::array<float, kSkyZoneCount> inside = px.zone;
            inside[static_cast<std::size_t>(px.surface_zone)] -= px.surface_weight;
            float total = px.truncated;
            for (float w : inside) total += w;
            if (total <= 0.0f) continue;
            const auto w = [&](SkyZone z) {
                return std::max(inside[static_cast<std::size_t>(z)], 0.0f) / total;
            };
            image.at(x, y) =
                glm::vec4(w(SkyZone::high_sky), w(SkyZone::low_sky), w(SkyZone::head), 1.0f);
        }
    }
    return image;
}

}  // namespace gem
