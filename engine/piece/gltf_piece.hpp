#pragma once
// A piece from a glTF 2.0 file as jewellery CAD and web viewers write them
// (import/gltf_document.hpp reads the file): the scene's metres into the piece's millimetres
// (a file written in millimetres is seen by its size and read so), +y up as in the piece's
// frame (a file whose centre stone's table faces another axis is turned); every part a stone
// or metal.
//
// A part is a stone on the weight of its evidence (gltf_stone_evidence.hpp: its material, a
// vendor's gem extension, its names, and where those disagree its shape), unless a manifest
// beside the file says otherwise (gltf_manifest.hpp); each stone says in the log how it was
// recognised. A part holding several stones (stones merged into one mesh) is split into its
// connected pieces. Every other part is metal, shaded by the metallic-roughness factors of the
// material that covers most of it (F0 mixed from the dielectric's to the base colour by the
// metalness).
//
// Liberal in what it takes: what can be shown is shown, and what was repaired or read past is
// one "warning: FILE: ..." line in the log naming the node. Points and lines are skipped;
// triangles with no area dropped; a stone wound against itself turned, an open one closed
// (by its facets' planes, else by filling its holes); a "stone" that cannot be traced (a
// part of more than 100,000 triangles, or one that stays open) is drawn as metal; the piece
// check (piece_check.hpp: stones apart, held, seats no deeper than a setter's) only warns, as
// CAD seats are often not cut and a loose stone has no metal. Refused only when no stone is
// left.
//
// A stone's material is a built-in one its names give (ruby, sapphire, ...), else diamond; the
// file's KHR_materials_ior sets its index, KHR_materials_dispersion its fire (the extension's
// Cauchy form), KHR_materials_volume its absorption (σ = −ln(c) / d), and a vendor's gem
// material (WEBGI_materials_diamond) its index, fire and colour where Khronos's say nothing.
//
// Stones placed by a rotation and a uniform scale (a mesh used by several nodes) stay one kind
// drawn at each placement; a mirrored or unevenly scaled stone is made in the piece's frame, a
// kind of its own.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "piece/gltf_manifest.hpp"
#include "piece/piece.hpp"
#include "util/result.hpp"

namespace gem {

// What begins each line of `log` that says what was repaired or read past.
inline constexpr std::string_view kWarningLine = "warning: ";

// `log`, if given, receives one line per stone kind (how it was recognised and its material),
// one kWarningLine line per repair or problem, and one for ignored textures. A manifest beside the
// file (gltf_manifest.hpp) is read and wins over the file's materials and names.
Result<Piece> load_gltf_piece(const std::filesystem::path& path,
                              std::vector<std::string>* log = nullptr);
// The same from the file's bytes; `name` stands for the file in messages (and names the
// piece), `base` is where a .gltf's buffers are looked for.
Result<Piece> parse_gltf_piece(std::string_view bytes, const std::string& name,
                               const std::filesystem::path& base,
                               std::vector<std::string>* log = nullptr,
                               const GltfManifest* manifest = nullptr);

}  // namespace gem
