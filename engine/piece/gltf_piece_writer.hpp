#pragma once
// A piece written as glTF 2.0 (.glb), for a shop's web catalogue and for CAD: the piece's
// millimetres as glTF's metres, +y up as in the piece's frame. Each kind of stone is one mesh,
// split at its facets so each facet keeps its flat normal, used by one node per placed stone
// (a rotation and a translation); the metal is one mesh with its own normals.
//
// A stone's material says what it is in the Khronos gem extensions, as web viewers and this
// project's reader (gltf_piece.hpp) take them: transmissive (KHR_materials_transmission), its
// index at the d line (KHR_materials_ior), its fire as 20 / V_d (KHR_materials_dispersion),
// and its volume (KHR_materials_volume: the stone's height as thickness, its Beer–Lambert
// absorption as an attenuation colour and distance); its name is the material's (a built-in
// one is read back exactly), its base colour the body colour. The metal's material is
// metallic, its base colour the metal's F0 and its roughness the metal's.

#include <filesystem>
#include <string>

#include "piece/piece.hpp"
#include "util/result.hpp"

namespace gem {

Result<std::string> piece_glb(const Piece& piece);
// Written whole or not at all (a temporary file renamed over `path`).
Result<bool> write_piece_glb(const Piece& piece, const std::filesystem::path& path);

// The material's Abbe number V_d = (n_d − 1) / (n_F − n_C), at glTF's wavelengths (the
// extension's λ_d 587.6, λ_F 486.1, λ_C 656.3 nm); infinite for a material without fire.
double abbe_number(const Material& material);

}  // namespace gem
