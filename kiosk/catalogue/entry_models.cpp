#include "catalogue/entry_models.hpp"

#include "piece/metal_obj.hpp"
#include "piece/piece_file.hpp"
#include "scene/stone_file.hpp"

namespace gem::kiosk {

Result<bool> build_entry_stones(CatalogueStone& entry, std::vector<std::string>* said) {
    if (!entry.piece.empty()) {
        Result<Piece> placed = load_piece(entry.piece, said);
        if (!placed) return Error{placed.error()};
        entry.placed = std::make_shared<const Piece>(std::move(placed).value());
    } else if (!entry.design.empty()) {
        Result<Stone> designed = load_stone_file(entry.design);
        if (!designed) return Error{designed.error()};
        entry.designed = std::make_shared<const Stone>(std::move(designed).value());
    }
    return true;
}

Result<bool> build_entry_ring(CatalogueStone& entry) {
    if (entry.ring == RingKind::obj) {
        Result<MetalMesh> mesh =
            load_metal_obj(entry.ring_obj, entry.metal, RingParams{}.roughness);
        if (!mesh) return Error{mesh.error()};
        entry.ring_mesh = std::make_shared<const MetalMesh>(std::move(mesh).value());
    }
    return true;
}

Result<bool> build_entry_models(CatalogueStone& entry) {
    Result<bool> stones = build_entry_stones(entry);
    if (!stones) return stones;
    return build_entry_ring(entry);
}

bool lacks_models(const CatalogueStone& entry) {
    return (!entry.piece.empty() && entry.placed == nullptr) ||
           (!entry.design.empty() && entry.designed == nullptr) ||
           (entry.ring == RingKind::obj && entry.ring_mesh == nullptr);
}

void drop_entry_models(CatalogueStone& entry) {
    entry.placed.reset();
    entry.designed.reset();
    entry.ring_mesh.reset();
}

bool same_entry(const CatalogueStone& a, const CatalogueStone& b) {
    return a.name == b.name && a.database == b.database && a.design == b.design &&
           a.piece == b.piece && a.ring_obj == b.ring_obj;
}

}  // namespace gem::kiosk
