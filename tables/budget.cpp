// Chooses build parameters under an error budget by measuring pilot pictures (budget.hpp).
#include "budget.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

#include "cpu/reference_render.hpp"
#include "gemdb/view_grid.hpp"
#include "picture/image_error.hpp"
#include "scene/scene.hpp"
#include "view_trace.hpp"

namespace gem::tables {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// What a table built with these parameters shows (before magnification to the screen).
struct Candidate {
    std::uint32_t level = 512;
    double spacing_deg = 2.0;
    double offset_deg = 0.0;  // from the asked direction to the nearest stored view
    std::uint32_t depth = 16;
    double threshold = 1e-5;
    bool dispersion = true;
};

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// Nearest-texel magnification (or minification) of `image` to side × side.
Image resample_nearest(const Image& image, int side) {
    if (image.width == side && image.height == side) return image;
    Image out(side, side);
    for (int y = 0; y < side; ++y) {
        const int sy = std::min(image.height - 1, y * image.height / side);
        for (int x = 0; x < side; ++x)
            out.at(x, y) = image.at(std::min(image.width - 1, x * image.width / side), sy);
    }
    return out;
}

// The median angle from a direction in the shown band to its nearest stored view, over a
// Fibonacci set of directions above the grid's lowest elevation.
Result<double> median_offset_deg(const Stone& stone, double spacing_deg, double min_elevation_deg) {
    ViewGridSpec spec;
    spec.spacing_rad = spacing_deg * kDegree;
    spec.min_elevation_rad = min_elevation_deg * kDegree;
    Result<ViewGrid> grid = ViewGrid::build(spec, stone.symmetry);
    if (!grid) return Error{grid.error()};
    std::vector<double> angles;
    const std::uint32_t n = 4000;
    const double min_y = std::sin(spec.min_elevation_rad);
    for (std::uint32_t i = 0; i < n; ++i) {
        const glm::dvec3 d = ViewGrid::sphere_point(i, n);
        if (d.y < min_y) continue;
        angles.push_back(grid.value().nearest(d).angle / kDegree);
    }
    std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
    return angles[angles.size() / 2];
}

class PilotRenderer {
  public:
    PilotRenderer(const Stone& stone, const BudgetRequest& request)
        : stone_(stone), request_(request), environment_(Environment::studio()) {
        shading_.lights = default_scene().lights;
    }

    // Worst mean ΔE00 over the pilot views of what `c` shows against the reference.
    Result<double> error(const Candidate& c) {
        double worst = 0.0;
        for (std::size_t v = 0; v < request_.pilot_views.size(); ++v) {
            Result<const Image*> reference = reference_image(v);
            if (!reference) return Error{reference.error()};
            const auto [elevation, azimuth] = request_.pilot_views[v];
            Result<Image> shown =
                render(elevation - c.offset_deg, azimuth, static_cast<int>(c.level), c.depth,
                       c.threshold, c.dispersion);
            if (!shown) return Error{shown.error()};
            ErrorOptions options;
            options.only_stone = true;
            Result<ImageError> e = compare_images(
                resample_nearest(shown.value(), request_.screen_px), *reference.value(), options);
            if (!e) return Error{e.error()};
            worst = std::max(worst, e.value().delta_e_mean);
        }
        return worst;
    }

  private:
    Result<Image> render(double elevation, double azimuth, int side, std::uint32_t depth,
                         double threshold, bool spectral) const {
        RenderSettings s;
        s.width = s.height = side;
        s.samples_per_pixel = 1;  // one ray per pixel, as a table stores
        s.camera.elevation_deg = elevation;
        s.camera.azimuth_deg = azimuth;
        s.shading = shading_;
        BuildParams params;
        params.max_depth = depth;
        params.weight_threshold = threshold;
        s.trace = table_trace_settings(params);
        s.spectral = spectral;
        s.background_is_environment = false;
        return render_reference(stone_, environment_, s);
    }

    Result<const Image*> reference_image(std::size_t v) {
        if (auto found = references_.find(v); found != references_.end()) return &found->second;
        const auto [elevation, azimuth] = request_.pilot_views[v];
        // Deep trees, spectral: what the stone looks like, against which every table is judged.
        Result<Image> image = render(elevation, azimuth, request_.screen_px, 64, 1e-6, true);
        if (!image) return Error{image.error()};
        return &references_.emplace(v, std::move(image).value()).first->second;
    }

    const Stone& stone_;
    const BudgetRequest& request_;
    Environment environment_;
    ShadingSettings shading_;
    std::map<std::size_t, Image> references_;
};

}  // namespace

