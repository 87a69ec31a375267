#pragma once
// The exact radiance along a ray through a whole piece: rays are followed into every stone
// with the exact tracer (each stone in its own frame, so the stone's tracer is the same one
// a loose stone uses), out of it, off the metal and into the other stones, up to a number of
// passes between parts; what escapes sees the environment and the lights. The metal is a
// conductor with the F0 the GPU shades it with (Schlick's Fresnel), rough metal sampled with
// the GGX distribution of its roughness (Walter et al. 2007, "Microfacet models for
// refraction through rough surfaces", eq. 33, 35-36, with Smith's masking). It is the truth a
// piece's GPU picture is measured against, and what gemrender --piece --method reference draws.
// Physical shading only (the thesis' model has no meaning for light passing between parts).

#include <cstdint>
#include <memory>
#include <vector>

#include "piece/piece.hpp"
#include "scene/environment.hpp"
#include "scene/shading.hpp"
#include "trace/intersector.hpp"
#include "trace/tracer.hpp"

namespace gem {

// What a ray leaving one part of a piece may meet: every other part (the truth); the metal
// alone, as a virtual cube holding only the metal gives the GPU's stones; or everything, but
// the metal's reflections see only the environment and the lights, as the GPU's metal does.
// The second and third measure what the GPU's stones and metal could gain at most
// (gpu_piece_test.cpp, docs/pieces.md).
enum class PieceSight { everything, metal_only, metal_sees_environment };

// The metal's triangles as a solid for the intersectors (trace/intersector.hpp), each facing
// where its vertex normals do; triangles without area are left out.
Stone metal_as_solid(const MetalMesh& metal);

class PieceTracer {
  public:
    // Passes between parts: a ray out of one stone may reach the metal, another stone, and so
    // on this many times; beyond, the environment stands in.
    static constexpr int kPasses = 4;
    // A branch whose share of the pixel falls below this is closed with the environment.
    static constexpr double kMinShare = 1e-3;

    // Keeps references: the piece, environment and settings must outlive the tracer.
    PieceTracer(const Piece& piece, const Environment& environment, const ShadingSettings& shading,
                const TraceSettings& trace, PieceSight sight = PieceSight::everything);
    ~PieceTracer();

    // One state per thread and sample: the ray-lists of every pass and the random stream that
    // samples rough metal.
    struct Scratch {
        std::vector<RayList> lists = std::vector<RayList>(kPasses + 1);
        std::uint64_t random = 0;
    };

    // Radiance along `ray` (piece frame); `iors` holds each kind's refractive index at the
    // wavelength being traced. `hit` says whether the ray met the piece at all.
    glm::dvec3 radiance(const Ray& ray, const std::vector<double>& iors, Scratch& scratch,
                        bool* hit = nullptr) const;

  private:
    struct Nearest;
    // The part `ray` meets first; no stone at all when `stones` is false.
    Nearest nearest(const Ray& ray, int skip_stone, bool stones = true) const;
    // What `ray` brings back from the part it meets first (`n`), and from a ray leaving a part
    // with `weight` of the pixel's share (escaping, or on to the next part).
    glm::dvec3 follow(const Ray& ray, const Nearest& n, const std::vector<double>& iors, int pass,
                      double share, Scratch& scratch) const;
    glm::dvec3 onward(const Ray& ray, int from_stone, const glm::dvec3& from_normal, double k,
                      const glm::dvec3& weight, const std::vector<double>& iors, int pass,
                      double share, Scratch& scratch) const;
    glm::dvec3 escaped(const Ray& ray, int from_stone, const glm::dvec3& from_normal, double k,
                       bool piece_blocks = true) const;
    glm::dvec3 metal(const Ray& ray, const SurfaceHit& hit, const std::vector<double>& iors,
                     int pass, double share, Scratch& scratch) const;

    const Piece& piece_;
    const Environment& environment_;
    const ShadingSettings& shading_;
    const TraceSettings& trace_;
    PieceSight sight_;
    std::vector<Tracer> tracers_;                        // one per kind
    std::vector<std::unique_ptr<Intersector>> entries_;  // one per kind
    std::vector<double> radii_;                          // one per kind
    Stone metal_solid_;                                  // the metal's triangles
    std::unique_ptr<Intersector> metal_;
};

}  // namespace gem
