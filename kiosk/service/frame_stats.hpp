#pragma once
// What the kiosk measures about itself while it runs: the time each frame took from the start
// of its drawing to present() returning, the interval between presented frames, and the time
// from an input event to the presentation of the first frame that shows it. The summary line
// is what the closing log line and the benchmark report; a CSV keeps every frame.

#include <cstdio>
#include <deque>
#include <string>
#include <vector>

namespace gem::kiosk {

struct FrameRecord {
    double start_s = 0.0;       // CLOCK_MONOTONIC when drawing began
    double draw_ms = 0.0;       // drawing + present, glFinish-bounded
    double interval_ms = 0.0;   // since the previous presented frame (0 for the first)
    double latency_ms = -1.0;   // oldest input event shown for the first time; -1: none
    double streaming_ms = 0.0;  // table views: cache lookups, waits and uploads
    // False: the picture on screen shown again undrawn (a settled still view); it counts in
    // total() but not in the drawing figures.
    bool drawn = true;
    // Drawn while render.method = "auto" measured the methods between the frames shown (with
    // the safe choice, its frame rate halved): counted in total() and named apart, not in the
    // drawing figures, which are the chosen method's.
    bool probing = false;
    // Its place in a still view (gpu::StillFrame::index: 0 its first, then its refining
    // frames, each band of one a record of its own); -1: a frame of a moving view.
    int still = -1;
};

class FrameStats {
  public:
    // Keeps at most `max_records` frames (the newest): a kiosk runs for weeks, and every frame
    // kept is memory; 0 keeps all (bounded runs that write a CSV).
    explicit FrameStats(std::size_t max_records = 0) : max_records_(max_records) {}
    void add(const FrameRecord& record);
    const std::deque<FrameRecord>& frames() const { return frames_; }
    long total() const { return total_; }  // every frame added, kept or not, drawn or not

    // "600 frames in 40.1 s: 15.0 frames/s; draw ms p50 63.1 p90 70.2 p99 81.0 max 90.3;
    //  input-to-frame ms p50 .. (n events)", and where both kinds were drawn, the moving
    //  frames' draw and the still views' apart: a still view's frames trace deeper and draw
    //  in bands, and a figure of both is a figure of neither.
    std::string summary() const;
    // One row per frame; errors name the file.
    bool write_csv(const std::string& path, std::string& error) const;

  private:
    std::size_t max_records_;
    std::deque<FrameRecord> frames_;
    long total_ = 0;
    long shown_again_ = 0;
    long while_probing_ = 0;
};

// The p-quantile (0..1) of `values` by the nearest-rank method; 0 for an empty list.
double quantile(std::vector<double> values, double p);

}  // namespace gem::kiosk
