#include "gpu/table_method.hpp"

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "gpu/channel_wavelengths.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/program_catalog.hpp"
#include "gpu/ring_renderer.hpp"
#include "gpu/stone_method.hpp"
#include "gpu/texel_array.hpp"
#include "util/elapsed.hpp"

namespace gem::gpu {

// The piece's textures after the views' (units 3-10): sixteen in all, the least ES 3.0
// guarantees a fragment shader.
constexpr int kPieceSightUnit = 11;
static_assert(kPieceSightUnit + RingRenderer::kPieceSightUnits <= 16);

namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

struct TableMethod::GpuView {
    std::shared_ptr<const DecodedView> source;  // identifies what is uploaded
    std::uint32_t view = 0;
    std::uint32_t level = 0;
    int side = 0;
    Texture pixels;
    Texture rays_a;
    Texture rays_b;
    Texture rays_c;
};

TableMethod::TableMethod(TableMethod&&) noexcept = default;
TableMethod& TableMethod::operator=(TableMethod&&) noexcept = default;
TableMethod::~TableMethod() = default;

Result<TableMethod> TableMethod::make(std::shared_ptr<const Database> database,
                                      const TableOptions& options) {
    TableMethod m;
    m.database_ = std::move(database);
    m.options_ = options;
    auto stone = StoneGeometry::upload(m.database_->stone());
    if (!stone) return Error{"table: " + stone.error()};
    m.stone_ = std::make_unique<StoneGeometry>(std::move(stone).value());
    m.programs_ = ProgramVariants(m.database_->stone().convex ? "table" : "table_non_convex", {});
    m.cache_ = std::make_unique<ViewCache>(std::make_shared<DatabaseViewSource>(m.database_),
                                           options.cache);
    return m;
}

std::uint32_t table_level_for(const Database& database, double pixels_across, int max_level) {
    const auto& levels = database.params().levels;
    std::uint32_t level = static_cast<std::uint32_t>(levels.size() - 1);
    for (std::uint32_t i = 0; i < levels.size(); ++i) {
        if (levels[i] >= pixels_across) {
            level = i;
            break;
        }
    }
    if (max_level >= 0) level = std::min(level, static_cast<std::uint32_t>(max_level));
    return level;
}

std::uint32_t TableMethod::level_for(double pixels_across) const {
    return table_level_for(*database_, pixels_across, options_.max_level);
}

void TableMethod::prefetch(const Camera& camera, std::span<const ViewHeading> headings, bool wait) {
    const double pixels_across = database_->camera().field_mm / camera.pixel_size();
    cache_->prefetch(headings, level_for(pixels_across));
    if (wait) cache_->wait_idle(std::chrono::seconds(60));
}

Result<const TableMethod::GpuView*> TableMethod::upload(const AcquiredView& acquired,
                                                        TableFrameStats& stats) {
    for (std::size_t i = 0; i < gpu_views_.size(); ++i) {
        if (gpu_views_[i]->source == acquired.view) {
            std::rotate(gpu_views_.begin(), gpu_views_.begin() + static_cast<long>(i),
                        gpu_views_.begin() + static_cast<long>(i) + 1);
            return gpu_views_.front().get();
        }
    }
    const auto start = Clock::now();
    const DecodedView& v = *acquired.view;
    auto view = std::make_unique<GpuView>();
    view->source = acquired.view;
    view->view = acquired.match.view;
    view->level = acquired.level;
    view->side = static_cast<int>(v.side);

    std::vector<std::uint32_t>& pixels = pixel_scratch_;
    pixels.resize(2 * v.ray_count.size());
    for (std::size_t p = 0; p < v.ray_count.size(); ++p) {
        pixels[2 * p] = v.ray_offset[p];
        pixels[2 * p + 1] = v.ray_count[p];
    }
    view->pixels = make_texture();
    glBindTexture(GL_TEXTURE_2D, view->pixels.get());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32UI, view->side, view->side, 0, GL_RG_INTEGER,
                 GL_UNSIGNED_INT, pixels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

    // a: direction, weight; b: position, path; c: d(direction)/dn (zero without), facet.
    const std::size_t rays = v.direction.size();
    std::vector<float>& a = ray_scratch_[0];
    std::vector<float>& b = ray_scratch_[1];
    std::vector<float>& c = ray_scratch_[2];
    a.resize(4 * rays);
    b.resize(4 * rays);
    c.resize(4 * rays);
    for (std::size_t r = 0; r < rays; ++r) {
        const glm::vec3 dn = v.dir_dn.empty() ? glm::vec3(0.0f) : v.dir_dn[r];
        const float ra[4] = {v.direction[r].x, v.direction[r].y, v.direction[r].z, v.weight[r]};
        const float rb[4] = {v.position[r].x, v.position[r].y, v.position[r].z, v.path_mm[r]};
        const float rc[4] = {dn.x, dn.y, dn.z, static_cast<float>(v.facet[r])};
        std::copy(ra, ra + 4, a.begin() + static_cast<std::ptrdiff_t>(4 * r));
        std::copy(rb, rb + 4, b.begin() + static_cast<std::ptrdiff_t>(4 * r));
        std::copy(rc, rc + 4, c.begin() + static_cast<std::ptrdiff_t>(4 * r));
    }
    Texture* targets[3] = {&view->rays_a, &view->rays_b, &view->rays_c};
    for (int i = 0; i < 3; ++i) {
        auto t = upload_texel_array(ray_scratch_[i].data(), rays, "table view rays");
        if (!t) return Error{t.error()};
        *targets[i] = std::move(t).value();
    }
    auto ok = gl_check("table method: view upload");
    if (!ok) return Error{ok.error()};

    // The least recently used beyond what the options keep go.
    gpu_views_.insert(gpu_views_.begin(), std::move(view));
    if (gpu_views_.size() > std::max<std::size_t>(options_.gpu_views, 3)) gpu_views_.pop_back();
    ++stats.uploads;
    stats.upload_ms += ms_since(start);
    return gpu_views_.front().get();
}

Result<bool> TableMethod::draw(const StoneFrame& frame, TableFrameStats* stats_out) {
    TableFrameStats stats;
    const Camera camera = stone_camera(frame);
    const CameraModel& model = database_->camera();
    const bool perspective = model.kind == CameraModel::Kind::perspective;
    if (perspective == camera.orthographic() ||
        (perspective &&
         std::abs(camera.distance() - model.distance_mm) > 1e-6 * model.distance_mm)) {
        return Error{"table method: the camera must be " +
                     std::string(perspective
                                     ? "perspective at " + std::to_string(model.distance_mm) +
                                           " mm, as the database was built"
                                     : "orthographic, as the database was built")};
    }
    const double image_scale = perspective ? camera.distance() : 1.0;
    const double pixels_across = model.field_mm / (camera.pixel_size() * image_scale);
    const std::uint32_t wanted = level_for(pixels_across);
    const glm::dvec3 asked = -camera.forward();
    const ViewGrid& grid = database_->grid();

    auto start = Clock::now();
    AcquiredView first = cache_->acquire(asked, wanted);
    // A scene's first frame finds nothing resident: wait for the view asked for (once).
    double cold_wait_ms = 0.0;
    if (!first.view && options_.wait_on_cold_start) {
        const auto waited = Clock::now();
        cache_->wait_idle(std::chrono::seconds(5));
        first = cache_->acquire(asked, wanted);
        cold_wait_ms = ms_since(waited);
    }
    std::array<ViewMatch, 3> near{};
    const std::size_t found = options_.blend ? grid.nearest_k(asked, near) : 0;
    AcquiredView second;
    double blend = 1.0;
    // Blend only when the nearest view itself is shown (not a stand-in for it). Weights
    // w_i ∝ (a2 − a_i) / a_i: the inverse angle makes the nearest view's weight 1 on a stored
    // direction (the view is exact there), the (a2 − a_i) factor takes the second view's weight
    // to 0 where it trades rank with the third, so the picture stays continuous as views change
    // rank, and equal angles (the midpoint) give equal weights.
    const double a0 = near[0].angle, a1 = near[1].angle, a2 = near[2].angle;
    if (found == 3 && a2 > a0) {
        const double w0 = (a2 - a0) * a1;  // both weights multiplied by a0 · a1
        const double w1 = (a2 - a1) * a0;
        blend = w0 + w1 > 0.0 ? w0 / (w0 + w1) : 1.0;
        if (first.view && first.match.view == near[0].view &&
            first.match.symmetry == near[0].symmetry) {
            second = cache_->acquire_view(near[1], wanted);
        }
    }
    stats.acquire_ms = ms_since(start) - cold_wait_ms;
    stats.wait_ms = cold_wait_ms;
    if (options_.wait_for_views &&
        (!first.exact || (second.view && !second.exact) || (blend < 1.0 && !second.view))) {
        start = Clock::now();
        cache_->wait_idle(std::chrono::seconds(60));
        first = cache_->acquire(asked, wanted);
        if (blend < 1.0) {
            second = cache_->acquire_view(near[1], wanted);
            if (!second.exact) {
                cache_->wait_idle(std::chrono::seconds(60));
                second = cache_->acquire_view(near[1], wanted);
            }
        }
        stats.wait_ms += ms_since(start);
    }
    stats.level = first.level;
    stats.exact = first.exact;
    stats.complete = first.exact && (blend >= 1.0 || (second.view && second.exact));
    stats.angle_rad = first.match.angle;
    if (!first.view) {
        if (stats_out != nullptr) *stats_out = stats;
        return true;  // cold start, not waited for: nothing resident yet, the background shows
    }

    auto g0 = upload(first, stats);
    if (!g0) return Error{g0.error()};
    const GpuView* v0 = g0.value();
    const GpuView* v1 = nullptr;
    if (second.view) {
        auto g1 = upload(second, stats);
        if (!g1) return Error{g1.error()};
        v1 = g1.value();
        // upload() may have reordered the list; v0 still points at a live view (three kept).
    }

    const bool dispersion = database_->params().dispersion;
    const std::uint32_t features = shading_features(frame) | (dispersion ? kFireFirstOrder : 0u) |
                                   (v1 != nullptr ? kTwoViews : 0u);
    const auto attach = [&](const Program& built) { stone_->attach(built); };
    auto chosen = programs_.get(features, attach);
    if (!chosen) return Error{chosen.error()};
    if (options_.blend) {
        // A blend draws one view on a stored direction and two between them: both programs
        // are built at the first draw, so a turn never waits for a compile (a map lookup
        // after that).
        auto other = programs_.get(features ^ kTwoViews, attach);
        if (!other) return Error{other.error()};
    }
    const Program& p = *chosen.value();
    const PipelineScope pass(StoneGeometry::front_faces(p));
    set_camera_uniforms(p, frame);
    const SamplerBinding sharp = set_shading_uniforms(p, frame, 0);
    stone_->bind(p, 1);
    p.set("u_field_mm", static_cast<float>(model.field_mm));
    p.set("u_image_scale", static_cast<float>(image_scale));
    if (dispersion) {
        const auto nd = static_cast<float>(frame.material.index());
        p.set("u_dn_channel", channel_indices(frame.material) - glm::vec3(nd));
    }
    // table.frag's uniforms of view slots 0 and 1: four textures, image map, frame, side.
    static constexpr const char* kSlotUniforms[2][7] = {
        {"u_pixels0", "u_rays_a0", "u_rays_b0", "u_rays_c0", "u_image_map0", "u_to_stone0",
         "u_side0"},
        {"u_pixels1", "u_rays_a1", "u_rays_b1", "u_rays_c1", "u_image_map1", "u_to_stone1",
         "u_side1"}};
    auto bind_view = [&](const GpuView& v, const AcquiredView& a, int slot, int unit) {
        const char* const* names = kSlotUniforms[slot];
        const Texture* textures[4] = {&v.pixels, &v.rays_a, &v.rays_b, &v.rays_c};
        for (int i = 0; i < 4; ++i) {
            glActiveTexture(GL_TEXTURE0 + unit + i);
            glBindTexture(GL_TEXTURE_2D, textures[i]->get());
            p.set(names[i], unit + i);
        }
        const glm::dmat2 map = grid.image_map(a.match, asked, camera.right(), camera.up());
        p.set(names[4], glm::mat2(map));
        // g · asked ≈ stored, so a stored-frame vector v is gᵀ v in the stone frame.
        p.set(names[5], glm::mat3(glm::transpose(grid.group()[a.match.symmetry])));
        p.set(names[6], v.side);
    };
    bind_view(*v0, first, 0, 3);
    if (v1 != nullptr) {
        p.set("u_blend", static_cast<float>(blend));
        bind_view(*v1, second, 1, 7);
    }
    set_piece_sight_uniforms(p, frame, kPieceSightUnit);

    stone_->draw_triangles();
    stats.drawn = true;
    stats.views = v1 != nullptr ? 2 : 1;
    stats.blend = v1 != nullptr ? blend : 1.0;
    if (stats_out != nullptr) *stats_out = stats;
    return gl_check("table method");
}

namespace {

// The table method as a stone method: the one loose stone its database holds, its views
// streamed ahead of the turn by prepare().
class TableStones final : public StoneMethod {
  public:
    explicit TableStones(TableMethod table) : table_(std::move(table)) {}

