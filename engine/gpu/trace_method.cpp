#include "gpu/trace_method.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>

#include <GLES3/gl31.h>

#include "gpu/channel_wavelengths.hpp"
#include "gpu/environment_cube.hpp"
#include "gpu/framebuffer_scope.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/program_catalog.hpp"
#include "gpu/render_target.hpp"
#include "gpu/ring_renderer.hpp"
#include "gpu/stone_method.hpp"
#include "picture/camera.hpp"
#include "trace/convex_pieces.hpp"
#include "trace/folded_exit.hpp"
#include "util/elapsed.hpp"

namespace gem::gpu {
namespace {

// Texture units: the environment cube, then the stone's guess map or triangles.
constexpr int kEnvironmentUnit = 0;
constexpr int kStoneUnit = 1;
constexpr int kPieceSightUnit = 2;  // and the next RingRenderer::kPieceSightUnits - 1
constexpr int kVisibilityUnit = kPieceSightUnit + RingRenderer::kPieceSightUnits;
static_assert(kVisibilityUnit < 16);

// A GLSL float literal with nine significant digits (a float's round trip) and always a point
// or an exponent: "1" would be an int, and GLSL ES does not mix ints into float arithmetic.
std::string glsl_float(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    std::string literal = text;
    if (literal.find_first_of(".e") == std::string::npos) literal += ".0";
    return literal;
}

std::string glsl_vec2(glm::dvec2 v) {
    return "vec2(" + glsl_float(v.x) + ", " + glsl_float(v.y) + ")";
}

// One plane's arguments to EXIT_PLANE and FOLDED_PLANE: n.x, n.y, n.z, d.
std::string plane_arguments(const Plane& p) {
    return glsl_float(p.n.x) + ", " + glsl_float(p.n.y) + ", " + glsl_float(p.n.z) + ", " +
           glsl_float(p.d);
}

// trace.frag's STONE_EXIT_PLANES: one EXIT_PLANE(index, n.x, n.y, n.z, d) per facet.
std::string exit_planes_define(const Stone& stone) {
    std::string text = "STONE_EXIT_PLANES";
    for (std::size_t i = 0; i < stone.facets.size(); ++i) {
        text += " EXIT_PLANE(" + std::to_string(i) + ", " + plane_arguments(stone.facets[i].plane) +
                ")";
    }
    return text;
}

// trace.frag's EXIT_FOLDED constants (trace/folded_exit.hpp).
std::vector<std::string> folded_defines(const Stone& stone, const FoldedExit& fold) {
    std::vector<std::string> defines = {"EXIT_FOLDED",
                                        "FOLD_LEVELS " + std::to_string(fold.levels()),
                                        "FOLD_WEDGES " + std::to_string(fold.wedges())};
    std::string mirrors = "FOLD_MIRROR_LIST";
    for (std::size_t i = 0; i < fold.mirrors().size(); ++i) {
        mirrors += (i == 0 ? " " : ", ") + glsl_vec2(fold.mirrors()[i]);
    }
    defines.push_back(mirrors);
    defines.push_back("FOLD_EDGE_LO " + glsl_vec2(fold.wedge_edges()[0]));
    defines.push_back("FOLD_EDGE_HI " + glsl_vec2(fold.wedge_edges()[1]));
    defines.push_back("FOLD_INSIDE " + glsl_float(fold.inside()));
    const TurnedOutline& o = fold.outline();
    defines.push_back("FOLD_GUESS_Z_SCALE " + glsl_float(o.z_scale));
    defines.push_back("FOLD_GUESS_RADIUS " + glsl_float(o.radius));
    defines.push_back("FOLD_GUESS_Y " + glsl_vec2({o.y_min, o.y_max}));
    if (o.pavilion_slope > 0.0) {
        defines.push_back("FOLD_GUESS_PAVILION " + glsl_vec2({o.pavilion_slope, o.y_min}));
    }
    if (o.crown_slope > 0.0) {
        defines.push_back("FOLD_GUESS_CROWN " + glsl_vec2({o.crown_slope, o.crown_apex}));
    }
    std::string planes = "FOLDED_PLANES";
    for (std::uint32_t c : fold.candidates()) {
        planes += " FOLDED_PLANE(" + plane_arguments(stone.facets[c].plane) + ")";
    }
    defines.push_back(planes);
    return defines;
}

// trace.frag's PIECES constants (trace/convex_pieces.hpp).
static_assert(ConvexPieces::kMaxPieces <= 4,
              "trace.frag keeps each piece's nearest plane in a vec4");
std::vector<std::string> pieces_defines(const Stone& stone, const ConvexPieces& split) {
    const auto& pieces = split.pieces();
    // The partition as nested selects: below_cut(p, d, n, d) ? below : above.
    std::function<std::string(int)> locate = [&](int child) -> std::string {
        if (child < 0) return std::to_string(-1 - child);
        const ConvexPieces::Node& node = split.nodes()[static_cast<std::size_t>(child)];
        return "(below_cut(p, d, vec3(" + glsl_float(node.cut.n.x) + ", " +
               glsl_float(node.cut.n.y) + ", " + glsl_float(node.cut.n.z) + "), " +
               glsl_float(node.cut.d) + ") ? " + locate(node.below) + " : " + locate(node.above) +
               ")";
    };
    // Each plane once, with the pieces it bounds as bits: a facet may bound several, a cut
    // bounds one from each side, facing opposite ways.
    std::vector<int> masks(stone.facets.size(), 0);
    std::string exits = "PIECE_BOUNDS";
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        for (std::uint32_t f : pieces[k].facets) masks[f] |= 1 << k;
        for (const Plane& cut : pieces[k].cuts) {
            exits +=
                " PIECE_BOUND(-1, " + std::to_string(1 << k) + ", " + plane_arguments(cut) + ")";
        }
    }
    for (std::size_t f = 0; f < masks.size(); ++f) {
        if (masks[f] == 0) continue;
        exits += " PIECE_BOUND(" + std::to_string(f) + ", " + std::to_string(masks[f]) + ", " +
                 plane_arguments(stone.facets[f].plane) + ")";
    }
    std::string polygons = "POCKET_WALLS";
    for (const ConvexPieces::WallPolygon& wall : split.wall_polygons()) {
        const std::string facet = std::to_string(wall.facet);
        polygons +=
            " WALL_BEGIN(" + facet + ", " + plane_arguments(stone.facets[wall.facet].plane) + ")";
        for (const Plane& edge : wall.edges)
            polygons += " WALL_EDGE(" + plane_arguments(edge) + ")";
        polygons += " WALL_END(" + facet + ")";
    }
    std::string walls;
    for (std::uint32_t f : split.pocket_walls()) {
        walls += (walls.empty() ? "" : " || ") + ("facet == " + std::to_string(f));
    }
    return {"PIECES",
            "PIECE_POCKET_WALL " + (walls.empty() ? "false" : "(" + walls + ")"),
            "PIECE_COUNT " + std::to_string(pieces.size()),
            "PIECE_LOCATE " + locate(split.nodes().empty() ? -1 : 0),
            exits,
            polygons};
}

// A non-convex stone's programs: its convex pieces where it splits into few (and `search`
// does not ask for the triangles), else its triangles.
ProgramVariants non_convex_programs(const Stone& stone, ExitSearch search, ExitSearch& used) {
    if (search != ExitSearch::triangles) {
        if (auto split = ConvexPieces::split(stone)) {
            used = ExitSearch::pieces;
            return ProgramVariants("trace_non_convex", pieces_defines(stone, *split));
        }
    }
    used = ExitSearch::triangles;
    return ProgramVariants("trace_non_convex", {});
}

// The program variants of an exit search; none for folding a stone that does not fold.
std::optional<ProgramVariants> convex_programs(const Stone& stone, ExitSearch search) {
    switch (search) {
        case ExitSearch::constants:
            return ProgramVariants("trace", {"EXIT_UNROLLED", exit_planes_define(stone)});
        case ExitSearch::folded: {
            const auto fold = FoldedExit::make(stone);
            if (!fold) return std::nullopt;
            return ProgramVariants("trace", folded_defines(stone, *fold));
        }
        case ExitSearch::walk:
        case ExitSearch::measured:
        case ExitSearch::pieces:  // a non-convex stone's searches: a convex stone walks
        case ExitSearch::triangles:
            break;
    }
    return ProgramVariants("trace", {});
}

// The fire a draw compiles in. A still frame's wavelengths (a spectral picture's) replace a
// convex stone's fire, whichever it is, traced exactly at them; a non-convex stone traces fire
// only with them and when asked for spectral fire (trace.frag: its triangles make three
// channels three times the work). Spectral fire without them is exact.
std::uint32_t fire_features(TraceDispersion dispersion, bool convex, bool has_spectrum) {
    if (dispersion == TraceDispersion::none) return 0;
    if (has_spectrum && (convex || dispersion == TraceDispersion::spectral)) return kFireExact;
    if (!convex) return 0;
    return dispersion == TraceDispersion::first_order ? kFireFirstOrder : kFireExact;
}

}  // namespace

