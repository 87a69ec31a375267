#pragma once
// Fire as the angular spread of colours: a ray path traced at a red and at a blue wavelength
// leaves the stone in two slightly different directions; the angle between them is how far
// the stone fans white light out into a spectrum along that path.
//
// Why this measure: fire is seen when a small bright source (a spotlight, a candle) sends
// light that the stone splits so widely that different colours reach the eye from different
// facets, or one facet flashes a single colour. Tolkowsky ("Diamond Design", 1919) chose the
// crown's slope for this: the more obliquely light leaves a crown facet, the wider the colours
// fan out. GIA's DCLR metric (Reinitz et al., "Modeling the appearance of the round brilliant
// cut diamond: an analysis of fire, and more about brilliance", Gems & Gemology 37(3), 2001)
// counts the coloured light reaching the eye from point sources, which needs an observer and
// a lamp layout; the angular spread is the geometric quantity underneath it, independent of
// those choices, and what the tracer gives exactly. The Fraunhofer C (656.3 nm) and F
// (486.1 nm) lines bracket the bright part of the spectrum and are the lines of the usual
// optical dispersion (Abbe number); gemmologists quote B–G (686.7–430.8 nm), which spans the
// dimmer ends of the spectrum.

#include <vector>

#include "trace/ray_list.hpp"

namespace gem {

inline constexpr double kFraunhoferC = 656.3;  // nm, hydrogen α
inline constexpr double kFraunhoferF = 486.1;  // nm, hydrogen β

// For every exit of `reference` (traced at n(D)), the angle in degrees between the exits of
// the same path traced at the red and the blue index, or a negative value where the path does
// not exist at both (total internal reflection turned on or off between the two indices).
// Exits are matched as the table derivative pass matches them: the next exit, in the tracer's
// depth-first order, that left by the same facet after as many internal reflections.
void colour_spread_deg(const RayList& reference, const RayList& red, const RayList& blue,
                       std::vector<double>& out);

}  // namespace gem