    void prepare(const Camera& camera, const glm::dvec3& omega, bool wait) override {
        const ViewHeading heading{-camera.forward(), omega};
        table_.prefetch(camera, std::span<const ViewHeading>(&heading, 1), wait);
    }

    Result<bool> draw(const std::vector<StoneFrame>& frames, const std::vector<std::size_t>& kinds,
                      FrameStats& stats) override {
        (void)kinds;
        for (const StoneFrame& frame : frames) {
            auto ok = table_.draw(frame, &stats.table);
            if (!ok) return ok;
            stats.stand_in = stats.stand_in || !stats.table.complete;
        }
        return true;
    }

  private:
    TableMethod table_;
};

}  // namespace

Result<std::unique_ptr<StoneMethod>> make_table_stones(const FrameSetup& setup,
                                                       const std::vector<const Stone*>& kinds) {
    (void)kinds;  // the database's stone
    if (setup.database == nullptr)
        return Error{"frame renderer: the table method needs a database"};
    auto made = TableMethod::make(setup.database, setup.table);
    if (!made) return Error{made.error()};
    return std::unique_ptr<StoneMethod>(std::make_unique<TableStones>(std::move(made).value()));
}

namespace {

std::vector<ProgramSpec> table_programs() {
    constexpr std::uint32_t kFeatures = kShadingFeatures | kFireFirstOrder | kTwoViews;
    // The thesis' shading stage from ray-tables (table_method.hpp).
    return {
        {"table", {"stone.vert"}, stone_method_sources("table.frag"), {}, kFeatures},
        {"table_non_convex",
         {"stone.vert"},
         stone_method_sources("table.frag"),
         {"NON_CONVEX"},
         kFeatures},
    };
}

// Two stored views blended at the level the picture's size needs, the nearest view alone,
// and the nearest a level lower (only where there is one, else it would repeat the one before).
std::vector<MethodRung> table_rungs(const RungContext& context) {
    std::vector<MethodRung> rungs{{"table", true, -1, "table blend"},
                                  {"table", false, -1, "table nearest"}};
    if (context.needed_level > 0) {
        const int lower = context.needed_level - 1;
        rungs.push_back({"table", false, lower, "table nearest level " + std::to_string(lower)});
    }
    return rungs;
}

}  // namespace

extern const MethodEntry kTableMethod;
constinit const MethodEntry kTableMethod{.name = "table",
                                         .needs_database = true,
                                         .draws_pieces = false,
                                         .refracts = true,
                                         .opacity_from_alpha = false,
                                         .make = make_table_stones,
                                         .programs = table_programs,
                                         .rungs = table_rungs};

}  // namespace gem::gpu
