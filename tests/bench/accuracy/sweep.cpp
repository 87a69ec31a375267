#include "sweep.hpp"

#include <cstdio>
#include <numbers>

#include "database_cache.hpp"
#include "example_images.hpp"
#include "gpu_frames.hpp"
#include "reference_images.hpp"
#include "scene_references.hpp"
#include "scenes.hpp"
#include "still_pictures.hpp"
#include "views.hpp"

namespace gem::accuracy {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

struct Context {
    const SweepOptions& options;
    DatabaseCache& cache;
    std::vector<Row>& rows;
};

Result<bool> add(Context& ctx, Row row, const Image& test, const Image& reference,
                 const std::vector<float>& mask, const Image* reference_nd = nullptr) {
    auto e = stone_error(test, reference, mask);
    if (!e) return Error{e.error()};
    row.error = e.value();
    if (reference_nd != nullptr) {
        auto nd = stone_error(test, *reference_nd, mask);
        if (!nd) return Error{nd.error()};
        row.error_nd = nd.value();
        row.has_nd = true;
    }
    print_row(row);
    ctx.rows.push_back(std::move(row));
    return true;
}

// The table method with `config` (nearest or blend) on `views`, rows labelled `study`.
Result<std::vector<GpuFrame>> table_rows(
    Context& ctx, const Scene& scene, const Environment& env, SceneReferences& refs,
    const char* study, const TableConfig& config, bool blend,
    const std::vector<std::pair<const char*, glm::dvec3>>& views) {
    auto db = ctx.cache.get(scene.stone_name, scene.stone, config, scene.min_elevation_deg);
    if (!db) return Error{db.error()};
    GpuPoint point;
    point.method = "table";
    point.database = db.value().database;
    point.blend = blend;
    std::vector<glm::dvec3> dirs;
    for (const auto& v : views) dirs.push_back(v.second);
    auto frames = render_gpu(scene, env, point, dirs, ctx.options.image, ctx.options.frames);
    if (!frames) return Error{frames.error()};
    for (std::size_t i = 0; i < views.size(); ++i) {
        auto ref = refs.get(views[i].second);
        if (!ref) return Error{ref.error()};
        const GpuFrame& f = frames.value()[i];
        Row row;
        row.study = study;
        row.scene = scene.name;
        row.view = views[i].first;
        row.offset_deg = f.table.angle_rad * kRadToDeg;
        row.method = "table";
        row.level = static_cast<int>(config.level);
        row.spacing_deg = config.spacing_deg;
        row.blend = blend;
        row.blend_weight = f.table.blend;
        row.depth = config.depth;
        row.threshold = config.threshold;
        row.dispersion = config.dispersion;
        row.frame_ms = f.median_ms;
        row.db_bytes = db.value().bytes;
        row.build_s = db.value().build_s;
        auto added = add(ctx, row, f.image, ref.value()->reference.image, ref.value()->mask,
                         &ref.value()->reference_nd.image);
        if (!added) return Error{added.error()};
    }
    return std::move(frames).value();
}

// trace (depth, threshold) or phong on `views`.
Result<std::vector<GpuFrame>> gpu_rows(
    Context& ctx, const Scene& scene, const Environment& env, SceneReferences& refs,
    const ViewGrid& base_grid, const char* study, std::string method, int depth, double threshold,
    const std::vector<std::pair<const char*, glm::dvec3>>& views) {
    GpuPoint point;
    point.method = method;
    point.trace.max_depth = depth;
    point.trace.min_weight = threshold;
    std::vector<glm::dvec3> dirs;
    for (const auto& v : views) dirs.push_back(v.second);
    auto frames = render_gpu(scene, env, point, dirs, ctx.options.image, ctx.options.frames);
    if (!frames) return Error{frames.error()};
    for (std::size_t i = 0; i < views.size(); ++i) {
        auto ref = refs.get(views[i].second);
        if (!ref) return Error{ref.error()};
        Row row;
        row.study = study;
        row.scene = scene.name;
        row.view = views[i].first;
        row.offset_deg = base_grid.nearest(views[i].second).angle * kRadToDeg;
        row.method = method;
        if (method == "trace") {
            row.depth = depth;
            row.threshold = threshold;
        }
        row.frame_ms = frames.value()[i].median_ms;
        auto added = add(ctx, row, frames.value()[i].image, ref.value()->reference.image,
                         ref.value()->mask, &ref.value()->reference_nd.image);
        if (!added) return Error{added.error()};
    }
    return std::move(frames).value();
}

// The reference itself at cheaper settings, and the 1-sample reference against a 4-sample one.
Result<bool> reference_rows(Context& ctx, const Scene& scene, SceneReferences& refs,
                            const ViewGrid& base_grid, const glm::dvec3& view, bool with_aliasing) {
    auto ref = refs.get(view);
    if (!ref) return Error{ref.error()};
    Row row;
    row.study = "reference";
    row.scene = scene.name;
    row.view = "on";
    row.offset_deg = base_grid.nearest(view).angle * kRadToDeg;
    row.method = "reference";
    row.depth = 64;
    row.threshold = 1e-6;
    row.dispersion = true;
    row.frame_ms = ref.value()->reference.seconds * 1e3;
    row.compared_with = "itself";
    auto same = add(ctx, row, ref.value()->reference.image, ref.value()->reference.image,
                    ref.value()->mask);
    if (!same) return Error{same.error()};
    std::vector<ReferenceSettings> cheaper = {
        {64, 1e-6, false, 1}, {12, 1e-4, true, 1}, {8, 1e-4, false, 1}, {4, 1e-4, false, 1}};
    if (ctx.options.quick) cheaper.resize(2);
    for (const ReferenceSettings& s : cheaper) {
        auto cheap = render_cpu(scene, refs.cpu_environment(), view, ctx.options.image, s);
        if (!cheap) return Error{cheap.error()};
        row.depth = s.depth;
        row.threshold = s.min_weight;
        row.dispersion = s.spectral;
        row.frame_ms = cheap.value().seconds * 1e3;
        row.compared_with = "reference";
        auto added = add(ctx, row, cheap.value().image, ref.value()->reference.image,
                         ref.value()->mask, &ref.value()->reference_nd.image);
        if (!added) return Error{added.error()};
    }
    // Aliasing: what 1 sample at the pixel centre (every GPU method, and the reference) misses
    // of an image averaged over the pixel.
    if (!with_aliasing) return true;
    ReferenceSettings ss = full_reference();
    ss.samples = 4;
    auto super = render_cpu(scene, refs.cpu_environment(), view, ctx.options.image, ss);
    if (!super) return Error{super.error()};
    row.study = "aliasing";
    row.depth = 64;
    row.threshold = 1e-6;
    row.dispersion = true;
    row.samples = 1;
    row.frame_ms = ref.value()->reference.seconds * 1e3;
    row.compared_with = "ref-4spp";
    return add(ctx, row, ref.value()->reference.image, super.value().image, ref.value()->mask);
}

Result<bool> quantisation_rows(Context& ctx, const Scene& scene, const Environment& env,
                               const CachedDatabase& base, const TableConfig& config,
                               SceneReferences& refs, const glm::dvec3& on) {
    // The same depth and threshold as the table, n(D), 1 sample: what the table would show if
    // nothing were quantised or interpolated.
    ReferenceSettings exact{config.depth, config.threshold, false, 1};
    auto cpu = render_cpu(scene, refs.cpu_environment(), on, ctx.options.image, exact);
    if (!cpu) return Error{cpu.error()};
    auto ref = refs.get(on);
    if (!ref) return Error{ref.error()};
    GpuPoint table;
    table.database = base.database;
    auto t = render_gpu(scene, env, table, {on}, ctx.options.image, 1);
    if (!t) return Error{t.error()};
    GpuPoint trace;
    trace.method = "trace";
    trace.trace.max_depth = config.depth;
    trace.trace.min_weight = config.threshold;
    auto g = render_gpu(scene, env, trace, {on}, ctx.options.image, 1);
    if (!g) return Error{g.error()};
    Row row;
    row.study = "quantise";
    row.scene = scene.name;
    row.view = "on";
    row.offset_deg = t.value()[0].table.angle_rad * kRadToDeg;
    row.method = "table";
    row.level = config.level;
    row.spacing_deg = config.spacing_deg;
    row.depth = config.depth;
    row.threshold = config.threshold;
    row.frame_ms = t.value()[0].median_ms;
    row.db_bytes = base.bytes;
    row.build_s = base.build_s;
    row.compared_with = "exact-cpu";
    auto a = add(ctx, row, t.value()[0].image, cpu.value().image, ref.value()->mask);
    if (!a) return a;
    row.compared_with = "trace-gpu";
    a = add(ctx, row, t.value()[0].image, g.value()[0].image, ref.value()->mask);
    if (!a) return a;
    row.method = "trace";
    row.level = 0;
    row.spacing_deg = 0.0;
    row.db_bytes = 0;
    row.build_s = 0.0;
    row.frame_ms = g.value()[0].median_ms;
    row.compared_with = "exact-cpu";
    return add(ctx, row, g.value()[0].image, cpu.value().image, ref.value()->mask);
}

Result<bool> path_rows(Context& ctx, const Scene& scene, const Environment& env,
                       const CachedDatabase& base, SceneReferences& refs) {
    const int count = ctx.options.quick ? 5 : 9;
    const auto path = view_path(base.database->grid(), scene.target, count, 0.8);
    std::vector<std::pair<const char*, glm::dvec3>> views;
    for (const glm::dvec3& d : path) views.push_back({"path", d});
    for (const bool blend : {false, true}) {
        TableConfig config;
        config.level = static_cast<std::uint32_t>(ctx.options.image);
        auto rows = table_rows(ctx, scene, env, refs, "path", config, blend, views);
        if (!rows) return Error{rows.error()};
    }
    return true;
}

}  // namespace

