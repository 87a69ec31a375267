#pragma once
// The thesis' method on the GPU (docs/design.md, "Stage 2: shading"): the view cache streams
// ray-tables from a .gemdb, the stored views the camera needs are uploaded as textures, and
// the stone pass shades them where the stone is (table.frag). Between stored directions it shows
// either the nearest stored view or a blend of the two nearest (TableOptions::blend).

#include <array>
#include <memory>
#include <span>

#include "gemdb/reader.hpp"
#include "gemdb/view_cache.hpp"
#include "gpu/frame_uniforms.hpp"
#include "gpu/gl_handles.hpp"
#include "gpu/program_variants.hpp"
#include "gpu/stone_geometry.hpp"
#include "util/result.hpp"

namespace gem::gpu {

struct TableOptions {
    bool blend = false;  // false: the nearest stored view; true: the two nearest, weighted
    // Headless renders (tests, gemrender) wait until the views they want are decoded; the
    // kiosk does not and shows what is resident (after a scene's first frame, below).
    bool wait_for_views = false;
    // A new scene's first frame finds nothing resident. true: it waits for its view (at most
    // 5 s), so a stone never first appears as an empty setting (the VM test saw seconds of it
    // under emulation); later frames never wait. false: that frame shows the background.
    bool wait_on_cold_start = true;
    // The highest level shown (a cheaper, coarser view for a slow GPU); -1: no cap.
    int max_level = -1;
    // Stored views kept on the GPU, most recently used first: two for a blend and one on its
    // way in. A piece whose stones of one kind are drawn from tables needs one (two in a blend)
    // per stone, or every frame uploads each stone's view again.
    std::size_t gpu_views = 3;
    ViewCacheOptions cache;
};

struct TableFrameStats {
    double acquire_ms = 0.0;  // view cache lookups (never waits on the disk unless asked)
    double upload_ms = 0.0;   // texture uploads of views not yet on the GPU
    double wait_ms = 0.0;     // waiting for decodes (wait_for_views only)
    std::uint32_t uploads = 0;
    std::uint32_t level = 0;  // level shown by the nearest view
    bool exact = false;       // the nearest stored view at the wanted level was shown
    // Every view the frame asked for was shown at its level (the nearest and, in a blend, the
    // second): the same view drawn again looks the same.
    bool complete = false;
    bool drawn = false;       // false when nothing was resident yet (cold start)
    double angle_rad = 0.0;   // between the asked direction and the nearest view's image
    std::uint32_t views = 0;  // stored views shaded: 1, or 2 in a blend
    double blend = 1.0;       // weight of the nearest view
};

// The level whose side best serves a stone `pixels_across` pixels wide on screen: the first
// at least that wide (else the largest), capped at `max_level` when it is not -1.
std::uint32_t table_level_for(const Database& database, double pixels_across, int max_level = -1);

class TableMethod {
  public:
    static Result<TableMethod> make(std::shared_ptr<const Database> database,
                                    const TableOptions& options = {});
    TableMethod(TableMethod&&) noexcept;
    TableMethod& operator=(TableMethod&&) noexcept;
    ~TableMethod();

    // Draws the stone layer. frame.stone is ignored: the database's stone is drawn. Errors: a
    // camera the database cannot serve (perspective against orthographic tables, or another
    // eye distance), GL errors.
    Result<bool> draw(const StoneFrame& frame, TableFrameStats* stats = nullptr);

    // Before a frame at `camera`: queues the views the stones heading as `headings` say (in the
    // stone's frame) will reach, at the level that serves the stone at the camera's scale;
    // `wait`: until they are decoded.
    void prefetch(const Camera& camera, std::span<const ViewHeading> headings, bool wait);

    const Database& database() const { return *database_; }
    ViewCache& cache() { return *cache_; }
    // The level whose side best serves a stone `pixels_across` pixels wide on screen.
    std::uint32_t level_for(double pixels_across) const;

  private:
    struct GpuView;
    TableMethod() = default;
    Result<const GpuView*> upload(const AcquiredView& acquired, TableFrameStats& stats);

    std::shared_ptr<const Database> database_;
    std::unique_ptr<ViewCache> cache_;
    TableOptions options_;
    std::unique_ptr<StoneGeometry> stone_;
    ProgramVariants programs_;  // shading, fire and one or two views compiled in
    // The views on the GPU, most recently used first; a blend needs two, a turn a third.
    std::vector<std::unique_ptr<GpuView>> gpu_views_;
    // Packing space for uploads, kept so a turn does not reallocate tens of MB per view.
    std::vector<std::uint32_t> pixel_scratch_;
    std::vector<float> ray_scratch_[3];
};

}  // namespace gem::gpu
