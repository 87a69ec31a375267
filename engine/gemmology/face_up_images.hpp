#pragma once
// Pictures of a face-up analysis (face_up.hpp), one pixel per traced pixel, linear RGB with
// alpha = 1 on the stone and 0 off it, over black:
//  - light return: grey = the pixel's light return under the sky model (white: all of the
//    light reaching the eye comes from the lit sky);
//  - ASET: the weight of each ray from inside the stone (the exits; the first surface
//    reflection, which on the scope shows its viewing hole, is left out) painted with its
//    zone's colour as the AGS scope paints the hemisphere (red: 45°–75°, green: 0°–45°, blue:
//    the head, black: below the girdle plane), divided by the pixel's total weight, so that
//    the colour shows where the light comes from and dark shows leakage, as on the scope's
//    black stage.

#include "gemmology/face_up.hpp"
#include "picture/image.hpp"

namespace gem {

Image light_return_image(const FaceUpAnalysis& analysis);
Image aset_image(const FaceUpAnalysis& analysis);

}  // namespace gem