Result<BudgetChoice> choose_parameters(const Stone& stone, const BudgetRequest& request,
                                       const std::function<void(const BudgetStep&)>& on_step) {
    if (!(request.budget_delta_e > 0.0)) return Error{"--budget: must be a positive ΔE00"};
    if (!(request.max_jump_px > 0.0)) return Error{"--jump: must be a positive pixel count"};
    if (request.screen_px < 16) return Error{"--screen: at least 16 pixels"};
    if (request.spacings_deg.empty() || request.levels.empty() || request.depths.empty() ||
        request.thresholds.empty() || request.pilot_views.empty())
        return Error{"budget: a candidate list is empty"};

    BudgetChoice choice;
    PilotRenderer pilot(stone, request);

    // The spacing: the largest whose jump at the rim, θ · screen_px / 2 pixels for a turn of
    // θ radians, stays within max_jump_px.
    std::vector<double> spacings = request.spacings_deg;
    std::sort(spacings.begin(), spacings.end());
    auto jump_px = [&](double spacing_deg) {
        return spacing_deg * kDegree * request.screen_px / 2.0;
    };
    double spacing = spacings.front();
    for (double s : spacings)
        if (jump_px(s) <= request.max_jump_px) spacing = s;
    choice.jump_met = jump_px(spacing) <= request.max_jump_px;
    Result<double> offset = median_offset_deg(stone, spacing, request.min_elevation_deg);
    if (!offset) return Error{"spacing " + number(spacing) + "°: " + offset.error()};

    // The picture, searched at a stored direction (offset 0), from the most accurate candidate:
    // the level that covers the screen (or the largest), the deepest trees, the lowest
    // threshold, dispersion on.
    std::vector<std::uint32_t> levels = request.levels;
    std::sort(levels.begin(), levels.end());
    std::uint32_t top_level = levels.back();
    for (auto it = levels.rbegin(); it != levels.rend(); ++it)
        if (*it >= static_cast<std::uint32_t>(request.screen_px)) top_level = *it;
    Candidate current{top_level,
                      spacing,
                      0.0,
                      *std::max_element(request.depths.begin(), request.depths.end()),
                      *std::min_element(request.thresholds.begin(), request.thresholds.end()),
                      true};

    auto measure = [&](const std::string& parameter, const std::string& value,
                       const Candidate& c) -> Result<BudgetStep> {
        Result<double> e = pilot.error(c);
        if (!e) return Error{e.error()};
        BudgetStep step{parameter, value, e.value(), e.value() <= request.budget_delta_e};
        choice.steps.push_back(step);
        if (on_step) on_step(step);
        return step;
    };
    Result<BudgetStep> start = measure("start", "most accurate", current);
    if (!start) return Error{start.error()};
    choice.met = start.value().accepted;
    double error = start.value().delta_e;

    // Tries `values` (cheapest first) for one parameter and keeps the first within budget;
    // `apply` sets the value and says whether it is cheaper than where the parameter stands.
    auto relax = [&](const std::string& parameter, const auto& values, auto apply,
                     auto describe) -> Result<bool> {
        for (const auto& value : values) {
            Candidate c = current;
            if (!apply(c, value)) continue;
            Result<BudgetStep> step = measure(parameter, describe(value), c);
            if (!step) return Error{step.error()};
            if (step.value().accepted) {
                current = c;
                error = step.value().delta_e;
                return true;
            }
        }
        return false;
    };
    if (choice.met) {
        std::vector<std::uint32_t> depths = request.depths;
        std::sort(depths.begin(), depths.end());
        std::vector<double> thresholds = request.thresholds;
        std::sort(thresholds.rbegin(), thresholds.rend());
        Result<bool> steps[] = {
            relax(
                "dispersion", std::vector<bool>{false},
                [](Candidate& c, bool on) {
                    c.dispersion = on;
                    return true;
                },
                [](bool on) { return std::string(on ? "on" : "off"); }),
            relax(
                "level", levels,
                [&](Candidate& c, std::uint32_t l) {
                    c.level = l;
                    return l < current.level;
                },
                [](std::uint32_t l) { return std::to_string(l) + " px"; }),
            relax(
                "depth", depths,
                [&](Candidate& c, std::uint32_t d) {
                    c.depth = d;
                    return d < current.depth;
                },
                [](std::uint32_t d) { return std::to_string(d); }),
            relax(
                "threshold", thresholds,
                [&](Candidate& c, double t) {
                    c.threshold = t;
                    return t > current.threshold;
                },
                [](double t) { return number(t); }),
        };
        for (const Result<bool>& r : steps)
            if (!r) return Error{r.error()};
    }

    // For the record: what the chosen tables show at the median offset from a stored view,
    // against the exact picture of the asked direction.
    Candidate between = current;
    between.offset_deg = offset.value();
    Result<double> between_error = pilot.error(between);
    if (!between_error) return Error{between_error.error()};

    choice.spacing_deg = spacing;
    choice.offset_deg = offset.value();
    choice.delta_e = error;
    choice.between_delta_e = between_error.value();
    choice.params.grid.spacing_rad = spacing * kDegree;
    choice.params.grid.min_elevation_rad = request.min_elevation_deg * kDegree;
    choice.params.max_depth = current.depth;
    choice.params.weight_threshold = current.threshold;
    choice.params.dispersion = current.dispersion;
    // Two levels: the chosen one, and half of it for stand-ins while views stream in.
    choice.params.levels = {std::max<std::uint32_t>(16, current.level / 2), current.level};
    return choice;
}

}  // namespace gem::tables
