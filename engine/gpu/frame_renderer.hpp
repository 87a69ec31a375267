#pragma once
// One frame of the shading stage, whatever the method: background, stone layer (a stone method
// from the registry, stone_method.hpp: a loose stone, or every stone of a piece), ring or the
// piece's metal, composited with alpha and depth into the bound framebuffer (docs/design.md,
// "Data flow").
// gemrender and the kiosk both draw through it. With metal, virtual cubes show it around the
// stones: a loose stone's seen from its centre, a piece's one per group of stones seen from
// inside one of them (piece/sight_groups.hpp), their six faces rendered when the scene changes
// (make() and set_lights()), not every frame.

#include <memory>
#include <optional>

#include "gpu/background_pass.hpp"
#include "gpu/environment_cube.hpp"
#include "gpu/frame_setup.hpp"
#include "gpu/frame_uniforms.hpp"
#include "gpu/scene_cover.hpp"
#include "gpu/stone_method.hpp"
#include "gpu/visibility_target.hpp"
#include "piece/metal_mesh.hpp"
#include "piece/piece.hpp"
#include "scene/environment.hpp"
#include "trace/tracer.hpp"
#include "util/result.hpp"

namespace gem::gpu {

class RingRenderer;

class FrameRenderer {
  public:
    static Result<FrameRenderer> make(FrameSetup setup);
    FrameRenderer(FrameRenderer&&) noexcept;
    FrameRenderer& operator=(FrameRenderer&&) noexcept;
    ~FrameRenderer();

    // Draws into the bound framebuffer (viewport set), waiting for the GPU as `wait` says.
    // `still`: what this frame of a still view traces differently (HdrPicture::still_frame());
    // the default while the view moves.
    Result<FrameStats> render(const Camera& camera, FrameWait wait, const StillFrame& still = {});
    // New lights re-render the ring's cube faces (its metal reflects them).
    Result<bool> set_lights(const std::vector<Light>& lights);

    // FrameSetup::visibility_pass, changed between frames (to measure the stones both ways).
    void set_visibility_pass(VisibilityPass pass) { setup_.visibility_pass = pass; }
    // Before a frame: what the stone method needs for `camera`, the view turning at `omega`
    // (StoneMethod::prepare: the table's views decoded ahead of the turn).
    void prepare(const Camera& camera, const glm::dvec3& omega, bool wait = false) {
        method_->prepare(camera, omega, wait);
    }
    // The stone method (stone_method.hpp) and its name in the registry.
    StoneMethod& method() { return *method_; }
    const StoneMethod& method() const { return *method_; }
    const std::string& method_name() const { return setup_.method; }
    // The stone (a piece's centre stone).
    const Stone& stone() const;

    // The kinds of stone drawn (a piece's distinct stones; one for a loose stone); a method
    // with models (the trace) traces each kind with its own.
    std::size_t kind_count() const { return kind_count_; }
    const Stone& kind(std::size_t k) const;
    // The stones drawn (a loose stone: one), each of a kind, placed in the piece.
    std::size_t stone_count() const { return kinds_.size(); }
    std::size_t kind_of(std::size_t stone) const { return kinds_[stone]; }
    const Placement& placement_of(std::size_t stone) const { return frames_[stone].placement; }
    // The first stone of kind `k` (its placement, material).
    std::size_t first_of_kind(std::size_t k) const;
    std::optional<StoneModel> model(std::size_t k) const { return method_->model(k); }
    void set_model(std::size_t k, const StoneModel& model) { method_->set_model(k, model); }
    // Draws the first stone of kind `k` alone, loose at the centre with its material, as
    // `model` traces it, into the bound framebuffer (viewport set; depth cleared first), seeing
    // what the piece's stones see: for measuring a model (stone_models.hpp). A method with
    // models only.
    Result<bool> draw_kind_alone(std::size_t k, const Camera& camera, const StoneModel& model);
    // What render() draws through `camera` besides its background, when that background is
    // one colour (FrameSetup::background_colour, or what an orthographic camera sees of the
    // environment): the tiles that the boxes about each stone and the metal's cells touch
    // (scene_cover.hpp). Null where the background shows the environment's changing view, or
    // the camera is a perspective one (the boxes are projected orthographically). Held
    // by the renderer until the next call (a frame allocates nothing for it).
    const SceneCover* cover(const Camera& camera);
    // Why a still view's metal and stones do not see their own piece (piece_path.glsl), where
    // they cannot; empty where they do, or there is no metal.
    const std::string& sight_note() const { return sight_note_; }
    // Radius about the centre (the stone's, the piece's) that holds everything drawn.
    double scene_radius_mm() const { return scene_radius_mm_; }
    double stone_radius_mm() const { return stone_radius_mm_; }

  private:
    FrameRenderer() = default;
    Result<bool> update_ring_cube();
    // The cube stone `i` sees, and where it was seen from; the environment alone without metal.
    void set_sight(StoneFrame& frame, std::size_t i) const;
    // The background's one colour through `camera`, where it is one.
    std::optional<glm::vec3> flat_background(const Camera& camera) const;
    // The visibility target attached to the bound framebuffer as its second colour, where
    // this frame can use it (the method shades by it, a framebuffer object, at most 255 stones
    // for an 8-bit stencil, samples the GL can hold in an integer texture, a metal that marks
    // them, FrameSetup::visibility_pass); else none.
    VisibilityAttachment attach_visibility(const Camera& camera, const StillFrame& still);

    FrameSetup setup_;
    std::unique_ptr<BackgroundPass> background_;
    std::unique_ptr<EnvironmentCube> environment_cube_;  // the environment alone
    // Environment + ring as a group of stones sees it (piece/sight_groups.hpp): one cube per
    // group, seen from its centre; a loose stone's one cube is seen from its own centre.
    struct SightCube {
        std::unique_ptr<EnvironmentCube> cube;
        glm::dvec3 centre{0.0};
    };
    std::vector<SightCube> sight_cubes_;
    std::vector<std::size_t> sight_of_;  // each stone's cube (index into sight_cubes_)
    // The stones drawn, each a frame made once (its material, placement and shading; the camera
    // and cube are filled in per frame, so a frame copies nothing that allocates), and its kind
    // (an index into the piece's kinds; 0 for a loose stone).
    std::vector<StoneFrame> frames_;
    std::vector<std::size_t> kinds_;
    std::size_t kind_count_ = 0;
    const MethodEntry* method_entry_ = nullptr;
    std::string check_label_;  // "frame (trace)": made once, so a frame allocates nothing
    std::string sight_note_;
    std::unique_ptr<StoneMethod> method_;
    std::unique_ptr<RingRenderer> ring_;
    std::unique_ptr<VisibilityTarget> visibility_;  // StoneFrame::visibility
    double scene_radius_mm_ = 0.0;
    double stone_radius_mm_ = 0.0;
    double ring_radius_mm_ = 0.0;        // the metal's, about the centre
    std::vector<CoverBox> cover_boxes_;  // about each stone and the metal's cells (cover())
    SceneCover cover_;                   // cover()'s last
};

}  // namespace gem::gpu
