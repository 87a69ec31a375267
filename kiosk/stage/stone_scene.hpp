#pragma once
// What the kiosk shows at one moment, assembled for the GPU: one catalogue stone (its ray-table
// database, its ring, its colour) or piece (its stones and metal) under one background preset and
// one lighting preset, drawn with the configured method. A new stone or background makes a new
// StoneScene (the environment cube and the ring's cube faces are built once per scene); a new
// lighting preset only changes the lights (and the environment level, which needs a new scene too).

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "catalogue/catalogue.hpp"
#include "gpu/frame_composer.hpp"
#include "gpu/frame_renderer.hpp"
#include "piece/ring_mesh.hpp"
#include "scene/environment.hpp"
#include "scene/lights.hpp"
#include "stage/framing.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

struct LookChoice {
    // Background: the studio, a uniform surround, an equirectangular image, or a flat colour
    // behind a studio-lit stone, or a flat colour behind a stone in a light tent.
    enum class Background { studio, uniform, image, colour, tent } background = Background::studio;
    glm::dvec3 colour{0.05};
    std::filesystem::path image;
    double background_intensity = 1.0;
    std::vector<Light> lights;
    double environment_intensity = 1.0;
    double exposure_ev = 0.0;  // the lighting preset's exposure (added to [picture]'s)
};

struct RenderChoice {
    std::string method = "table";  // a stone method by its registry name (gpu/stone_method.hpp)
    bool blend = false;
    int cube_face = 256;
    int depth = 8;  // trace: internal segments followed
    // trace, where the database stores dispersion: every colour channel traced at its own
    // index (exact fire, three times the work) instead of first order.
    bool exact_fire = false;
    int max_level = -1;  // table: highest ray-table level shown; -1: none
    std::size_t cache_bytes = std::size_t{256} << 20;
    bool wait_for_views = false;  // a single still (tests, snapshots) waits for exact views
    double stone_share = 0.25;    // the start view's framing rule (framing.hpp)
};

class StoneScene {
  public:
    // Errors name the stone, and the file or setting that failed. `kind_tables`: a piece's
    // kinds drawn from tables (by kind, null: the configured method; gpu/piece_tables.hpp).
    static Result<std::unique_ptr<StoneScene>> make(
        const CatalogueStone& stone, const LookChoice& look, const RenderChoice& render,
        const std::vector<std::shared_ptr<const Database>>& kind_tables = {});

    gpu::FrameRenderer& renderer() { return renderer_.value(); }
    // The stone's tables; a design (CatalogueStone::design) has none.
    bool has_database() const { return database_ != nullptr; }
    const Database& database() const { return *database_; }
    // The stone, or a piece's centre stone (the hero of the picture).
    const Stone& stone() const;
    bool is_piece() const { return piece_ != nullptr; }
    const std::string& name() const { return name_; }
    // The view a frame composes (gpu/frame_composer.hpp) for `view` in a picture of `size`,
    // framed as framing.hpp says at the start view (start_view.hpp); view.zoom scales that
    // framing. camera(): the same view's camera, unmoved by any jitter.
    gpu::FrameView frame_view(const ViewState& view, glm::ivec2 size) const;
    Result<Camera> camera(const ViewState& view, glm::ivec2 size) const;
    // A piece's small stones each given the model the start view in a picture of `size` needs
    // (gpu/stone_models.hpp); one log line per distinct stone measured, none for a loose stone.
    Result<std::vector<std::string>> choose_stone_models(glm::ivec2 size);
    // The framing for a picture of `size` (computed once per size).
    const Framing& framing(glm::ivec2 size) const;

    // The band of elevations the stone's database holds (the gestures keep the view inside).
    double min_elevation_deg() const { return min_elevation_deg_; }
    double max_elevation_deg() const { return max_elevation_deg_; }

  private:
    StoneScene() = default;
    std::string name_;
    std::shared_ptr<const Database> database_;
    std::shared_ptr<const Stone> designed_;
    std::shared_ptr<const Piece> piece_;
    Environment environment_ = Environment::studio();
    MetalMesh ring_;
    std::optional<gpu::FrameRenderer> renderer_;
    double min_elevation_deg_ = -90.0;
    double max_elevation_deg_ = 90.0;
    double stone_share_ = 0.25;
    mutable glm::ivec2 framed_size_{0};
    mutable Framing framing_;
};

}  // namespace gem::kiosk
