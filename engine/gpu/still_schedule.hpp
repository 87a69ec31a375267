#pragma once
// How a still view is refined (HdrPicture averages its frames): how many frames, how deep each
// traces, and for how long.
//
// A still picture is held back by two things (docs/accuracy.md, "The still picture converges
// to the spectral truth", a diamond at 40° against the converged reference): its frames, and
// the depth they trace to. 256 frames at depth 16 are ΔE00 5.29 from the truth, at depth 64
// 1.57; 16 frames at depth 16 are 7.33. More frames at a shallow depth stop helping once their
// noise is below that depth's bias, so the depth doubles each time the frames do, from
// kFramesAtFirstDepth on: frames 0-15 at `depth`, 16-31 at twice it, 32-63 at four times, up
// to `depth_max`. The mean mixes them; the shallow frames' share, and so their bias, falls as
// the deep ones accumulate (a sixteenth of a 256-frame view is at the first depth).
//
// The view is refined while the shopper looks: for `seconds` after it stopped (0: no limit),
// until it has `frames` frames, the point where more change nothing the reference can tell
// (1024 at depth 64: ΔE00 1.17, the 64-sample reference's own noise). A touch restarts it at
// once; the frame in flight is what it waits for, so a still frame expected to take longer
// than `frame_ms` is drawn in bands(), horizontal bands of the picture one after another,
// each a frame of the display (HdrPicture). Its cost is estimated from the last still frame's
// (on llvmpipe a frame's cost grows about linearly with its depth, docs/accuracy.md); a frame
// that would need more than kMostBands bands is traced shallower, never below `depth`.

namespace gem::gpu {

struct StillScheduleOptions {
    int frames = 16;    // at most this many frames averaged (the moving view's own first)
    int depth = 0;      // the still frames' depth at first; 0: the moving frames'
    int depth_max = 0;  // the deepest they come to as frames accumulate (≤ depth: never deeper)
    double seconds = 0.0;   // refined at most this long after the view stopped; 0: no limit
    double frame_ms = 0.0;  // a frame (or band of one) expected within this; 0: no bound
};

class StillSchedule {
  public:
    // The first depth keeps its frames this long; then each doubling of the frames doubles it.
    static constexpr int kFramesAtFirstDepth = 16;
    // A frame in more bands than this is traced shallower instead: each band draws again what
    // is not traced (its clear, the background, the stones' depth and the metal's passes), so
    // many bands cost more than the depth gains. 16, not 8: a still frame of the halo at
    // 1920×1080 on llvmpipe, its metal and stones following their rays through the piece, takes
    // about 1.3 s whatever its depth; in 8 bands a touch waited 170 ms at the median, in 16
    // 87 ms, for 16 frames in 21.3 s instead of 20.5 (docs/accuracy.md).
    static constexpr int kMostBands = 16;

    StillSchedule() = default;
    explicit StillSchedule(const StillScheduleOptions& options) : options_(options) {}

    // A frame begins at `now_s`: the last one's view (`still`) or a new one (a restart).
    void begin_frame(bool still, double now_s);
    // A frame's measured cost at its depth() (in bands: its dearest band's times the bands):
    // what the next is judged by.
    void frame_drawn(double ms);

    // This frame's place in the still view: -1 moving, 0 the view's first (the moving view's
    // own frame), then 1, 2, ... up to frames().
    int index() const { return index_; }
    // The depth this frame traces to: 0 for a moving frame (the moving frames' own).
    int depth() const { return depth_; }
    // In how many bands this frame is drawn (1: whole).
    int bands() const { return bands_; }
    // Drawing more changes nothing: all its frames, or its time is up.
    bool settled() const { return settled_; }
    // How long after its first frame began this view settled.
    double settled_after_s() const { return settled_s_ - started_s_; }
    int deepest() const { return deepest_; }  // the deepest frame of this view

  private:
    // The depth the rule gives frame `index`, before the cost bound.
    int wanted_depth(int index) const;
    void note_depth();  // deepest_ kept

    StillScheduleOptions options_;
    int index_ = -1;
    int depth_ = 0;
    int bands_ = 1;
    bool settled_ = false;
    double started_s_ = 0.0;
    double settled_s_ = 0.0;
    int deepest_ = 0;
    // The last still frame's cost per unit of depth (ms); 0: none measured yet in this view.
    double ms_per_depth_ = 0.0;
};

}  // namespace gem::gpu
