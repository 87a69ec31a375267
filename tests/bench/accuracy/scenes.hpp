#pragma once
// The fixed scenes of the accuracy benchmark: a stone, the direction it is looked at from
// (stone frame, stone → eye), and optionally a ring around it. Every method and setting is
// measured on these same scenes.

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/stone.hpp"
#include "piece/ring_mesh.hpp"
#include "scene/shading.hpp"
#include "util/result.hpp"

namespace gem::accuracy {

struct Scene {
    std::string name;        // CSV key, e.g. "diamond-tilted"
    std::string stone_name;  // which database family it uses, e.g. "diamond"
    Stone stone;
    glm::dvec3 target{0.0, 1.0, 0.0};  // the view asked for, before snapping on/between views
    // The lowest elevation the scene's databases store (a little below the target's), so
    // builds hold only the directions the scene can show (docs/design.md, "Model no more than
    // a scene needs").
    double min_elevation_deg = 20.0;
    std::optional<MetalMesh> ring;
    bool sweeps = false;  // the table settings are swept on this scene, not only the base point
};

// Direction from the stone toward the eye at azimuth/elevation (degrees), as Camera does.
glm::dvec3 direction_from(double azimuth_deg, double elevation_deg);

// Diamond face-up and tilted, the diamond in its solitaire ring, an oval sapphire, a heart
// ruby. `quick`: the face-up diamond only.
Result<std::vector<Scene>> make_scenes(bool quick);

// The lights every method shades with (the same for GPU and CPU).
ShadingSettings scene_lights();

}  // namespace gem::accuracy
