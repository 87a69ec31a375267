#pragma once
// A piece from a glTF 2.0 file as jewellery CAD and web viewers write them
// (import/gltf_document.hpp reads the file): the scene's metres into the piece's millimetres,
// +y up as in the piece's frame; every part a stone or metal.
//
// A part is a stone when its material is transmissive (KHR_materials_transmission), when it
// carries a gem extension (KHR_materials_ior, _volume, _dispersion), or when its node's, mesh's
// or material's name holds a gem word (kGemWords: "Diamond_12", "Gem 01", "dia045"), unless a
// manifest beside the file says otherwise (gltf_manifest.hpp); each stone
// says in the log how it was recognised. A part holding several stones (stones merged into one
// mesh) is split into its connected pieces. Every other part is metal, shaded by its
// metallic-roughness factors (F0 mixed from 0.04 to the base colour by the metalness).
//
// A stone's material is a built-in one its names give (ruby, sapphire, ...), else diamond; the
// file's KHR_materials_ior sets its index, KHR_materials_dispersion its fire (the extension's
// Cauchy form), KHR_materials_volume its absorption (σ = −ln(c) / d).
//
// Stones placed by a rotation and a uniform scale (a mesh used by several nodes) stay one kind
// drawn at each placement; a mirrored or unevenly scaled stone is made in the piece's frame, a
// kind of its own. The piece is checked as a free piece is (piece_check.hpp).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "piece/gltf_manifest.hpp"
#include "piece/piece.hpp"
#include "util/result.hpp"

namespace gem {

// Words in node, mesh or material names that mark a stone (lower case, whole words of the
// name split at anything not a letter, and at letters next to digits).
extern const std::vector<std::string> kGemWords;

// `log`, if given, receives one line per stone kind (how it was recognised and its material)
// and one for ignored textures. A manifest beside the file (gltf_manifest.hpp) is read and
// wins over the file's materials and names.
Result<Piece> load_gltf_piece(const std::filesystem::path& path,
                              std::vector<std::string>* log = nullptr);
// The same from the file's bytes; `name` stands for the file in messages (and names the
// piece), `base` is where a .gltf's buffers are looked for.
Result<Piece> parse_gltf_piece(std::string_view bytes, const std::string& name,
                               const std::filesystem::path& base,
                               std::vector<std::string>* log = nullptr,
                               const GltfManifest* manifest = nullptr);

}  // namespace gem
