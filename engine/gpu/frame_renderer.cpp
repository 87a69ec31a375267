#include "gpu/frame_renderer.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

#include "gpu/gl_check.hpp"
#include "gpu/phong_method.hpp"
#include "gpu/piece_tables.hpp"
#include "gpu/ring_renderer.hpp"
#include "piece/ring_mesh.hpp"
#include "piece/sight_groups.hpp"
#include "util/elapsed.hpp"

namespace gem::gpu {

FrameRenderer::FrameRenderer(FrameRenderer&&) noexcept = default;
FrameRenderer& FrameRenderer::operator=(FrameRenderer&&) noexcept = default;
FrameRenderer::~FrameRenderer() = default;

const Stone& FrameRenderer::stone() const {
    if (setup_.piece != nullptr) return setup_.piece->stone_of(0);
    return setup_.database != nullptr && method_entry_->needs_database ? setup_.database->stone()
                                                                       : setup_.stone;
}

const Stone& FrameRenderer::kind(std::size_t k) const {
    // Looked up, not kept: a loose stone lives in this renderer, which may have moved.
    return setup_.piece != nullptr ? setup_.piece->kinds[k] : stone();
}

std::size_t FrameRenderer::first_of_kind(std::size_t k) const {
    for (std::size_t i = 0; i < kinds_.size(); ++i) {
        if (kinds_[i] == k) return i;
    }
    return 0;
}

Result<bool> FrameRenderer::draw_kind_alone(std::size_t k, const Camera& camera,
                                            const StoneModel& model) {
    const std::size_t first = first_of_kind(k);
    StoneFrame frame = frames_[first];
    frame.placement = {};
    frame.stone = &kind(k);
    frame.camera = camera;
    frame.piece_sight = nullptr;
    set_sight(frame, first);
    frame.scene_radius_mm = bounding_radius(frame.stone->vertices) * 1.01;
    glClearDepthf(1.0f);
    glClear(GL_DEPTH_BUFFER_BIT);
    return method_->draw_alone(k, frame, model);
}

Result<FrameRenderer> FrameRenderer::make(FrameSetup setup) {
    if (setup.environment == nullptr) return Error{"frame renderer: no environment"};
    const MethodEntry* entry = find_stone_method(setup.method);
    if (entry == nullptr) {
        return Error{"frame renderer: no stone method '" + setup.method + "' (this build has " +
                     stone_method_names() + ")"};
    }
    if (entry->needs_database && setup.database == nullptr) {
        return Error{"frame renderer: the " + setup.method + " method needs a database"};
    }
    FrameRenderer r;
    r.method_entry_ = entry;
    r.visibility_ = std::make_unique<VisibilityTarget>();
    r.check_label_ = "frame (" + setup.method + ")";
    r.setup_ = std::move(setup);
    const FrameSetup& s = r.setup_;
    auto background = BackgroundPass::make();
    if (!background) return Error{background.error()};
    r.background_ = std::make_unique<BackgroundPass>(std::move(background).value());
    auto cube = EnvironmentCube::from_environment(*s.environment, s.cube_face);
    if (!cube) return Error{cube.error()};
    r.environment_cube_ = std::make_unique<EnvironmentCube>(std::move(cube).value());

    // The kinds of stone and where each stone is drawn: a piece's, or the one loose stone.
    std::vector<const Stone*> kinds;
    if (s.piece != nullptr) {
        if (!entry->draws_pieces) {
            return Error{"frame renderer: the " + s.method +
                         " method draws one loose stone, not a piece (a database holds one)"};
        }
        if (s.piece->stones.empty()) return Error{"frame renderer: the piece has no stones"};
        for (const Stone& kind : s.piece->kinds) kinds.push_back(&kind);
        for (const PieceStone& p : s.piece->stones) {
            StoneFrame frame;
            frame.material = kinds[p.kind]->material;
            frame.placement = p.placement;
            r.frames_.push_back(std::move(frame));
            r.kinds_.push_back(p.kind);
        }
    } else {
        kinds.push_back(&r.stone());
        StoneFrame frame;
        frame.material = s.material;
        r.frames_.push_back(std::move(frame));
        r.kinds_.push_back(0);
    }
    for (std::size_t i = 0; i < r.frames_.size(); ++i) {
        r.frames_[i].shading = s.shading;
        r.frames_[i].stone_id = static_cast<std::uint32_t>(i + 1);  // the visibility pass's
    }
    r.kind_count_ = kinds.size();
    auto method = entry->make(s, kinds);
    if (!method) return Error{method.error()};
    r.method_ = std::move(method).value();
    if (s.piece != nullptr && !s.kind_tables.empty()) {
        std::vector<Placement> placements;
        for (const StoneFrame& frame : r.frames_) placements.push_back(frame.placement);
        auto tabled = with_kind_tables(std::move(r.method_), s, kinds, r.kinds_, placements);
        if (!tabled) return Error{"frame renderer: " + tabled.error()};
        r.method_ = std::move(tabled).value();
    }
    // What the frame draws, in boxes each small on the picture (cover()): a box about each stone
    // where it sits, and the metal's cells.
    for (std::size_t i = 0; i < r.frames_.size(); ++i) {
        CoverBox box{glm::dvec3(std::numeric_limits<double>::infinity()),
                     glm::dvec3(-std::numeric_limits<double>::infinity())};
        for (const glm::dvec3& v : kinds[r.kinds_[i]]->vertices) {
            const glm::dvec3 p = r.frames_[i].placement.to_piece(v);
            box.lo = glm::min(box.lo, p);
            box.hi = glm::max(box.hi, p);
        }
        r.cover_boxes_.push_back(box);
    }
    r.stone_radius_mm_ = bounding_radius(r.stone().vertices);
    r.scene_radius_mm_ = (s.piece != nullptr ? s.piece->radius_mm() : r.stone_radius_mm_) * 1.01;
    const MetalMesh* metal = s.piece != nullptr ? &s.piece->metal : s.ring;
    if (metal != nullptr && !metal->indices.empty()) {
        auto ring = RingRenderer::make(*metal, *r.environment_cube_);
        if (!ring) return Error{ring.error()};
        r.ring_ = std::make_unique<RingRenderer>(std::move(ring).value());
        // In a still view the metal and the stones see the piece, its metal and stones, as the
        // reference's do.
        std::vector<PlacedStone> placed;
        for (std::size_t i = 0; i < r.frames_.size(); ++i) {
            placed.push_back({kinds[r.kinds_[i]], r.frames_[i].placement, &r.frames_[i].material});
        }
        // Where the GPU cannot hold it, the metal sees the environment alone and the stones
        // their cubes, as a moving frame's do, and it says why: the piece is still shown.
        auto sight = PieceSight::make(sight_mesh(*metal, placed));
        auto sees = sight ? r.ring_->see_piece(std::move(sight).value(),
                                               glm::vec3(s.environment->mean_radiance()))
                          : Result<bool>(Error{sight.error()});
        if (!sees) {
            r.sight_note_ =
                "the metal sees the environment alone and the stones their cubes, not their "
                "piece: " +
                sees.error();
        }
        r.scene_radius_mm_ = std::max(r.scene_radius_mm_, metal->radius_mm() * 1.01);
        r.ring_radius_mm_ = metal->radius_mm();
        // Cells of a 48th of the metal's diameter: at the start view a tile is about one.
        const std::vector<CoverBox> cells = metal_cover_boxes(*metal, metal->radius_mm() / 24.0);
        r.cover_boxes_.insert(r.cover_boxes_.end(), cells.begin(), cells.end());
        // Each group of stones sees the metal from its own centre (piece/sight_groups.hpp), a
        // loose stone from its own. A loose stone's cube faces stand about as far as the ring's
        // radius, so rays leaving off-centre see it with parallax. A piece's groups look their
        // cubes up by direction alone (a cube at infinity): against the exact reference, a
        // parallax box (about each stone's frame origin) of 8, 16, 32 and 100 times a group's
        // reach gave the halo 7.8, 7.0, 6.6 and 6.5 ΔE00 and at infinity 6.4; the solitaire
        // 6.9, -, 5.1, 4.7 and 4.7 (scripts/piece_accuracy.sh, 2026-12-05).
        std::vector<SightGroup> groups;
        if (s.piece != nullptr) groups = sight_groups(*s.piece);
        if (groups.empty()) groups.push_back({glm::dvec3(0.0), true, {0}});
        r.sight_of_.assign(r.frames_.size(), 0);
        for (std::size_t g = 0; g < groups.size(); ++g) {
            const SightGroup& group = groups[g];
            // Small stones' cubes at a quarter of the face: half measured the same, at twice
            // the cost (docs/pieces.md).
            const int face = group.own ? s.cube_face : std::max(64, s.cube_face / 4);
            auto sight_cube = EnvironmentCube::allocate(face);
            if (!sight_cube) return Error{sight_cube.error()};
            r.sight_cubes_.push_back(
                {std::make_unique<EnvironmentCube>(std::move(sight_cube).value()), group.centre});
            for (const std::size_t i : group.stones) r.sight_of_[i] = g;
        }
        auto updated = r.update_ring_cube();
        if (!updated) return Error{updated.error()};
    }
    return r;
}

Result<bool> FrameRenderer::update_ring_cube() {
    if (!ring_) return true;
    // The ring renderer restores the caller's framebuffer and viewport itself.
    for (SightCube& sight : sight_cubes_) {
        auto ok = ring_->render_environment_cube(*environment_cube_, *sight.cube, setup_.shading,
                                                 sight.centre);
        if (!ok) return ok;
    }
    return true;
}

void FrameRenderer::set_sight(StoneFrame& frame, std::size_t i) const {
    if (sight_cubes_.empty()) {
        frame.environment = environment_cube_.get();
        frame.cube_half_mm = 0.0;
        return;
    }
    frame.environment = sight_cubes_[sight_of_[i]].cube.get();
    // A piece's cubes by direction (0: at infinity); a loose stone's with parallax, its faces
    // about as far as the ring's radius.
    frame.cube_half_mm = setup_.piece != nullptr ? 0.0 : ring_radius_mm_;
}

Result<bool> FrameRenderer::set_lights(const std::vector<Light>& lights) {
    setup_.shading.lights = lights;
    for (StoneFrame& frame : frames_) frame.shading.lights = lights;
    return update_ring_cube();
}

std::optional<glm::vec3> FrameRenderer::flat_background(const Camera& camera) const {
    // An orthographic camera sees the environment along one direction only, so its background
    // is one colour: a clear, not a pass of cube lookups over every pixel (8 ms a frame at
    // 1024² on llvmpipe, whatever the stone covers). The studio's is the same colour all round
    // a turn at one elevation.
    if (setup_.background_colour) return setup_.background_colour;
    if (camera.orthographic()) return glm::vec3(setup_.environment->radiance(camera.forward()));
    return std::nullopt;
}

const SceneCover* FrameRenderer::cover(const Camera& camera) {
    const std::optional<glm::vec3> background = flat_background(camera);
    // The boxes are projected as an orthographic camera sees them; a perspective one (a loose
    // stone seen from a distance, on a flat colour) finishes the whole picture.
    if (!background || !camera.orthographic()) return nullptr;
    // Two pixels more each way: a triangle's edge rasterises into the pixels it touches, and
    // MSAA's samples sit within them.
    mark_cover(cover_boxes_, camera, 2, cover_.tiles);
    cover_.background = *background;
    return &cover_;
}

VisibilityAttachment FrameRenderer::attach_visibility(const Camera& camera,
                                                      const StillFrame& still) {
    if (setup_.visibility_pass == VisibilityPass::off || !method_->shades_by_visibility()) {
        return {};
    }
    GLint stencil = 0, samples = 0;
    glGetIntegerv(GL_STENCIL_BITS, &stencil);
    glGetIntegerv(GL_SAMPLES, &samples);
    if (stencil < 8 || frames_.size() > 255) return {};
    if (samples > 0) {
        if (setup_.visibility_pass == VisibilityPass::where_it_pays && frames_.size() < 2) {
            return {};
        }
        // A metal that follows its rays through the piece marks no samples (its program has
        // no such output); a still view's frames are single samples.
        if (ring_ && ring_->follows_piece(still.index)) return {};
    }
    return visibility_->attach(glm::ivec2(camera.width(), camera.height()), samples);
}

Result<FrameStats> FrameRenderer::render(const Camera& camera, FrameWait wait,
                                         const StillFrame& still) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    FrameStats stats;
    glClearDepthf(1.0f);
    glClearStencil(0);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    auto ok = background_->draw(camera, *environment_cube_, flat_background(camera));
    if (!ok) return Error{ok.error()};
    // One pass timed alone (FrameWait::passes): from the glFinish before it to one after it.
    if (wait == FrameWait::passes) glFinish();
    auto pass_start = Clock::now();
    const auto passed = [&](double& ms) {
        if (wait != FrameWait::passes) return;
        glFinish();
        ms += ms_since(pass_start);
        pass_start = Clock::now();
    };

