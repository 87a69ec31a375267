#include "stage/stone_scene.hpp"

#include <numbers>

#include "gemdb/reader.hpp"
#include "gpu/stone_method.hpp"
#include "gpu/stone_models.hpp"
#include "picture/camera.hpp"
#include "piece/metal_obj.hpp"
#include "scene/scene.hpp"
#include "stage/start_view.hpp"

namespace gem::kiosk {

namespace {

Result<Environment> make_environment(const LookChoice& look) {
    Environment environment = Environment::studio();
    switch (look.background) {
        case LookChoice::Background::uniform:
            environment = Environment::uniform(look.colour);
            break;
        case LookChoice::Background::image: {
            auto loaded = Environment::load_image(look.image);
            if (!loaded) return Error{loaded.error()};
            environment = std::move(loaded).value();
            break;
        }
        case LookChoice::Background::tent:
            environment = Environment::light_tent();
            break;
        case LookChoice::Background::studio:
        case LookChoice::Background::colour:
            break;
    }
    return environment.with_intensity(look.environment_intensity);
}

Result<MetalMesh> make_ring(const CatalogueStone& stone, const Stone& geometry) {
    if (stone.ring == RingKind::obj && stone.ring_mesh) return *stone.ring_mesh;
    if (stone.ring == RingKind::obj) {
        return load_metal_obj(stone.ring_obj, stone.metal, RingParams{}.roughness);
    }
    RingParams params;
    params.metal = stone.metal;
    return make_ring(params, geometry);
}

}  // namespace

Result<std::unique_ptr<StoneScene>> StoneScene::make(
    const CatalogueStone& stone, const LookChoice& look, const RenderChoice& render,
    const std::vector<std::shared_ptr<const Database>>& kind_tables) {
    auto fail = [&](const std::string& why) { return Error{"stone '" + stone.name + "': " + why}; };
    std::unique_ptr<StoneScene> scene(new StoneScene());
    scene->name_ = stone.name;
    // Validation mapped and checked the database, or built the design's stone; a stone with
    // neither (a test's hand-made catalogue) has its database opened here.
    scene->database_ = stone.opened;
    scene->designed_ = stone.designed;
    scene->piece_ = stone.placed;
    if (!scene->database_ && !scene->designed_ && !scene->piece_) {
        auto database = Database::open(stone.database);
        if (!database) return fail(database.error());
        scene->database_ = std::make_shared<const Database>(std::move(database).value());
    }
    const double to_deg = 180.0 / std::numbers::pi;
    // A design has no tables, so no band of stored views: any elevation is exact.
    scene->min_elevation_deg_ =
        scene->database_ ? scene->database_->params().grid.min_elevation_rad * to_deg : -90.0;
    scene->max_elevation_deg_ = 90.0;
    const Stone& geometry = scene->stone();

    auto environment = make_environment(look);
    if (!environment) return fail(environment.error());
    scene->environment_ = std::move(environment).value();

    gpu::FrameSetup setup;
    // A design or a piece is drawn by the exact trace, which needs no tables, where the
    // configured method cannot draw it (phong, the baseline, draws either).
    const gpu::MethodEntry* chosen = gpu::find_stone_method(render.method);
    if (chosen == nullptr) return fail("no stone method '" + render.method + "'");
    const bool drawable = scene->piece_ ? chosen->draws_pieces
                                        : scene->database_ != nullptr || !chosen->needs_database;
    const gpu::MethodEntry& method = drawable ? *chosen : gpu::fallback_stone_method();
    setup.method = method.name;
    setup.piece = scene->piece_.get();
    if (scene->piece_) setup.kind_tables = kind_tables;
    setup.database = scene->database_;
    setup.stone = geometry;
    setup.material = scene->database_ ? scene->database_->material() : geometry.material;
    if (stone.colour) setup.material.body_colour = *stone.colour;
    if (stone.absorption_per_mm) setup.material.absorption_per_mm = *stone.absorption_per_mm;
    setup.shading.lights = look.lights;
    // The scene default gemrender uses (scene/scene.hpp), 0.8, where the method draws the stone
    // with opacity 1 − α (phong): the physical model's α = 1 would leave only the metal.
    if (method.opacity_from_alpha) setup.shading.alpha = Scene{}.alpha;
    setup.trace.max_depth = render.depth;
    // Fire where the database stores it: each colour channel traced at its own index, or as
    // the tables show it, each exit's channels moved by their direction's derivative.
    const bool fire =
        scene->database_ ? scene->database_->params().dispersion : geometry.material.disperses();
    if (fire) {
        setup.trace_dispersion =
            render.exact_fire ? gpu::TraceDispersion::exact : gpu::TraceDispersion::first_order;
    }
    setup.table.blend = render.blend;
    setup.table.max_level = render.max_level;
    setup.table.cache.memory_bytes = render.cache_bytes;
    setup.table.wait_for_views = render.wait_for_views;
    setup.environment = &scene->environment_;
    setup.cube_face = render.cube_face;
    if (look.background == LookChoice::Background::colour ||
        look.background == LookChoice::Background::tent) {
        setup.background_colour = glm::vec3(look.colour * look.background_intensity);
    }
    if (stone.ring != RingKind::none && !scene->piece_) {
        auto ring = make_ring(stone, geometry);
        if (!ring) return fail(ring.error());
        scene->ring_ = std::move(ring).value();
        setup.ring = &scene->ring_;
    }
    auto renderer = gpu::FrameRenderer::make(std::move(setup));
    if (!renderer) return fail(renderer.error());
    scene->renderer_.emplace(std::move(renderer).value());
    scene->stone_share_ = render.stone_share;
    return scene;
}

const Stone& StoneScene::stone() const {
    if (piece_) return piece_->stone_of(0);
    return database_ ? database_->stone() : *designed_;
}

const Framing& StoneScene::framing(glm::ivec2 size) const {
    if (size == framed_size_) return framing_;
    // The hero is the loose stone, or a piece's centre stone; everything else is "ring".
    std::vector<glm::dvec3> stone = this->stone().vertices;
    // A piece whose centre stone is no larger than the rest (a band, three equal stones, a
    // file's stones merged into one mesh, each a kind of its own) has no hero: the whole piece
    // is framed, as tight as it fits (a share no stone reaches). A centre stone a tenth larger
    // than every other is the hero.
    bool hero = !piece_ || piece_->stones.size() == 1;
    if (piece_ && !hero) {
        const double centre = bounding_radius(piece_->stone_of(0).vertices);
        hero = true;
        for (std::size_t i = 1; i < piece_->stones.size() && hero; ++i) {
            hero = centre > 1.1 * bounding_radius(piece_->stone_of(i).vertices);
        }
    }
    const double share = hero ? stone_share_ : 1e-3;
    const MetalMesh& metal = piece_ ? piece_->metal : ring_;
    std::vector<glm::dvec3> ring(metal.positions.begin(), metal.positions.end());
    if (piece_) {
        for (glm::dvec3& p : stone) p = piece_->stones.front().placement.to_piece(p);
        for (std::size_t i = 1; i < piece_->stones.size(); ++i) {
            for (const glm::dvec3& p : piece_->stone_of(i).vertices) {
                ring.push_back(piece_->stones[i].placement.to_piece(p));
            }
        }
    }
    framing_ = frame_ring(stone, ring, kStartView, size, renderer_->scene_radius_mm(), share);
    framed_size_ = size;
    return framing_;
}

Result<std::vector<std::string>> StoneScene::choose_stone_models(glm::ivec2 size) {
    std::vector<std::string> lines;
    if (!piece_) return lines;
    auto camera = this->camera(kStartView, size);
    if (!camera) return Error{"stone models: " + camera.error()};
    auto chosen = gpu::choose_stone_models(*renderer_, camera.value());
    if (!chosen) return Error{chosen.error()};
    for (const gpu::ModelChoice& choice : chosen.value()) {
        std::size_t instances = 0;
        for (const PieceStone& s : piece_->stones) instances += s.kind == choice.kind ? 1 : 0;
        lines.push_back("stone model: " + gpu::describe(choice, *renderer_, instances));
    }
    return lines;
}

gpu::FrameView StoneScene::frame_view(const ViewState& view, glm::ivec2 size) const {
    return {.camera = framed_camera(view, framing(size)),
            .framing_mm = renderer_->scene_radius_mm()};
}

Result<Camera> StoneScene::camera(const ViewState& view, glm::ivec2 size) const {
    const gpu::FrameView v = frame_view(view, size);
    return Camera::make(v.camera, v.framing_mm, size.x, size.y);
}

}  // namespace gem::kiosk
