#include "optics/fresnel.hpp"

#include <algorithm>
#include <cmath>

namespace gem {

std::optional<glm::dvec3> refract(const glm::dvec3& d, const glm::dvec3& n, double n1, double n2) {
    const double eta = n1 / n2;
    const double cos_i = -glm::dot(d, n);
    const double sin2_t = eta * eta * std::max(0.0, 1.0 - cos_i * cos_i);
    if (sin2_t >= 1.0) return std::nullopt;
    const double cos_t = std::sqrt(1.0 - sin2_t);
    return glm::normalize(eta * d + (eta * cos_i - cos_t) * n);
}

FresnelTerms fresnel(double cos_i, double n1, double n2) {
    cos_i = std::clamp(cos_i, 0.0, 1.0);
    const double sin_i2 = 1.0 - cos_i * cos_i;
    const double sin_t2 = (n1 / n2) * (n1 / n2) * sin_i2;
    if (sin_t2 >= 1.0) return {1.0, 1.0};
    const double cos_t = std::sqrt(1.0 - sin_t2);
    const double s = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    const double p = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
    return {s * s, p * p};
}

double critical_angle(double n_inside, double n_outside) {
    return std::asin(std::min(1.0, n_outside / n_inside));
}

}  // namespace gem
