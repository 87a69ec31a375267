#pragma once
// The gemmologist's viewing set-up for light-return measures: the stone face-up under a
// uniform diffuse hemisphere ("sky") above the girdle plane, the viewer straight above the
// table with the head shadowing a cone about the viewing axis, and nothing lit below the
// girdle plane (a stone in a ring or in a dark tray gets no light from underneath).
//
// The sky is split as the American Gem Society's ASET scope splits it (AGS Laboratories 2005;
// Sasian, Quick, Sheffield, Caudill & Yantzer, "Evaluation of brilliance, fire, and
// scintillation in round brilliant gemstones", Opt. Eng. 46(9) 093604, 2007): the scope is a
// hemisphere painted green from the horizon to 45° elevation, red from 45° to 75°, and blue
// from 75° to 90°, the blue cap standing for the light the viewer's own head blocks. Light
// the stone takes from below the girdle plane (it leaks through the pavilion) shows black on
// a dark stage. We take the head as that blue cap: a 15° half-angle cone about the axis, what
// a head about 15 cm wide subtends at a viewing distance of about 28 cm. Cut-analysis programs
// such as DiamCalc (OctoNus) and GemRay also darken an observer's head in their lighting;
// only the cone's size is a choice, and it is a setting here.

#include <cstdint>

#include <glm/glm.hpp>

namespace gem {

// Where a ray, traced backwards from the eye and leaving the stone along `d`, takes its light
// from, in ASET terms.
enum class SkyZone : std::uint8_t {  // the order is used: the first three lie above the girdle
    low_sky,   // ASET green: 0° to the red/green boundary (45°) above the girdle plane
    high_sky,  // ASET red: from that boundary up to the edge of the head shadow (75°)
    head,      // ASET blue: inside the head's cone about the viewing axis
    below,     // ASET black: below the girdle plane (leakage through the pavilion)
};
inline constexpr int kSkyZoneCount = 4;

struct SkyModel {
    double head_half_angle_deg = 15.0;  // the head's cone about +y (ASET blue: 75°–90°)
    double red_green_deg = 45.0;        // elevation splitting ASET red (above) from green
    double radiance = 1.0;              // the lit sky's uniform radiance (head and below: 0)

    // `d`: unit direction, stone frame (+y up through the table, toward the viewer).
    SkyZone zone(const glm::dvec3& d) const;
    // Radiance arriving along -d, i.e. what a ray leaving along d sees.
    double radiance_along(const glm::dvec3& d) const;
};

}  // namespace gem
