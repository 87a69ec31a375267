#include "piece/ring_mesh.hpp"

#include <cmath>

#include "piece/settings.hpp"

namespace gem {
namespace {

Result<bool> check(const RingParams& p) {
    auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
    if (!positive(p.inner_radius_mm)) return Error{"ring.inner_radius_mm: must be positive"};
    if (!positive(p.band_width_mm)) return Error{"ring.band_width_mm: must be positive"};
    if (!positive(p.band_thickness_mm)) return Error{"ring.band_thickness_mm: must be positive"};
    if (p.prong_width_mm != 0.0 && !(p.prong_width_mm >= 0.2 && p.prong_width_mm <= 3.0)) {
        return Error{"ring.prong_width_mm: must be 0.2..3, or 0 to fit the stone"};
    }
    if (p.prongs < 2 || p.prongs > 12) return Error{"ring.prongs: must be 2..12"};
    if (!(p.roughness >= 0.0 && p.roughness <= 1.0)) return Error{"ring.roughness: must be 0..1"};
    return true;
}

}  // namespace

Result<MetalMesh> make_ring(const RingParams& params, const Stone& stone) {
    if (auto ok = check(params); !ok) return Error{ok.error()};
    if (stone.vertices.empty() || stone.triangles.empty()) {
        return Error{"ring: the stone '" + stone.name + "' has no geometry"};
    }
    // The solitaire setting (piece/settings.hpp) with the stone at the centre: the piece's
    // frame is the stone's.
    SettingParams setting;
    setting.kind = SettingKind::solitaire;
    setting.metal = params.metal;
    setting.roughness = params.roughness;
    setting.shank = {2.0 * params.inner_radius_mm, params.band_width_mm, params.band_thickness_mm};
    setting.claws.claws = params.prongs;
    setting.claws.width_mm = params.prong_width_mm;
    setting.claws.first_deg = 180.0 / params.prongs;  // one claw each side of the +x axis
    Result<Piece> piece = make_setting(setting, stone.name, stone, std::nullopt);
    if (!piece) return Error{"ring: " + piece.error()};
    return std::move(piece.value().metal);
}

}  // namespace gem