    if (setup_.piece != nullptr && !camera.orthographic()) {
        return Error{
            "frame renderer: a piece is drawn with an orthographic camera (a "
            "perspective eye off a stone's axis is no orbit about it)"};
    }
    for (std::size_t i = 0; i < frames_.size(); ++i) {
        StoneFrame& frame = frames_[i];
        // Filled in here: the stone lives in this renderer (or its piece), which may have moved.
        frame.stone = &kind(kinds_[i]);
        frame.camera = camera;
        set_sight(frame, i);
        frame.scene_radius_mm = scene_radius_mm_;
        frame.still = still;
        // As the metal's rays (RingRenderer::draw), from the still view's second frame.
        frame.piece_sight = ring_ && ring_->follows_piece(still.index) ? ring_.get() : nullptr;
    }
    // The stones' depth first (where the method has that pass), then the metal, then the
    // stones: each is shaded only where it is seen. Stones shaded before the metal cost every
    // pixel the metal then covers: a band's far side, the halo's stones under their beads
    // (bench_pieces: the band's stone pass shaded 130k pixels to keep 46k).
    // With the visibility target, the depth pass also writes each pixel's stone (the stencil)
    // and entry facet (the target), and the metal in front of a stone takes its stencil back,
    // so that each stone is then shaded as one rectangle under a stencil test: a fragment
    // shader runs on whole blocks of pixels, and drawn facet by facet a block ran once per
    // facet triangle it met (bench_pieces: 1.6 facets a block for the halo's stones).
    // In a multisampled frame each sample holds its stone and facet, and each stone's pixel
    // traces each facet its samples show once, weighed by them (trace.frag).
    const VisibilityAttachment visibility = attach_visibility(camera, still);
    // The target is off the framebuffer again however the stones' passes end; a frame copied
    // from these (a stone drawn alone) is drawn facet by facet.
    struct VisibilityEnd {
        std::vector<StoneFrame>& frames;
        const VisibilityTarget& target;
        bool attached;
        // Read by the stones' pass, so no longer drawn into.
        void detach() {
            if (!attached) return;
            const GLenum scene_only[] = {GL_COLOR_ATTACHMENT0};
            glDrawBuffers(1, scene_only);
            target.detach();
            attached = false;
        }
        ~VisibilityEnd() {
            detach();
            for (StoneFrame& frame : frames) frame.visibility = {};
        }
    } visibility_end{frames_, *visibility_, visibility.texture != 0};
    for (StoneFrame& frame : frames_) frame.visibility = visibility;
    if (visibility.texture != 0) {
        const GLenum ids[] = {GL_NONE, GL_COLOR_ATTACHMENT1};
        glDrawBuffers(2, ids);
    }
    auto depth = method_->draw_depth(frames_, kinds_);
    // The metal in front of a stone takes its stencil back; in a multisampled frame it also
    // writes no stone into the target at the samples it takes (the stones' pass, which reads a
    // pixel's samples there, cannot read the stencil).
    MetalMarks metal_marks = MetalMarks::none;
    if (visibility.texture != 0) {
        metal_marks = visibility.samples > 0 && ring_ != nullptr ? MetalMarks::stencil_and_target
                                                                 : MetalMarks::stencil;
        if (metal_marks == MetalMarks::stencil_and_target) {
            const GLenum both[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
            glDrawBuffers(2, both);
        } else {
            visibility_end.detach();
        }
        stats.stones_by_visibility = true;
    }
    if (!depth) return Error{depth.error()};
    passed(stats.stone_depth_ms);
    if (ring_) {
        ok = ring_->draw(camera, scene_radius_mm_, setup_.shading, still.index, metal_marks);
        visibility_end.detach();
        if (!ok) return Error{ok.error()};
        passed(stats.metal_ms);
    }
    const auto submit_start = Clock::now();
    ok = method_->draw(frames_, kinds_, stats);
    if (!ok) return Error{ok.error()};
    stats.stone_submit_ms = ms_since(submit_start);
    passed(stats.stone_ms);
    stats.stone_ms += stats.stone_depth_ms;
    if (wait != FrameWait::none) glFinish();
    stats.cpu_ms = ms_since(start);
    auto clean = gl_check(check_label_);
    if (!clean) return Error{clean.error()};
    return stats;
}

}  // namespace gem::gpu