Result<std::vector<Row>> run_sweep(const SweepOptions& options) {
    auto scenes = make_scenes(options.quick);
    if (!scenes) return Error{scenes.error()};
    std::vector<Row> rows;
    DatabaseCache cache(options.cache);
    Context ctx{options, cache, rows};
    const Environment studio = Environment::studio();
    TableConfig base;
    base.level = static_cast<std::uint32_t>(options.image);
    print_header();
    for (const Scene& scene : scenes.value()) {
        SceneReferences refs(scene, studio, options.image);
        auto base_db = cache.get(scene.stone_name, scene.stone, base, scene.min_elevation_deg);
        if (!base_db) return Error{base_db.error()};
        const ViewGrid& grid = base_db.value().database->grid();
        const glm::dvec3 on = on_view(grid, scene.target);
        const glm::dvec3 between = between_view(grid, scene.target);
        const std::vector<std::pair<const char*, glm::dvec3>> views = {{"on", on},
                                                                       {"between", between}};
        // The base point and the other methods.
        auto nearest = table_rows(ctx, scene, studio, refs, "base", base, false, views);
        if (!nearest) return Error{nearest.error()};
        auto blend = table_rows(ctx, scene, studio, refs, "blend", base, true, views);
        if (!blend) return Error{blend.error()};
        auto trace = gpu_rows(ctx, scene, studio, refs, grid, "base", "trace", base.depth,
                              base.threshold, views);
        if (!trace) return Error{trace.error()};
        auto phong = gpu_rows(ctx, scene, studio, refs, grid, "base", "phong", 0, 0.0, views);
        if (!phong) return Error{phong.error()};
        for (const int depth : options.quick ? std::vector<int>{4} : std::vector<int>{2, 4, 12}) {
            auto t = gpu_rows(ctx, scene, studio, refs, grid, "trace-depth", "trace", depth,
                              base.threshold, views);
            if (!t) return Error{t.error()};
        }
        auto r = reference_rows(ctx, scene, refs, grid, on,
                                scene.name == "diamond-faceup" || scene.name == "oval-sapphire");
        if (!r) return Error{r.error()};
        if (!scene.ring) {
            auto ref = refs.get(on);
            if (!ref) return Error{ref.error()};
            r = still_rows(scene, studio, on, ref.value()->mask, options.image, options.quick,
                           rows);
            if (!r) return Error{r.error()};
        }
        if (!options.quick) {
            r = quantisation_rows(ctx, scene, studio, base_db.value(), base, refs, on);
            if (!r) return Error{r.error()};
        }
        if (!options.images.empty()) {
            auto ref = refs.get(between);
            if (!ref) return Error{ref.error()};
            r = write_example(options.images / (scene.name + ".png"), ref.value()->reference.image,
                              ref.value()->mask,
                              {&nearest.value()[1].image, &blend.value()[1].image,
                               &trace.value()[1].image, &phong.value()[1].image});
            if (!r) return Error{r.error()};
        }

        if (scene.sweeps) {
            struct Variant {
                const char* study;
                TableConfig config;
            };
            std::vector<Variant> variants;
            auto with = [&](const char* study, auto change) {
                TableConfig c = base;
                change(c);
                variants.push_back({study, c});
            };
            const std::uint32_t side = base.level;
            with("level", [&](TableConfig& c) { c.level = side / 2; });
            with("level", [&](TableConfig& c) { c.level = side * 2; });
            for (double s :
                 options.quick ? std::vector<double>{12} : std::vector<double>{3, 4, 8, 12}) {
                with("spacing", [&](TableConfig& c) { c.spacing_deg = s; });
            }
            if (!options.quick) {
                for (int d : {2, 4, 12}) with("depth", [&](TableConfig& c) { c.depth = d; });
                for (double t : {1e-2, 1e-3, 1e-5}) {
                    with("threshold", [&](TableConfig& c) { c.threshold = t; });
                }
                with("dispersion", [&](TableConfig& c) { c.dispersion = true; });
            }
            for (const Variant& v : variants) {
                auto db =
                    cache.get(scene.stone_name, scene.stone, v.config, scene.min_elevation_deg);
                if (!db) return Error{db.error()};
                // A different spacing stores other directions: its own on/between views.
                const ViewGrid& g = db.value().database->grid();
                const std::vector<std::pair<const char*, glm::dvec3>> vviews =
                    v.config.spacing_deg == base.spacing_deg
                        ? views
                        : std::vector<std::pair<const char*, glm::dvec3>>{
                              {"on", on_view(g, scene.target)},
                              {"between", between_view(g, scene.target)}};
                auto rows_v =
                    table_rows(ctx, scene, studio, refs, v.study, v.config, false, vviews);
                if (!rows_v) return Error{rows_v.error()};
            }
        }
        if (scene.name == "diamond-tilted" || scene.name == "oval-sapphire" || options.quick) {
            r = path_rows(ctx, scene, studio, base_db.value(), refs);
            if (!r) return Error{r.error()};
        }
    }
    return rows;
}

}  // namespace gem::accuracy
