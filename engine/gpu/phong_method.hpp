#pragma once
// The `phong` method (docs/design.md, "Methods side by side"; thesis fig. 8.17): the stone's
// facets rasterised (the stone pass's triangles) with flat normals and Phong lighting,
// alpha-blended over the background, back facets first and then front facets, no refraction. The
// baseline the table and trace methods are compared against.

#include "geometry/stone.hpp"
#include "gpu/frame_uniforms.hpp"
#include "gpu/gl_handles.hpp"
#include "gpu/program_variants.hpp"
#include "gpu/stone_geometry.hpp"
#include "util/result.hpp"

namespace gem::gpu {

class PhongMethod {
  public:
    // Its programs are built now for every light count and the specular exponent h
    // (frame.shading.h must keep it).
    static Result<PhongMethod> make(const Stone& stone, double h);

    // Draws over the bound framebuffer with GL_SRC_ALPHA / GL_ONE_MINUS_SRC_ALPHA blending:
    // Phong with the lights (k_s, h from frame.shading), ambient from frame.environment along
    // the facet normal, stone colour frame.material.body_colour, opacity 1 − frame.shading.alpha
    // (the thesis' transparency; alpha = 1 leaves only the depth). Writes the depth of the
    // nearest front facet (view_projection(frame.camera, frame.scene_radius_mm)), whatever the
    // depth buffer held there before, so a ring drawn next composites against the stone.
    Result<bool> draw(const StoneFrame& frame) const;

  private:
    PhongMethod(StoneGeometry geometry, ProgramVariants programs, std::uint32_t specular_power);
    StoneGeometry geometry_;            // the stone pass's triangles; normals from its facet planes
    ProgramVariants programs_;          // one per light count, all built by make()
    std::uint32_t specular_power_ = 0;  // specular_power_feature of make()'s h
};

}  // namespace gem::gpu
