#pragma once
// What the stone sees in every direction (stone frame, radiance in linear RGB): a procedural
// studio, a uniform colour, or an equirectangular image. Lookups allocate nothing.

#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "util/result.hpp"

namespace gem {

class Environment {
  public:
    enum class Kind { studio, uniform, image };

    // A jeweller's studio: dark floor and walls, bright soft-edged rectangular softboxes
    // overhead and to the sides. Deterministic.
    static Environment studio();
    static Environment uniform(const glm::dvec3& colour);
    // A white light tent with dark flags round it (environment_tent.cpp), as an image.
    static Environment light_tent();
    // PNG (8-bit sRGB, decoded to linear) or Radiance .hdr (linear); +y is the image's top
    // row, the image's centre column looks toward -z. Errors name the file.
    static Result<Environment> load_image(const std::filesystem::path& path);
    // An equirectangular image already in memory (linear RGB rows, top row first).
    static Environment from_pixels(int width, int height, std::vector<glm::vec3> pixels);

    // Radiance arriving from unit direction `d` (i.e. seen looking along d).
    glm::dvec3 radiance(const glm::dvec3& d) const;
    // The radiance averaged over every direction (4096 directions spread evenly over the
    // sphere: a Fibonacci lattice). Computed, not kept: call it once per use.
    glm::dvec3 mean_radiance() const;
    // The same surroundings, every radiance multiplied by `intensity` (a lighting preset's
    // environment level).
    Environment with_intensity(double intensity) const;

    Kind kind() const { return kind_; }

  private:
    glm::dvec3 studio_radiance(const glm::dvec3& d) const;
    glm::dvec3 image_radiance(const glm::dvec3& d) const;

    Kind kind_ = Kind::studio;
    glm::dvec3 colour_{1.0};
    double intensity_ = 1.0;
    int width_ = 0;
    int height_ = 0;
    std::vector<glm::vec3> pixels_;
};

}  // namespace gem
