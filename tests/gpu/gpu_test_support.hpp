#pragma once
// What the headless GPU tests share: one EGL context for the whole test program (made on
// first use; every test fails with EGL's message if there is none), image comparison in
// 8-bit sRGB (PSNR, as people see the images), and failure artefacts in GEM_ARTIFACT_DIR.

#include <filesystem>
#include <string>

#include "gpu/egl_context.hpp"
#include "gpu/frame_renderer.hpp"
#include "optics/spectrum.hpp"
#include "picture/camera.hpp"
#include "picture/image.hpp"
#include "util/result.hpp"

namespace gem::gpu_test {

// The context, current on the calling thread; an error when EGL cannot make one.
Result<gpu::EglContext*> context();

// Peak signal-to-noise ratio of the 8-bit sRGB RGB channels over the pixels where `mask`
// (when given) has alpha > 0.5 in either image; infinity for identical images.
double psnr_srgb8(const Image& a, const Image& b, bool only_stone = false);

// Writes `image` to GEM_ARTIFACT_DIR/name.png and returns the path (for failure messages).
std::filesystem::path write_artifact(const Image& image, const std::string& name);
// An image of |a − b| × gain per channel, to look at when a comparison fails.
Image difference_image(const Image& a, const Image& b, float gain = 4.0f);

// The mean of the first `frames` frames of a still view at `camera` (their metal and stones
// following their rays through a piece), unjittered, each kept in half floats as the still
// picture keeps them: a frame's radiance may pass 1 or go below 0 where a correction is
// weighed for the frames its tile skips. Drawn into a framebuffer of its own. `spectrum`:
// each frame traced at its own wavelengths (a spectral still view); `moving`: the frames drawn
// as a moving view's, following nothing through the piece (with `spectrum`, the same
// wavelengths without the piece's rays).
Result<Image> mean_of_still_frames(gpu::FrameRenderer& renderer, const Camera& camera, int frames,
                                   const StillSpectrum* spectrum = nullptr, bool moving = false);

// The trace of `piece` (or the `loose` stone, its material its own) in `environment`, which
// must outlive the renderer made from it; the rest of the setup is the caller's.
gpu::FrameSetup trace_setup(const Piece* piece, const Stone* loose, const Environment& environment);

}  // namespace gem::gpu_test