const char* to_string(TraceDispersion fire) {
    switch (fire) {
        case TraceDispersion::none:
            return "none";
        case TraceDispersion::first_order:
            return "first-order";
        case TraceDispersion::exact:
            return "exact";
        case TraceDispersion::spectral:
            return "spectral";
    }
    return "?";
}

const char* to_string(ExitSearch search) {
    switch (search) {
        case ExitSearch::walk:
            return "facet walk";
        case ExitSearch::constants:
            return "every plane as constants";
        case ExitSearch::folded:
            return "folded into one wedge";
        case ExitSearch::measured:
            return "measured";
        case ExitSearch::pieces:
            return "convex pieces";
        case ExitSearch::triangles:
            return "every triangle";
    }
    return "?";
}

TraceMethod::TraceMethod(StoneGeometry geometry, ProgramVariants programs, bool convex)
    : geometry_(std::move(geometry)),
      programs_(std::move(programs)),
      no_attributes_(make_vertex_array()),
      convex_(convex) {}

Result<const Program*> TraceMethod::program(std::uint32_t features) {
    return programs_.get(features, [&](const Program& built) { geometry_.attach(built); });
}

Result<TraceMethod> TraceMethod::make(const Stone& stone, ExitSearch search) {
    auto geometry = StoneGeometry::upload(stone);
    if (!geometry) return Error{"trace: " + geometry.error()};
    const double radius = bounding_radius(stone.vertices);
    if (!stone.convex) {
        ExitSearch used = ExitSearch::triangles;
        auto programs = non_convex_programs(stone, search, used);
        TraceMethod m(std::move(geometry).value(), std::move(programs), false);
        m.search_ = used;
        return m;
    }
    // A non-convex stone's searches (pieces, triangles) mean nothing to a convex one: its
    // fastest is measured.
    if (search != ExitSearch::measured && search != ExitSearch::pieces &&
        search != ExitSearch::triangles) {
        auto programs = convex_programs(stone, search);
        if (!programs) return Error{"trace: the stone's planes are not mirrored to fold them"};
        TraceMethod m(std::move(geometry).value(), std::move(programs).value(), true);
        m.search_ = search;
        return m;
    }

    // Every search on one small picture of the stone (a three-quarter view, the default trace
    // settings, an empty cube): the faster of three frames each, drawn to completion.
    constexpr int kSide = 64;
    auto target = RenderTarget::make(kSide, kSide);
    auto cube = EnvironmentCube::allocate(8);
    if (!target || !cube) return Error{!target ? target.error() : cube.error()};
    CameraSettings view;
    view.azimuth_deg = 10.0;
    view.elevation_deg = 40.0;
    auto camera = Camera::make(view, radius, kSide, kSide);
    if (!camera) return Error{"trace: " + camera.error()};
    const FramebufferScope restore;
    target.value().bind();
    StoneFrame frame{&stone, stone.material, camera.value(), {}, &cube.value(), 0.0, 2.0 * radius};
    TraceMethod m(std::move(geometry).value(), ProgramVariants("trace", {}), true);
    auto time_ms = [&]() -> Result<double> {
        double best = std::numeric_limits<double>::infinity();
        for (int i = 0; i < 3; ++i) {  // the first compiles the shader's last stages: not timed
            glClearDepthf(1.0f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            const auto start = std::chrono::steady_clock::now();
            auto ok = m.draw(frame, TraceSettings{});
            glFinish();
            if (!ok) return Error{ok.error()};
            const double ms = ms_since(start);
            if (i > 0) best = std::min(best, ms);
        }
        return best;
    };
    std::optional<ProgramVariants> fastest;
    double fastest_ms = std::numeric_limits<double>::infinity();
    Result<bool> measured = true;
    for (ExitSearch candidate : {ExitSearch::walk, ExitSearch::constants, ExitSearch::folded}) {
        auto programs = convex_programs(stone, candidate);
        if (!programs) continue;  // a stone that does not fold
        std::swap(m.programs_, programs.value());
        auto ms = time_ms();
        if (!ms) {
            measured = Error{ms.error()};
            break;
        }
        m.measured_ms_[static_cast<int>(candidate)] = ms.value();
        if (ms.value() < fastest_ms) {
            fastest_ms = ms.value();
            m.search_ = candidate;
            fastest = std::move(m.programs_);
        }
    }
    if (!measured) return Error{measured.error()};
    m.programs_ = std::move(fastest).value();
    return m;
}

std::string TraceMethod::measurement() const {
    std::string text;
    char one[80];
    for (ExitSearch s : {ExitSearch::walk, ExitSearch::constants, ExitSearch::folded}) {
        const double ms = measured_ms(s);
        if (ms <= 0.0) continue;
        std::snprintf(one, sizeof one, "%s%s %.2f ms", text.empty() ? "" : ", ", to_string(s), ms);
        text += one;
    }
    return text.empty() ? "not measured" : text;
}

Result<bool> TraceMethod::draw(const StoneFrame& frame, const TraceSettings& trace,
                               TraceDispersion dispersion) {
    assert(frame.environment != nullptr);
    const std::uint32_t features =
        shading_features(frame) |
        fire_features(dispersion, convex_, frame.still.wavelengths != nullptr) |
        (frame.visibility.texture != 0 ? kVisibility : 0u) |
        (frame.visibility.samples > 0 ? kVisibilitySamples : 0u);
    auto chosen = program(features);
    if (!chosen) return Error{chosen.error()};
    const Program& p = *chosen.value();
    // By visibility: one rectangle about the stone, shaded where the visibility pass's stencil
    // holds the stone (the pass decided by its depth test which stone each pixel shows, so a
    // block with none of its pixels is never shaded), blended over what is drawn.
    const bool by_visibility = frame.visibility.texture != 0;
    Pipeline rectangle_pipeline{&p, Blend::alpha, {false, GL_LESS, false}};
    rectangle_pipeline.stencil = {true, GL_EQUAL, static_cast<GLint>(frame.stone_id)};
    const PipelineScope pass(by_visibility ? rectangle_pipeline : StoneGeometry::front_faces(p));
    set_camera_uniforms(p, frame);
    const SamplerBinding sharp = set_shading_uniforms(p, frame, kEnvironmentUnit);
    geometry_.bind(p, kStoneUnit);
    geometry_.bind_exit_guess(p, kStoneUnit);
    set_piece_sight_uniforms(p, frame, kPieceSightUnit);
    p.set("u_facet_count", geometry_.facet_count());
    p.set("u_ior", static_cast<float>(frame.material.index()));
    // A still frame may trace deeper than a moving one, never shallower.
    p.set("u_max_depth", std::max(frame.still.depth, trace.max_depth));
    p.set("u_min_weight", static_cast<float>(trace.min_weight));
    p.set("u_thesis_weights", trace.weights == WeightModel::thesis_factors ? 1 : 0);
    p.set("u_r_factor", static_cast<float>(trace.r_factor));
    p.set("u_t_factor", static_cast<float>(trace.t_factor));
    // A still frame's own wavelengths where it has them, and how its three traces mix into the
    // channels; else the channels' dominant ones, each its own channel.
    const StillWavelengths* still = frame.still.wavelengths;
    p.set("u_ior_channel", still != nullptr ? glm::vec3(frame.material.index(still->nm.x),
                                                        frame.material.index(still->nm.y),
                                                        frame.material.index(still->nm.z))
                                            : channel_indices(frame.material));
    p.set("u_channel_mix", still != nullptr ? glm::mat3(still->mix) : glm::mat3(1.0f));

    if (by_visibility) {
        draw_rectangle(p, frame);
    } else {
        geometry_.draw_triangles();
    }
    return gl_check("trace pass");
}

std::optional<glm::vec4> TraceMethod::rectangle(const StoneFrame& frame) const {
    // The stone's corners through the matrix its depth pass drew them with, and a pixel more
    // each way; the whole picture where a corner lies behind a perspective eye.
    const glm::mat4 vp = stone_view_projection(frame);
    glm::vec2 lo(std::numeric_limits<float>::infinity());
    glm::vec2 hi(-std::numeric_limits<float>::infinity());
    for (const glm::dvec3& v : frame.stone->vertices) {
        const glm::vec4 clip = vp * glm::vec4(glm::vec3(v), 1.0f);
        if (clip.w <= 0.0f) {
            lo = glm::vec2(-1.0f);
            hi = glm::vec2(1.0f);
            break;
        }
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
    }
    const glm::vec2 pixel(2.0f / static_cast<float>(frame.camera.width()),
                          2.0f / static_cast<float>(frame.camera.height()));
    lo = glm::max(lo - pixel, glm::vec2(-1.0f));
    hi = glm::min(hi + pixel, glm::vec2(1.0f));
    if (lo.x >= hi.x || lo.y >= hi.y) return std::nullopt;
    return glm::vec4(lo, hi);
}

void TraceMethod::draw_rectangle(const Program& program, const StoneFrame& frame) const {
    const std::optional<glm::vec4> quad = rectangle(frame);
    if (!quad) return;
    const bool samples = frame.visibility.samples > 0;
    glActiveTexture(GL_TEXTURE0 + kVisibilityUnit);
    glBindTexture(samples ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D, frame.visibility.texture);
    glActiveTexture(GL_TEXTURE0);
    program.set("u_visibility", kVisibilityUnit);
    if (samples) {
        program.set("u_samples", frame.visibility.samples);
        program.set("u_stone", frame.stone_id);
    }
    program.set("u_quad", *quad);
    glBindVertexArray(no_attributes_.get());
    glDrawArrays(GL_TRIANGLES, 0, 6);
}

void TraceMethod::clear_visibility(const StoneFrame& frame) const {
    const std::optional<glm::vec4> quad = rectangle(frame);
    if (!quad) return;
    // The rectangle's pixels: those whose centres the quad covers lie within these.
    const glm::vec2 size(frame.camera.width(), frame.camera.height());
    const glm::ivec2 lo(glm::floor((glm::vec2(quad->x, quad->y) * 0.5f + 0.5f) * size));
    const glm::ivec2 hi(glm::ceil((glm::vec2(quad->z, quad->w) * 0.5f + 0.5f) * size));
    glScissor(lo.x, lo.y, hi.x - lo.x, hi.y - lo.y);
    const GLuint no_stone[4] = {0, 0, 0, 0};
    glClearBufferuiv(GL_COLOR, 1, no_stone);
}

void TraceMethod::draw_depth(const StoneFrame& frame, const Program& depth,
                             PipelineScope& pass) const {
    depth.set("u_view_projection", stone_view_projection(frame));
    if (frame.visibility.texture != 0) {
        // Into the visibility target alone (the scene's draw buffer is none): a colour mask
        // would mask it too.
        depth.set("u_stone", frame.stone_id);
        pass.change(StoneGeometry::visibility(depth, frame.stone_id));
    }
    geometry_.draw_triangles();
}

namespace {

// The trace as a stone method: one TraceMethod per kind of stone (its block and programs), each
// kind traced with its own model (depth, fire), the setup's to begin with.
class TraceStones final : public StoneMethod {
  public:
    TraceStones(const FrameSetup& setup, Program depth, Program visibility)
        : trace_(setup.trace),
          search_(setup.trace_search),
          depth_(std::move(depth)),
          visibility_(std::move(visibility)) {}

    bool shades_by_visibility() const override { return true; }

    Result<bool> add_kind(const Stone& stone, const StoneModel& model) {
        auto made = TraceMethod::make(stone, search_);
        if (!made) return Error{made.error()};
        methods_.push_back(std::make_unique<TraceMethod>(std::move(made).value()));
        convex_.push_back(stone.convex);
        models_.push_back(model);
        settings_.push_back(trace_);
        settings_.back().max_depth = model.depth;
        return true;
    }

    Result<bool> draw(const std::vector<StoneFrame>& frames, const std::vector<std::size_t>& kinds,
                      FrameStats& stats) override {
        (void)stats;
        for (std::size_t i = 0; i < frames.size(); ++i) {
            const std::size_t k = kinds[i];
            auto ok = methods_[k]->draw(frames[i], settings_[k], models_[k].fire);
            if (!ok) return ok;
        }
        return true;
    }

    Result<bool> draw_depth(const std::vector<StoneFrame>& frames,
                            const std::vector<std::size_t>& kinds) override {
        const Program& depth =
            !frames.empty() && frames.front().visibility.texture != 0 ? visibility_ : depth_;
        if (!frames.empty() && frames.front().visibility.samples > 0) {
            // Cleared about each stone, not whole: a multisampled integer clear of the whole
            // picture took llvmpipe 6-8 ms at 1080p (bench_pieces --samples 4), more than
            // the stones' passes saved.
            GLint scissor[4];
            glGetIntegerv(GL_SCISSOR_BOX, scissor);
            const GLboolean scissored = glIsEnabled(GL_SCISSOR_TEST);
            glEnable(GL_SCISSOR_TEST);
            for (std::size_t i = 0; i < frames.size(); ++i) {
                methods_[kinds[i]]->clear_visibility(frames[i]);
            }
            glScissor(scissor[0], scissor[1], scissor[2], scissor[3]);
            if (!scissored) glDisable(GL_SCISSOR_TEST);
        }
        PipelineScope pass(!frames.empty() && frames.front().visibility.texture != 0
                               ? StoneGeometry::visibility(depth, 0)
                               : StoneGeometry::depth_only(depth));
        for (std::size_t i = 0; i < frames.size(); ++i) {
            methods_[kinds[i]]->draw_depth(frames[i], depth, pass);
        }
        auto clean = gl_check("trace depth pass");
        if (!clean) return Error{clean.error()};
        return true;
    }

    std::optional<StoneModel> model(std::size_t kind) const override { return models_[kind]; }
    void set_model(std::size_t kind, const StoneModel& model) override {
        models_[kind] = model;
        settings_[kind].max_depth = model.depth;
    }
    Result<bool> draw_alone(std::size_t kind, const StoneFrame& frame,
                            const StoneModel& model) override {
        TraceSettings trace = trace_;
        trace.max_depth = model.depth;
        return methods_[kind]->draw(frame, trace, model.fire);
    }

    std::string describe() const override {
        const TraceMethod& first = *methods_.front();
        if (!convex_.front()) {
            return std::string("the first stone not convex: exits by ") +
                   to_string(first.exit_search());
        }
        return std::string("exits by ") + to_string(first.exit_search()) +
               " (64x64 test: " + first.measurement() + ")";
    }

  private:
    TraceSettings trace_;
    ExitSearch search_;   // a non-convex kind's
    Program depth_;       // stone_depth
    Program visibility_;  // stone_visibility
    std::vector<std::unique_ptr<TraceMethod>> methods_;
    std::vector<bool> convex_;
    std::vector<StoneModel> models_;
    std::vector<TraceSettings> settings_;  // the setup's, at each kind's model's depth
};

}  // namespace

Result<std::unique_ptr<StoneMethod>> make_trace_stones(const FrameSetup& setup,
                                                       const std::vector<const Stone*>& kinds) {
    auto depth = build_program("stone_depth");
    if (!depth) return Error{depth.error()};
    auto visibility = build_program("stone_visibility");
    if (!visibility) return Error{visibility.error()};
    auto method = std::make_unique<TraceStones>(setup, std::move(depth).value(),
                                                std::move(visibility).value());
    for (const Stone* kind : kinds) {
        auto added = method->add_kind(*kind, {setup.trace.max_depth, setup.trace_dispersion});
        if (!added) return Error{added.error()};
    }
    return std::unique_ptr<StoneMethod>(std::move(method));
}

namespace {

std::vector<ProgramSpec> trace_programs() {
    constexpr std::uint32_t kFeatures =
        kShadingFeatures | kFireFirstOrder | kFireExact | kVisibility | kVisibilitySamples;
    std::vector<std::string> sources = stone_method_sources("trace.frag");
    sources.insert(sources.end() - 1,
                   {"trace_common.glsl", "trace_folded.glsl", "trace_pieces.glsl"});
    return {
        // Exact tracing per fragment, exits by walking the facets (trace_method.hpp).
        {"trace", {"stone.vert"}, sources, {}, kFeatures},
        // A non-convex stone's fire is traced per channel in a still view only.
        {"trace_non_convex", {"stone.vert"}, sources, {"NON_CONVEX"}, kFeatures & ~kFireFirstOrder},
    };
}

// Exact fire first where the stone's fire is drawn (each channel at its own index); without
// it the two would draw the same.
std::vector<MethodRung> trace_rungs(const RungContext& context) {
    std::vector<MethodRung> rungs;
    if (context.dispersion) rungs.push_back({"trace", false, -1, "trace exact fire", true});
    rungs.push_back({"trace", false, -1, "trace"});
    return rungs;
}

}  // namespace

extern const MethodEntry kTraceMethod;
constinit const MethodEntry kTraceMethod{.name = "trace",
                                         .needs_database = false,
                                         .draws_pieces = true,
                                         .refracts = true,
                                         .opacity_from_alpha = false,
                                         .make = make_trace_stones,
                                         .programs = trace_programs,
                                         .rungs = trace_rungs};

}  // namespace gem::gpu
