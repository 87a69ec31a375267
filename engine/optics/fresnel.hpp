#pragma once
// Reflection, Snell refraction, total internal reflection and exact dielectric Fresnel
// reflectance for unpolarised light (Born & Wolf, Principles of Optics, §1.5.2).

#include <optional>

#include <glm/glm.hpp>

namespace gem {

// Mirror reflection of direction d about the unit normal n (either side).
inline glm::dvec3 reflect(const glm::dvec3& d, const glm::dvec3& n) {
    return d - 2.0 * glm::dot(d, n) * n;
}

// Refraction of unit direction d through a surface with unit normal n that faces against d
// (dot(d, n) < 0), going from index n1 into index n2. Empty on total internal reflection.
std::optional<glm::dvec3> refract(const glm::dvec3& d, const glm::dvec3& n, double n1, double n2);

struct FresnelTerms {
    double rs = 0.0;                                        // s-polarised reflectance
    double rp = 0.0;                                        // p-polarised reflectance
    double reflectance() const { return 0.5 * (rs + rp); }  // unpolarised
    double transmittance() const { return 1.0 - reflectance(); }
};

// Reflectances at incidence cosine cos_i (0..1) going from n1 into n2; 1 beyond the critical
// angle (total internal reflection).
FresnelTerms fresnel(double cos_i, double n1, double n2);

// Unpolarised reflectance; the transmitted share is 1 − R since dielectrics do not absorb at
// the interface.
inline double fresnel_reflectance(double cos_i, double n1, double n2) {
    return fresnel(cos_i, n1, n2).reflectance();
}

// Critical angle (radians) for light inside index n_inside meeting index n_outside < n_inside.
double critical_angle(double n_inside, double n_outside = 1.0);

// Beer–Lambert: the share of light left after `path_mm` through a medium with coefficient
// `absorption_per_mm`, per channel.
inline glm::dvec3 beer_lambert(const glm::dvec3& absorption_per_mm, double path_mm) {
    return glm::exp(-absorption_per_mm * path_mm);
}

}  // namespace gem
