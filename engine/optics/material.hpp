#pragma once
// Gem materials: refractive index with dispersion, body colour and Beer–Lambert absorption.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace gem {

// Fraunhofer lines used by gemmologists (nm): dispersion is quoted as n(G) - n(B).
inline constexpr double kFraunhoferB = 686.7;
inline constexpr double kFraunhoferD = 589.3;
inline constexpr double kFraunhoferG = 430.8;

// Refractive index as a function of wavelength.
struct Dispersion {
    enum class Kind { constant, cauchy, sellmeier };
    Kind kind = Kind::constant;
    // constant: coef[0] = n. cauchy: n = coef[0] + coef[1] / λ² (λ in µm).
    // sellmeier: n² = 1 + Σ B_i λ² / (λ² − C_i), coef = {B1, C1, B2, C2, B3, C3}, λ in µm, C in
    // µm².
    std::vector<double> coef{1.5};

    double index(double wavelength_nm) const;
    // A finite n >= 1 everywhere in the rendered spectrum, with no Sellmeier resonance in it:
    // what index() and the shading assume of a material read from a file.
    bool is_physical() const;
    static Dispersion constant_index(double n);
    // Cauchy fit through n(D) and the B–G dispersion n(G) − n(B).
    static Dispersion cauchy_from_nd(double nd, double dispersion_bg);
};

struct Material {
    std::string name = "glass";
    Dispersion dispersion;
    glm::dvec3 body_colour{1.0};        // the thesis' stone colour I_o (linear RGB, 0..1)
    glm::dvec3 absorption_per_mm{0.0};  // Beer–Lambert coefficient per linear RGB channel

    double index(double wavelength_nm = kFraunhoferD) const {
        return dispersion.index(wavelength_nm);
    }
    // Whether the index changes with wavelength: a stone of it shows fire.
    bool disperses() const { return dispersion.kind != Dispersion::Kind::constant; }
};

// The built-in catalogue of materials (diamond, sapphire, ruby, emerald, garnet, spinel,
// cubic zirconia, moissanite, quartz, crown glass), looked up by name, case-insensitive.
std::optional<Material> find_material(std::string_view name);
const std::vector<Material>& builtin_materials();

}  // namespace gem
