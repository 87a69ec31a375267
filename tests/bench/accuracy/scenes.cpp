#include "scenes.hpp"

#include <cmath>
#include <numbers>

#include "geometry/cuts.hpp"
#include "optics/material.hpp"

namespace gem::accuracy {

glm::dvec3 direction_from(double azimuth_deg, double elevation_deg) {
    const double a = azimuth_deg * std::numbers::pi / 180.0;
    const double e = elevation_deg * std::numbers::pi / 180.0;
    // CameraSettings: azimuth about +y from +z toward +x, elevation above the girdle plane.
    return {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
}

ShadingSettings scene_lights() {
    ShadingSettings s;
    s.lights = {{{20.0, 60.0, 40.0}, false, {2.0, 2.0, 2.0}},
                {{-30.0, 50.0, -20.0}, false, {1.5, 1.5, 1.5}}};
    return s;
}

namespace {

Result<Stone> cut(CutShape shape, const char* material) {
    auto m = find_material(material);
    if (!m) return Error{std::string("accuracy: no material '") + material + "'"};
    return make_cut(default_cut_params(shape), *m);
}

}  // namespace

Result<std::vector<Scene>> make_scenes(bool quick) {
    auto diamond = cut(CutShape::round_brilliant, "diamond");
    if (!diamond) return Error{diamond.error()};
    std::vector<Scene> scenes;
    scenes.push_back({"diamond-faceup", "diamond", diamond.value(), direction_from(10.0, 80.0),
                      20.0, std::nullopt, true});
    if (quick) return scenes;
    scenes.push_back({"diamond-tilted", "diamond", diamond.value(), direction_from(25.0, 45.0),
                      20.0, std::nullopt, true});
    // Polished, so one sample at a pixel's centre is exact in the reference as on the GPU (a
    // rough ring's reflection is sampled in the reference, filtered on the GPU).
    RingParams polished;
    polished.roughness = 0.0;
    auto ring = make_ring(polished, diamond.value());
    if (!ring) return Error{ring.error()};
    scenes.push_back({"diamond-ring", "diamond", diamond.value(), direction_from(-30.0, 40.0), 20.0,
                      std::move(ring).value(), true});
    auto oval = cut(CutShape::oval, "sapphire");
    if (!oval) return Error{oval.error()};
    scenes.push_back({"oval-sapphire", "oval-sapphire", std::move(oval).value(),
                      direction_from(30.0, 55.0), 35.0, std::nullopt, false});
    auto heart = cut(CutShape::heart, "ruby");
    if (!heart) return Error{heart.error()};
    scenes.push_back({"heart-ruby", "heart-ruby", std::move(heart).value(),
                      direction_from(-20.0, 65.0), 45.0, std::nullopt, false});
    return scenes;
}

}  // namespace gem::accuracy
