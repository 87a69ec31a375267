#include "stage/framing.hpp"

#include <algorithm>
#include <limits>

namespace gem::kiosk {

namespace {

struct Extent {
    glm::dvec2 low{std::numeric_limits<double>::infinity()};
    glm::dvec2 high{-std::numeric_limits<double>::infinity()};
    void add(const glm::dvec2& p) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    bool empty() const { return low.x > high.x; }
    glm::dvec2 size() const { return high - low; }
    glm::dvec2 middle() const { return 0.5 * (low + high); }
};

}  // namespace

CameraSettings framed_camera(const ViewState& view, const Framing& framing) {
    CameraSettings settings;
    settings.azimuth_deg = view.azimuth_deg;
    settings.elevation_deg = view.elevation_deg;
    settings.roll_deg = view.roll_deg;
    settings.zoom = framing.zoom * view.zoom;
    settings.shift = framing.shift;
    return settings;
}

Framing frame_ring(const std::vector<glm::dvec3>& stone, const std::vector<glm::dvec3>& ring,
                   const ViewState& start, glm::ivec2 picture, double scene_radius_mm,
                   double stone_share) {
    Framing framing;
    ViewState level = start;
    level.zoom = 1.0;
    auto camera =
        Camera::make(framed_camera(level, framing), scene_radius_mm, picture.x, picture.y);
    if (!camera || stone.empty()) return framing;
    const Camera& c = camera.value();
    const auto on_screen = [&](const glm::dvec3& p) {
        return glm::dvec2(glm::dot(p, c.right()), glm::dot(p, c.up()));
    };
    Extent of_stone;
    for (const glm::dvec3& p : stone) of_stone.add(on_screen(p));
    Extent all = of_stone;
    for (const glm::dvec3& p : ring) all.add(on_screen(p));

    const double aspect = static_cast<double>(picture.x) / picture.y;
    const double inner = 1.0 - 2.0 * kFramingMargin;
    // Picture heights in mm: the tightest that holds everything, the widest the rule allows.
    const double fits = std::max(all.size().y, all.size().x / aspect) / inner;
    const double hero = of_stone.size().x / stone_share;
    double height = fits;
    glm::dvec2 middle = all.middle();
    if (fits > hero) {
        height = hero;
        framing.ring_cut = true;
        // Keep the stone whole and as near the outline's middle as that allows.
        const glm::dvec2 half(0.5 * height * aspect * inner, 0.5 * height * inner);
        middle = glm::clamp(middle, of_stone.high - half, of_stone.low + half);
    }
    framing.stone_share = of_stone.size().x / height;
    const double shorter = std::min(picture.x, picture.y);
    const double pixel_mm = height / picture.y;
    framing.zoom = 2.0 * scene_radius_mm / (pixel_mm * shorter);
    // The outline's middle goes to the picture's centre: the stone's centre moves the other way.
    framing.shift = -middle / glm::dvec2(0.5 * height * aspect, 0.5 * height);
    return framing;
}

}  // namespace gem::kiosk
