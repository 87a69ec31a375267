#pragma once
// The exact tracer: follows a pixel ray through a stone as a ray tree (reflection,
// refraction by Snell's law, total internal reflection) and returns the thesis ray-list.
// It is the one source of truth for the reference render, the tables and every accuracy check.

#include <memory>

#include "geometry/stone.hpp"
#include "trace/ray_list.hpp"

namespace gem {

enum class WeightModel {
    fresnel,         // exact unpolarised dielectric Fresnel products (physical)
    thesis_factors,  // the thesis' constant R-factor / T-factor per interaction
};

struct TraceSettings {
    int max_depth = 12;        // internal ray segments followed per branch
    double min_weight = 1e-4;  // a branch below this weight is cut (its energy is counted)
    WeightModel weights = WeightModel::fresnel;
    double r_factor = 0.3;  // thesis model: weight kept by an internal reflection
    double t_factor = 0.7;  // thesis model: weight kept by a refraction out of the stone
};

class Intersector;  // convex half-space clipping or triangle BVH, chosen from the stone

class Tracer {
  public:
    explicit Tracer(const Stone& stone);  // keeps a reference: the stone must outlive it
    explicit Tracer(Stone&&) = delete;
    ~Tracer();
    Tracer(Tracer&&) noexcept;
    Tracer& operator=(Tracer&&) noexcept;

    // Traces one ray arriving from outside the stone with refractive index `ior` (the
    // surrounding medium is air, n = 1). `out` is cleared first; its storage is reused.
    void trace(const Ray& ray, double ior, const TraceSettings& settings, RayList& out) const;

    const Stone& stone() const { return *stone_; }

  private:
    const Stone* stone_;
    std::unique_ptr<Intersector> intersector_;
};

}  // namespace gem
