#include "gpu/stone_models.hpp"

#include <GLES3/gl3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "gpu/framebuffer_scope.hpp"
#include "gpu/render_target.hpp"
#include "picture/image_error.hpp"
#include "piece/stone_shape.hpp"

namespace gem::gpu {

namespace {

// "no fire", "first-order fire", "exact fire".
std::string fire_phrase(TraceDispersion fire) {
    return fire == TraceDispersion::none ? "no fire" : std::string(to_string(fire)) + " fire";
}

}  // namespace

std::vector<StoneModel> cheaper_models(const StoneModel& configured) {
    std::vector<StoneModel> out;
    // Fire from least to most work, up to the configured.
    const auto add_with_fire = [&](int depth) {
        for (TraceDispersion fire : {TraceDispersion::none, TraceDispersion::first_order,
                                     TraceDispersion::exact, TraceDispersion::spectral}) {
            out.push_back({depth, fire});
            if (fire == configured.fire) break;
        }
    };
    for (int depth : {1, 2, 3, 4, 6}) {
        if (depth < configured.depth) add_with_fire(depth);
    }
    add_with_fire(configured.depth);
    return out;
}

std::size_t first_within(const std::vector<double>& errors, double budget) {
    for (std::size_t i = 0; i < errors.size(); ++i) {
        if (errors[i] <= budget) return i;
    }
    return errors.empty() ? 0 : errors.size() - 1;
}

Result<std::vector<ModelChoice>> choose_stone_models(FrameRenderer& renderer, const Camera& view,
                                                     double budget) {
    std::vector<ModelChoice> choices;
    const std::size_t hero = renderer.kind_of(0);
    const bool one_kind = renderer.kind_count() == 1;
    if (one_kind && renderer.stone_count() < 2) return choices;  // a loose stone is the hero
    const FramebufferScope restore;
    for (std::size_t k = 0; k < renderer.kind_count(); ++k) {
        if (k == hero && !one_kind) continue;
        if (!renderer.model(k)) continue;  // a method without models, or a kind from tables
        const Stone& stone = renderer.kind(k);
        const Placement& at = renderer.placement_of(renderer.first_of_kind(k));
        // The view's direction as this stone sees it, as an orbit about it at the view's scale.
        const glm::dvec3 towards_eye = at.direction_to_stone(-view.forward());
        CameraSettings seen;
        seen.elevation_deg =
            std::asin(std::clamp(towards_eye.y, -1.0, 1.0)) * 180.0 / std::numbers::pi;
        seen.azimuth_deg = std::atan2(towards_eye.x, towards_eye.z) * 180.0 / std::numbers::pi;
        const double radius = bounding_radius(stone.vertices);
        // A perspective pixel is tangent units at unit distance: at the eye's distance, mm.
        const double pixel_mm =
            view.orthographic() ? view.pixel_size() : view.pixel_size() * view.distance();
        const int side = std::max(8, static_cast<int>(std::ceil(2.0 * radius / pixel_mm)) + 2);
        seen.zoom = side * pixel_mm / (2.0 * radius);
        auto camera = Camera::make(seen, radius, side, side);
        if (!camera) return Error{"stone models: " + camera.error()};
        auto target = RenderTarget::make(side, side);
        if (!target) return Error{"stone models: " + target.error()};
        target.value().bind();
        const auto draw = [&](const StoneModel& model) -> Result<Image> {
            glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            auto ok = renderer.draw_kind_alone(k, camera.value(), model);
            if (!ok) return Error{ok.error()};
            return target.value().read();
        };
        ModelChoice choice;
        choice.kind = k;
        choice.width_px = 2.0 * radius / pixel_mm;
        choice.configured = *renderer.model(k);
        auto reference = draw(choice.configured);
        if (!reference) return Error{reference.error()};
        const std::vector<StoneModel> candidates = cheaper_models(choice.configured);
        std::vector<double> errors;
        ErrorOptions only_stone;
        only_stone.only_stone = true;
        for (const StoneModel& model : candidates) {
            if (model == choice.configured) {
                errors.push_back(0.0);
                break;
            }
            auto image = draw(model);
            if (!image) return Error{image.error()};
            auto error = compare_images(image.value(), reference.value(), only_stone);
            errors.push_back(error ? error.value().delta_e_mean : HUGE_VAL);
            if (errors.back() <= budget) break;  // the cheapest within: no need for dearer ones
        }
        const std::size_t chosen = first_within(errors, budget);
        choice.model = candidates[chosen];
        choice.delta_e = errors[chosen];
        choice.candidates = static_cast<int>(errors.size());
        renderer.set_model(k, choice.model);
        choices.push_back(choice);
    }
    return choices;
}

std::string describe(const ModelChoice& choice, const FrameRenderer& renderer,
                     std::size_t instances) {
    const Stone& stone = renderer.kind(choice.kind);
    char line[256];
    std::snprintf(line, sizeof line,
                  "%.1f mm %s (x%zu), %.0f px: depth %d, %s (mean ΔE00 %.2f against depth %d, "
                  "%s; %d models measured)",
                  girdle_width(stone), stone.material.name.c_str(), instances, choice.width_px,
                  choice.model.depth, fire_phrase(choice.model.fire).c_str(), choice.delta_e,
                  choice.configured.depth, fire_phrase(choice.configured.fire).c_str(),
                  choice.candidates);
    return line;
}

}  // namespace gem::gpu
