#pragma once
// render.method = "auto" for a kiosk session: when the methods are measured (once per session,
// after the first frame is on screen, at the display's size), the probe's frames between the
// frames shown (method_probe_run.hpp), the picture's extras (MSAA, glare) shed when no method
// holds the frame rate with them, and the choice in the journal. The session asks and applies;
// this decides.

#include <optional>

#include <glm/vec2.hpp>

#include "gpu/hdr_picture.hpp"
#include "probe/method_probe_run.hpp"
#include "stage/stone_scene.hpp"

namespace gem::kiosk {

// What the screen shows, for the probe to measure.
struct ProbeSubject {
    CatalogueStone stone;
    LookChoice look;
    RenderChoice render;          // the session's render choice, the method aside
    gpu::PictureOptions picture;  // the picture on screen's
    glm::ivec2 size{0};           // its pixels
    double budget_ms = 0.0;       // a frame's (frame_budget_ms); infinite: no rate to hold
};

// What the picture on screen has of the extras a second probe may shed (a GPU may offer fewer
// samples than asked, or no float target for the glare).
struct PictureExtras {
    int samples = 1;
    bool glare = false;
};

class AutoMethod {
  public:
    // As a scene is made: measures once per session and display size. Without a rate to hold,
    // `render` gets the most accurate method at once; before the first frame is shown, the
    // probe waits for it (call again after it); else the probe starts.
    void choose(const ProbeSubject& subject, bool first_frame_shown, RenderChoice& render);
    // The probe waits for the first frame to be shown.
    bool waiting_for_first_frame() const { return waiting_; }
    bool probing() const { return probe_ != nullptr; }

    struct Choice {
        std::optional<RenderChoice> render;          // the method chosen (none: none drew)
        std::optional<gpu::PictureOptions> picture;  // the picture remade without its extras
    };
    // One more probe frame, after a frame shown; once the methods are measured, the choice.
    std::optional<Choice> step(const PictureExtras& extras);
    void stop() { probe_.reset(); }

  private:
    std::optional<ProbeSubject> subject_;
    std::optional<glm::ivec2> probed_size_;  // the picture size the choice was made for
    bool waiting_ = false;
    std::unique_ptr<MethodProbe> probe_;
    std::optional<ProbeResult> with_extras_;  // the first probe's, when the extras are shed
};

}  // namespace gem::kiosk
