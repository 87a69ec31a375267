// gemtables inspect: one stored view as pictures — shaded in the studio environment with the
// engine's shader, and the ray-list length per pixel in false colour.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "commands.hpp"
#include "gemdb/reader.hpp"
#include "picture/image.hpp"
#include "scene/environment.hpp"
#include "scene/scene.hpp"
#include "scene/shading.hpp"

namespace gem::tables {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// The ray-list of one decoded pixel, back in the tracer's form the shader takes.
void pixel_list(const DecodedView& view, std::uint32_t pixel, RayList& out) {
    out.clear();
    const std::uint32_t count = view.ray_count[pixel];
    if (count == 0) return;
    out.hit = true;
    out.truncated_weight = view.truncated_weight[pixel];
    for (std::uint32_t k = 0; k < count; ++k) {
        const std::uint32_t i = view.ray_offset[pixel] + k;
        TracedRay ray;
        ray.origin = glm::dvec3(view.position[i]);
        ray.direction = glm::normalize(glm::dvec3(view.direction[i]));
        ray.weight = view.weight[i];
        ray.path_mm = view.path_mm[i];
        ray.bounces = view.bounces[i];
        ray.facet = view.facet[i];
        if (k == 0) {
            out.reflected = ray;
        } else {
            out.exits.push_back(ray);
        }
    }
}

// Black for a miss, then blue → cyan → green → yellow → red as the list grows to `longest`.
glm::vec4 length_colour(std::uint32_t count, std::uint32_t longest) {
    if (count == 0) return {0.0f, 0.0f, 0.0f, 1.0f};
    const float t =
        longest > 1 ? static_cast<float>(count - 1) / static_cast<float>(longest - 1) : 0.0f;
    static constexpr glm::vec3 kStops[] = {{0.0f, 0.0f, 1.0f},
                                           {0.0f, 1.0f, 1.0f},
                                           {0.0f, 1.0f, 0.0f},
                                           {1.0f, 1.0f, 0.0f},
                                           {1.0f, 0.0f, 0.0f}};
    const float x = t * 4.0f;
    const int i = std::min(static_cast<int>(x), 3);
    return {glm::mix(kStops[i], kStops[i + 1], x - static_cast<float>(i)), 1.0f};
}

}  // namespace

int run_inspect(const InspectOptions& o) {
    Result<Database> opened = Database::open(o.database);
    if (!opened) return fail(opened.error());
    const Database& db = opened.value();
    if (o.level >= static_cast<int>(db.level_count())) {
        return fail("--level " + std::to_string(o.level) + ": the database has " +
                    std::to_string(db.level_count()) + " levels (0 .. " +
                    std::to_string(db.level_count() - 1) + ")");
    }
    const auto level = static_cast<std::uint32_t>(o.level < 0 ? db.level_count() - 1 : o.level);
    // Azimuth about +y from +z toward +x, elevation above the girdle plane (picture/camera.hpp).
    const double az = o.azimuth_deg * kDegree;
    const double el = o.elevation_deg * kDegree;
    const glm::dvec3 asked{std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
    const ViewMatch match = db.grid().nearest(asked);
    Result<DecodedView> decoded = db.decode(match.view, level);
    if (!decoded) return fail(decoded.error());
    const DecodedView& view = decoded.value();

    const Environment studio = Environment::studio();
    ShadingSettings shading;
    shading.lights = default_scene().lights;
    const Shader shader(db.stone(), db.material(), studio, shading);
    // What shows around the stone: the studio behind it, seen along the pixel rays.
    const glm::dvec3 background = studio.radiance(-db.grid().direction(match.view));

    const auto side = static_cast<int>(view.side);
    Image shaded(side, side);
    Image lengths(side, side);
    std::uint32_t longest = 0;
    for (std::uint16_t c : view.ray_count) longest = std::max<std::uint32_t>(longest, c);
    RayList list;
    for (int y = 0; y < side; ++y) {
        for (int x = 0; x < side; ++x) {
            const auto pixel = static_cast<std::uint32_t>(y * side + x);
            pixel_list(view, pixel, list);
            const glm::dvec3 colour = list.hit ? shader.shade(list) : background;
            shaded.at(x, y) = glm::vec4(glm::vec3(colour), 1.0f);
            lengths.at(x, y) = length_colour(view.ray_count[pixel], longest);
        }
    }
    const std::string shaded_path = o.prefix + "-shaded.png";
    const std::string lengths_path = o.prefix + "-raylist-length.png";
    if (auto ok = write_png(shaded, shaded_path); !ok) return fail(ok.error());
    if (auto ok = write_png(lengths, lengths_path); !ok) return fail(ok.error());
    const glm::dvec3& d = db.grid().direction(match.view);
    std::printf(
        "gemtables: view %u (azimuth %.2f°, elevation %.2f°, %.2f° from the asked "
        "direction under symmetry %u), level %u (%d px), longest ray-list %u\n",
        match.view, std::atan2(d.x, d.z) / kDegree, std::asin(std::clamp(d.y, -1.0, 1.0)) / kDegree,
        match.angle / kDegree, match.symmetry, level, side, longest);
    std::printf("gemtables: wrote %s and %s (false colour: blue 1 ray … red %u rays)\n",
                shaded_path.c_str(), lengths_path.c_str(), longest);
    return 0;
}

}  // namespace gem::tables
