#include "stage/picture_choice.hpp"

#include <string>

#include "gpu/stone_method.hpp"

namespace gem::kiosk {

DisplayTransform display_transform(const PictureConfig& picture, const LookChoice& look) {
    DisplayTransform t;
    t.curve = picture.tone == PictureTone::clip ? ToneCurve::clip : ToneCurve::neutral;
    t.exposure_ev = picture.exposure_ev + look.exposure_ev;
    return t;
}

gpu::PictureOptions picture_options(const PictureConfig& picture) {
    gpu::PictureOptions o;
    o.samples = picture.msaa;
    o.glare = picture.glare;
    o.still_frames = picture.still_frames;
    o.spectral = picture.spectral_stills && picture.still_frames > 1;
    o.still_depth = picture.still_depth;
    o.still_depth_max = picture.still_depth_max;
    o.still_seconds = picture.still_seconds;
    o.still_frame_ms = picture.still_frame_ms;
    o.display = display_transform(picture, LookChoice{});
    return o;
}

RenderChoice render_choice(const KioskConfig& config) {
    RenderChoice render;
    // Until the probe has chosen, from the tables (the scene falls back where it has none).
    render.method = config.render.method == kAutoMethod ? std::string(gpu::tables_method().name)
                                                        : config.render.method;
    render.blend = config.render.blend;
    render.cube_face = config.render.cube_face;
    render.depth = config.render.depth;
    render.cache_bytes = static_cast<std::size_t>(config.render.view_cache_mb) << 20;
    render.stone_share = config.picture.stone_share;
    return render;
}

}  // namespace gem::kiosk
