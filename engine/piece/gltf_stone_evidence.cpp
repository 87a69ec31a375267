#include "piece/gltf_stone_evidence.hpp"

#include <algorithm>
#include <cctype>

namespace gem {

const std::vector<std::string> kGemWords = {
    // English, and the abbreviations CAD exports use ("dia045", "CZ_3")
    "diamond", "diamonds", "dia", "gem", "gems", "gemstone", "stone", "stones", "brilliant", "ruby",
    "sapphire", "emerald", "garnet", "spinel", "topaz", "amethyst", "zirconia", "cz", "moissanite",
    "crystal", "melee",
    // German, French, Italian, Spanish
    "diamant", "edelstein", "stein", "brillant", "pierre", "gemme", "diamante", "gemma", "pietra",
    "gema", "piedra"};

// Metals and the parts of a setting, in the same languages: what a stone is never called.
const std::vector<std::string> kMetalWords = {
    "gold", "platinum", "silver", "metal", "rhodium", "palladium", "titanium", "shank", "prong",
    "prongs", "claw", "claws", "bezel", "setting", "gallery", "basket", "mount", "mounting",
    // German, French, Italian, Spanish
    "weissgold", "gelbgold", "rotgold", "platin", "silber", "fassung", "krappe", "argent",
    "platine", "griffe", "sertissure", "oro", "argento", "platino", "plata", "griffa", "garra"};

std::vector<std::string> words_of(const std::string& name) {
    std::vector<std::string> out;
    std::string word;
    auto flush = [&] {
        if (!word.empty()) out.push_back(word);
        word.clear();
    };
    for (char ch : name) {
        const auto c = static_cast<unsigned char>(ch);
        if (!std::isalnum(c)) {
            flush();
            continue;
        }
        if (!word.empty() && (std::isdigit(c) != 0) !=
                                 (std::isdigit(static_cast<unsigned char>(word.back())) != 0)) {
            flush();
        }
        word.push_back(static_cast<char>(std::tolower(c)));
    }
    flush();
    return out;
}

namespace {

bool has_word(const std::vector<std::string>& words, const std::vector<std::string>& list) {
    return std::any_of(words.begin(), words.end(), [&](const std::string& w) {
        return std::find(list.begin(), list.end(), w) != list.end();
    });
}

bool carries(const import::GltfMaterial& m, const char* extension) {
    return std::find(m.extensions.begin(), m.extensions.end(), extension) != m.extensions.end();
}

}  // namespace

std::string StoneEvidence::describe() const {
    std::string out;
    for (const std::string& s : signs) out += (out.empty() ? "" : ", ") + s;
    return out.empty() ? "no sign either way" : out;
}

StoneEvidence stone_evidence(const import::GltfPart& part, const import::GltfMaterial* material) {
    StoneEvidence e;
    const auto count = [&](int weight, const std::string& sign) {
        e.score += weight;
        e.signs.push_back(sign + " (" + (weight > 0 ? "+" : "") + std::to_string(weight) + ")");
    };
    if (material != nullptr) {
        const std::string its = "its material '" + material->name + "' ";
        if (material->transmission > 0.0) count(3, its + "is transmissive");
        if (material->vendor_gem) count(3, its + "carries " + material->vendor_gem->extension);
        if (carries(*material, "KHR_materials_dispersion")) {
            count(2, its + "carries KHR_materials_dispersion");
        } else if (carries(*material, "KHR_materials_volume") && material->thickness_m > 0.0) {
            count(2, its + "carries KHR_materials_volume");
        }
        if (carries(*material, "KHR_materials_ior")) count(1, its + "carries KHR_materials_ior");
    }
    // Names: the first that says stone and the first that says metal, each counted once.
    const std::pair<const char*, std::string> names[] = {
        {"node", part.node}, {"mesh", part.mesh}, {"material", material ? material->name : ""}};
    bool gem = false, metal = false;
    for (const auto& [what, name] : names) {
        const std::vector<std::string> words = words_of(name);
        const bool g = has_word(words, kGemWords), m = has_word(words, kMetalWords);
        if (g && !m && !gem) {
            gem = true;
            count(2, std::string("its ") + what + "'s name '" + name + "' says stone");
        } else if (m && !g && !metal) {
            metal = true;
            count(-2, std::string("its ") + what + "'s name '" + name + "' says metal");
        }
    }
    return e;
}

}  // namespace gem
