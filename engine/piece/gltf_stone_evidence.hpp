#pragma once
// Whether a glTF part is a stone, on the weight of its evidence. CAD and web viewers mark stones
// in many ways and none is reliable alone: a shank may carry KHR_materials_ior for its clear
// coat, a stone may keep the default material of the layer it was drawn on, a setting may be
// named "Diamond setting". So each sign counts, for or against:
//
//   +3  a transmissive material (KHR_materials_transmission)
//   +3  a vendor's gem material (WEBGI_materials_diamond)
//   +2  KHR_materials_dispersion, or KHR_materials_volume with a thickness
//   +2  a gem word in the node's, mesh's or material's name ("Diamond_12", "dia045")
//   +1  KHR_materials_ior (alone it says no more than that the surface has an index)
//   −2  a metal word in one of those names ("Gold 18K", "Prong 3", "Shank")
//
// A name with both kinds of word ("Diamond setting", "Stone_Prong_2") counts for neither. At
// 2 or more the part is a stone, at 0 or less metal; at 1 its shape decides (gltf_piece.cpp:
// closed and convex, or closed with few facets, is a stone). Clearcoat and metalness say
// nothing: exporters write them on stones and metal alike.

#include <string>
#include <vector>

#include "import/gltf_document.hpp"

namespace gem {

// Words in names that mark a stone, and words that mark metal (lower case, whole words of the
// name split at anything not a letter or digit, and between letters and digits).
extern const std::vector<std::string> kGemWords;
extern const std::vector<std::string> kMetalWords;

struct StoneEvidence {
    int score = 0;
    std::vector<std::string> signs;  // each sign counted, e.g. "its material 'Gem' is transmissive"

    bool stone() const { return score >= 2; }
    bool metal() const { return score <= 0; }
    // "its material 'Gem' is transmissive (+3), its node's name 'Diamond_1' (+2)"
    std::string describe() const;
};

StoneEvidence stone_evidence(const import::GltfPart& part, const import::GltfMaterial* material);

// A name's words: lower case, split at anything not a letter or digit and between letters and
// digits ("Diamond_12" → diamond 12, "dia045" → dia 045).
std::vector<std::string> words_of(const std::string& name);

}  // namespace gem
