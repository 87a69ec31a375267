#pragma once
// gemrender's GPU path: renders a scene headless through EGL with the table, trace or phong
// method, optionally with a ring, as one image or as a turntable sequence that reports the
// time of every frame (glFinish-bounded) and the time spent streaming views.

#include <string>
#include <vector>

#include "picture/tone_map.hpp"
#include "piece/piece.hpp"
#include "scene/scene.hpp"

namespace gem {

struct GpuRenderOptions {
    std::string method;  // table, trace, phong
    // table: the .gemdb file (one); a piece: tables for any of its kinds of stone, each drawn
    // from the one whose stone it is (gpu/piece_tables.hpp)
    std::vector<std::string> databases;
    bool blend = false;         // table: blend the two nearest stored views
    std::string fire = "none";  // trace: dispersion "none", "first" (first order) or "exact"
    std::string ring;           // "", "parametric" or an OBJ file
    std::string metal = "yellow_gold";
    int frames = 1;                // > 1: a turntable sequence
    double turn_deg = 0.0;         // azimuth step per frame; 0: 360 / frames
    std::string frames_dir;        // where every frame goes as frame-NNNN.png (optional)
    std::string out;               // the (last) image
    DisplayTransform display;      // exposure and tone curve, as the CPU reference's PNG gets
    int msaa = 4;                  // samples per pixel of the rasterised stone and ring
    double glare = 0.0;            // glare share (the kiosk's bloom); 0 compares with the CPU
    int still_frames = 1;          // one picture: frames a sub-pixel apart averaged, as a still
                                   // kiosk view is
    int still_depth = 0;           // trace: those frames' depth where deeper than the scene's
    int still_depth_max = 0;       // ... deeper as they accumulate, to this (StillSchedule)
    const Piece* piece = nullptr;  // trace, phong: the piece instead of the scene's stone and a
                                   // ring, framed by its bounding sphere as the CPU frames it
};

// Returns the process exit status; messages go to stdout/stderr prefixed "gemrender:".
int render_gpu(const Scene& scene, const GpuRenderOptions& options);

}  // namespace gem
