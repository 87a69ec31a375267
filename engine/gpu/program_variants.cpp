#include "gpu/program_variants.hpp"

#include <cmath>

#include "gpu/program_catalog.hpp"

namespace gem::gpu {

std::vector<std::string> feature_defines(std::uint32_t features) {
    static constexpr const char* kDefines[kLightCountShift] = {
        "SHADING_THESIS", "CUBE_AT_INFINITY", "FIRE_FIRST_ORDER",
        "FIRE_EXACT",     "TWO_VIEWS",        "ABSORBING"};
    std::vector<std::string> defines;
    for (std::uint32_t bit = 0; bit < std::size(kDefines); ++bit) {
        if ((features & (1u << bit)) != 0) defines.emplace_back(kDefines[bit]);
    }
    if (const int lights = light_count_of(features); lights > 0) {
        defines.push_back("LIGHT_COUNT " + std::to_string(lights));
    }
    if (const int power = specular_power_of(features); power > 0) {
        defines.push_back("SPECULAR_POWER " + std::to_string(power));
    }
    if ((features & kSeesPiece) != 0) defines.emplace_back("SEES_PIECE");
    if ((features & kVisibility) != 0) defines.emplace_back("VISIBILITY");
    if ((features & kVisibilitySamples) != 0) defines.emplace_back("VISIBILITY_SAMPLES");
    return defines;
}

std::string glsl_version(std::uint32_t features) {
    return (features & kVisibilitySamples) != 0 ? "310 es" : "300 es";
}

std::uint32_t specular_power_feature(double h) {
    const bool whole = h >= 1.0 && h <= kMaxSpecularPower && h == std::floor(h);
    return whole ? static_cast<std::uint32_t>(h) << kSpecularPowerShift : 0u;
}

ProgramVariants::ProgramVariants(std::string name, std::vector<std::string> defines)
    : name_(std::move(name)), defines_(std::move(defines)) {}

Result<const Program*> ProgramVariants::build(std::uint32_t features) {
    std::vector<std::string> defines = defines_;
    for (std::string& define : feature_defines(features)) defines.push_back(std::move(define));
    auto program = build_program(name_, defines, glsl_version(features));
    if (!program) return Error{program.error()};
    return &built_.emplace(features, std::move(program).value()).first->second;
}

}  // namespace gem::gpu
