#include "optics/microfacet.hpp"

#include <algorithm>
#include <cmath>

#include "util/radical_inverse.hpp"

namespace gem {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The i-th of n points of the Hammersley set: ((i + 0.5)/n, radical inverse of i in base 2).
void hammersley(int i, int n, double& u1, double& u2) {
    u1 = (static_cast<double>(i) + 0.5) / n;
    u2 = radical_inverse(static_cast<unsigned>(i), 2);
}

}  // namespace

double ggx_distribution(double n_dot_m, double alpha) {
    if (n_dot_m <= 0.0) return 0.0;
    const double a2 = alpha * alpha;
    const double d = n_dot_m * n_dot_m * (a2 - 1.0) + 1.0;
    return a2 / (kPi * d * d);
}

double smith_g1(double n_dot_x, double alpha) {
    if (n_dot_x <= 0.0) return 0.0;
    const double a2 = alpha * alpha;
    return 2.0 * n_dot_x / (n_dot_x + std::sqrt(a2 + (1.0 - a2) * n_dot_x * n_dot_x));
}

glm::dvec3 schlick_fresnel(const glm::dvec3& f0, double cos_theta) {
    const double c = std::clamp(cos_theta, 0.0, 1.0);
    return f0 + (1.0 - f0) * std::pow(1.0 - c, 5.0);
}

glm::dvec3 sample_ggx_normal(const glm::dvec3& n, double alpha, double u1, double u2) {
    const double tan2 = alpha * alpha * u1 / std::max(1.0 - u1, 1e-12);
    const double cos_t = 1.0 / std::sqrt(1.0 + tan2);
    const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
    const glm::dvec3 tx =
        glm::normalize(std::abs(n.x) < 0.9 ? glm::cross(n, {1, 0, 0}) : glm::cross(n, {0, 1, 0}));
    const glm::dvec3 ty = glm::cross(n, tx);
    const double phi = 2.0 * kPi * u2;
    return sin_t * std::cos(phi) * tx + sin_t * std::sin(phi) * ty + cos_t * n;
}

GgxReflection ggx_reflect(const glm::dvec3& f0, const glm::dvec3& n, const glm::dvec3& v,
                          const glm::dvec3& m, double alpha) {
    GgxReflection r;
    const double v_dot_m = glm::dot(v, m);
    if (v_dot_m <= 0.0) return r;
    r.direction = 2.0 * v_dot_m * m - v;
    const double n_dot_l = glm::dot(n, r.direction), n_dot_v = glm::dot(n, v);
    const double n_dot_m = glm::dot(n, m);
    if (n_dot_l <= 0.0 || n_dot_v <= 0.0 || n_dot_m <= 0.0) return r;
    const double g = smith_g1(n_dot_v, alpha) * smith_g1(n_dot_l, alpha);
    r.weight = schlick_fresnel(f0, v_dot_m) * (g * v_dot_m / (n_dot_v * n_dot_m));
    return r;
}

EnvironmentBrdf environment_brdf(double n_dot_v, double roughness, int samples) {
    // Normals drawn from those v sees (Heitz, "Sampling the GGX Distribution of Visible
    // Normals", JCGT 7(4), 2018, listing 1), so that no sample is wasted below the surface and
    // each weighs F(v·m) G1(n·l) alone. The normal is z and v lies in the xz plane. Schlick is
    // linear in F0, so one pass gives both terms: F = F0 (1 − Fc) + Fc, Fc = (1 − v·m)^5.
    const double alpha = ggx_alpha(roughness);
    const double c = std::clamp(n_dot_v, 1e-4, 1.0);
    const glm::dvec3 v(std::sqrt(1.0 - c * c), 0.0, c);
    const glm::dvec3 vh = glm::normalize(glm::dvec3(alpha * v.x, alpha * v.y, v.z));
    const double lensq = vh.x * vh.x + vh.y * vh.y;
    const glm::dvec3 t1 =
        lensq > 0.0 ? glm::dvec3(-vh.y, vh.x, 0.0) / std::sqrt(lensq) : glm::dvec3(1, 0, 0);
    const glm::dvec3 t2 = glm::cross(vh, t1);
    const double blend = 0.5 * (1.0 + vh.z);
    EnvironmentBrdf sum;
    for (int i = 0; i < samples; ++i) {
        double u1 = 0.0, u2 = 0.0;
        hammersley(i, samples, u1, u2);
        const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
        const double p1 = r * std::cos(phi);
        const double p2 = (1.0 - blend) * std::sqrt(1.0 - p1 * p1) + blend * r * std::sin(phi);
        const glm::dvec3 nh =
            p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
        const glm::dvec3 m =
            glm::normalize(glm::dvec3(alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z)));
        const double v_dot_m = glm::dot(v, m);
        const double n_dot_l = 2.0 * v_dot_m * m.z - c;
        if (v_dot_m <= 0.0 || n_dot_l <= 0.0) continue;
        const double weight = smith_g1(n_dot_l, alpha);
        const double fc = std::pow(1.0 - v_dot_m, 5.0);
        sum.scale += (1.0 - fc) * weight;
        sum.bias += fc * weight;
    }
    sum.scale /= samples;
    sum.bias /= samples;
    return sum;
}

std::vector<float> environment_brdf_table(int size, int samples) {
    std::vector<float> table;
    table.reserve(static_cast<std::size_t>(2 * size * size));
    for (int j = 0; j < size; ++j) {
        for (int i = 0; i < size; ++i) {
            const EnvironmentBrdf e = environment_brdf((i + 0.5) / size, (j + 0.5) / size, samples);
            table.push_back(static_cast<float>(e.scale));
            table.push_back(static_cast<float>(e.bias));
        }
    }
    return table;
}

}  // namespace gem
