#pragma once
// The still picture (docs/accuracy.md, "The still picture"): what the kiosk shows once a view
// has settled, its still frames averaged over the pixel (gpu/hdr_picture.hpp), against a
// reference averaged over the pixel as well: the full reference at 16 samples a pixel. The
// sweep's other rows compare one centre sample with one; a still picture is a mean over the
// pixel and is only fairly judged against one.
//
// Rows (study "still", compared with "ref-16spp", on a scene's ON view; a scene with a ring is
// left out, its metal is no part of the still frames' question): the moving picture (1 frame,
// depth 8, exact fire), the still picture of 16 frames with exact fire at depth 8, and with
// spectral fire (every frame its own wavelengths) at still depths 8, 16 and 32, the depth rule
// the kiosk follows while a view is still (picture.still_depth). `samples` holds the frames
// averaged, `depth` the still frames' depth, `dispersion` whether the fire is spectral, and
// `frame_ms` the summed time of all the frames: what the shopper waits for the settled picture.

#include <vector>

#include "results.hpp"
#include "scene/environment.hpp"
#include "scenes.hpp"
#include "util/result.hpp"

namespace gem::accuracy {

// Needs a current GL context. Prints each row as it is measured. `quick`: still depths 8 and 16.
Result<bool> still_rows(const Scene& scene, const Environment& environment, const glm::dvec3& view,
                        const std::vector<float>& mask, int image, bool quick,
                        std::vector<Row>& rows);

}  // namespace gem::accuracy
