#pragma once
// One interface for a way of shading stones (docs/design.md, "Methods side by side"). A method
// is made from the scene once (the frame setup and the kinds of stone drawn) and draws a list of
// stone instances each frame, each in its own frame (StoneFrame: placement, camera, cube). What
// it needs before a frame (the table decodes the views a turn will reach) it does in prepare().
// The registry (stone_method.cpp) lists each method's entry, defined in the method's own file:
// its name and what it can draw, its maker, its GPU programs and its rungs of the kiosk's
// method probe. The kiosk's config, gemrender, the program catalogue and the probe find
// methods there and nowhere else, so a new method is its file, its shader and its line in the
// registry (docs/design.md, "Methods side by side").

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/stone.hpp"
#include "gpu/frame_setup.hpp"
#include "gpu/frame_uniforms.hpp"
#include "gpu/program.hpp"
#include "picture/camera.hpp"
#include "util/result.hpp"

namespace gem::gpu {

class StoneMethod {
  public:
    virtual ~StoneMethod() = default;

    // Before the frame at `camera`, the view turning at `omega` (rad/s, about the axis it
    // points along): the table asks its cache for the views ahead; `wait`: until they are
    // decoded (benchmarks, which time shading, not decoding). Others need nothing.
    virtual void prepare(const Camera& camera, const glm::dvec3& omega, bool wait = false) {
        (void)camera;
        (void)omega;
        (void)wait;
    }
    // Draws every stone: frames[i] is a stone of kind kinds[i] (an index into the kinds the
    // method was made with), its camera and cube filled in, into the bound framebuffer.
    virtual Result<bool> draw(const std::vector<StoneFrame>& frames,
                              const std::vector<std::size_t>& kinds, FrameStats& stats) = 0;
    // Before the metal and draw(): every stone's depth alone, so that the metal is shaded only
    // where no stone is in front of it and each stone only where nothing is (a piece's stones
    // behind its metal, a band's far side, cost their pixels otherwise; bench_pieces). False:
    // the method has no such pass (phong blends back faces that a depth pass would hide).
    virtual Result<bool> draw_depth(const std::vector<StoneFrame>& frames,
                                    const std::vector<std::size_t>& kinds) {
        (void)frames;
        (void)kinds;
        return false;
    }
    // Whether draw_depth() and draw() follow StoneFrame::visibility where it is set: the
    // depth pass writes each pixel's stone and entry facet, and draw() shades each stone as the
    // rectangle about it, its pixels in whole blocks (frame_renderer.hpp).
    virtual bool shades_by_visibility() const { return false; }

    // A method with models per kind of stone (the trace: depth and fire, stone_models.hpp);
    // the others have none: model() is empty and draw_alone() refuses.
    virtual std::optional<StoneModel> model(std::size_t kind) const {
        (void)kind;
        return std::nullopt;
    }
    virtual void set_model(std::size_t kind, const StoneModel& model) {
        (void)kind;
        (void)model;
    }
    // Draws `frame`'s stone (of kind `kind`) as `model` traces it.
    virtual Result<bool> draw_alone(std::size_t kind, const StoneFrame& frame,
                                    const StoneModel& model);

    // How the method settled itself, for the log (the trace: how it finds exits and what the
    // measurement gave); empty when there is nothing to say.
    virtual std::string describe() const { return {}; }
};

// One rung of the kiosk's method probe (render.method auto): a method at the settings it is
// tried with.
struct MethodRung {
    std::string method;       // the method's registry name
    bool blend = false;       // table: two stored views blended
    int max_level = -1;       // table: highest ray-table level shown; -1: the level the size needs
    std::string name;         // for the log line, e.g. "table blend"
    bool exact_fire = false;  // trace: each colour channel traced at its own index
};

// What a method's rungs depend on: the ray-table level the picture's size needs, and whether
// the stone's fire is drawn (its database stores dispersion, or a design's material disperses).
struct RungContext {
    int needed_level = 0;
    bool dispersion = false;
};

struct MethodEntry {
    std::string_view name;
    bool needs_database = false;  // draws from ray-tables: a design or a piece cannot use it
    bool draws_pieces = false;    // draws a piece's placed stones, not only a loose one
    // Follows the light through the stone; false: a baseline the probe chooses only when it
    // alone holds the frame rate (phong's flat stone).
    bool refracts = true;
    // Draws the stone with opacity 1 − α (phong): the physical shading's α = 1 would leave
    // only the metal on screen, so a scene draws it at the scene default.
    bool opacity_from_alpha = false;
    // `kinds`: the kinds of stone drawn (one for a loose stone), read while making (each
    // draw's StoneFrame names its stone again).
    Result<std::unique_ptr<StoneMethod>> (*make)(const FrameSetup& setup,
                                                 const std::vector<const Stone*>& kinds) = nullptr;
    // Its own GPU programs (program_catalog.hpp lists them with the shared ones).
    std::vector<ProgramSpec> (*programs)() = nullptr;
    // Its rungs of the probe's ladder, the most accurate first.
    std::vector<MethodRung> (*rungs)(const RungContext& context) = nullptr;
};

// Every method this build has, from the most accurate to the cheapest.
std::span<const MethodEntry* const> stone_methods();
const MethodEntry* find_stone_method(std::string_view name);
// "trace, table, phong": for messages about an unknown name.
std::string stone_method_names();
// The most accurate method that draws from ray-tables (a stone whose tables are at hand, before
// the probe has chosen); the fallback in a build without one.
const MethodEntry& tables_method();
// The most accurate refracting method that needs no tables and draws pieces: what draws a
// design or a piece where the configured method cannot.
const MethodEntry& fallback_stone_method();
// The probe's ladder: every method's rungs, in the registry's order.
std::vector<MethodRung> method_rungs(const RungContext& context);

}  // namespace gem::gpu
