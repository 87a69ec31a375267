#pragma once
// The streaming view cache between the table reader and the GPU (docs/design.md, "Streaming"):
// decoded views are kept within a memory bound (least recently used evicted first), decoded
// on one worker thread from a priority queue, and prefetched along the camera's rotation.
// acquire() never waits for the disk: it answers at once with the best view already resident
// and queues the decode of what was asked, so a later frame gets it.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <thread>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <glm/glm.hpp>

#include "gemdb/database_types.hpp"
#include "gemdb/view_grid.hpp"
#include "util/result.hpp"

namespace gem {

class Database;

// Where decoded views come from: the database, or a stand-in in tests. decode() is called
// from the cache's worker thread only.
class ViewSource {
  public:
    virtual ~ViewSource() = default;
    virtual const ViewGrid& grid() const = 0;
    virtual std::uint32_t level_count() const = 0;
    virtual Result<DecodedView> decode(std::uint32_t view, std::uint32_t level) const = 0;
    // A lower bound of the bytes the decoded view will hold, known before decoding (0 when
    // unknown): the cache refuses a view whose bound already exceeds its memory, so a damaged
    // or absurd index never makes the worker allocate gigabytes.
    virtual std::uint64_t decoded_bytes_at_least(std::uint32_t /*view*/,
                                                 std::uint32_t /*level*/) const {
        return 0;
    }
};

// Decodes from an open database, which it keeps alive.
class DatabaseViewSource final : public ViewSource {
  public:
    explicit DatabaseViewSource(std::shared_ptr<const Database> database);
    const ViewGrid& grid() const override;
    std::uint32_t level_count() const override;
    Result<DecodedView> decode(std::uint32_t view, std::uint32_t level) const override;
    std::uint64_t decoded_bytes_at_least(std::uint32_t view, std::uint32_t level) const override;

  private:
    std::shared_ptr<const Database> database_;
};

// Heap bytes a decoded view holds (every array's capacity × element size); this is what the
// cache's memory bound counts.
std::size_t decoded_view_bytes(const DecodedView& view);

struct ViewCacheOptions {
    std::size_t memory_bytes = 256u << 20;
    // Prefetch looks this far ahead along the rotation, and queues at most this many views.
    double prefetch_horizon_s = 0.5;
    std::uint32_t prefetch_max_views = 8;
    // Demand requests older than the newest this many are dropped: the camera has moved on.
    std::uint32_t max_demand_requests = 16;
};

// Where one stone's view direction is and how it turns (ViewCache::prefetch), in its frame.
struct ViewHeading {
    glm::dvec3 direction{0.0, 0.0, 1.0};
    glm::dvec3 angular_velocity{0.0};  // axis × rad/s
};

// What acquire() found. `view` is null when nothing usable is resident yet (cold start).
struct AcquiredView {
    std::shared_ptr<const DecodedView> view;
    ViewMatch match;  // the stored view shown, its symmetry element and angular offset
    std::uint32_t level = 0;
    bool exact = false;  // the nearest stored view at the wanted level
};

struct ViewCacheStats {
    std::uint64_t hits = 0;    // acquire() answered exactly
    std::uint64_t misses = 0;  // acquire() answered with a stand-in or nothing
    std::uint64_t decodes = 0;
    double decode_seconds = 0.0;
    std::uint64_t evictions = 0;
    std::uint64_t failures = 0;  // views marked bad
    std::size_t bytes_resident = 0;
    std::size_t views_resident = 0;
    std::size_t queued = 0;
};

class ViewCache {
  public:
    // Called once per view that cannot be decoded (damaged, or larger than the whole memory
    // bound), from the worker thread; the view is never requested again.
    using ErrorFn =
        std::function<void(std::uint32_t view, std::uint32_t level, const std::string& message)>;

    ViewCache(std::shared_ptr<const ViewSource> source, const ViewCacheOptions& options = {},
              ErrorFn on_error = {});
    ~ViewCache();  // stops the worker; queued requests are dropped
    ViewCache(const ViewCache&) = delete;
    ViewCache& operator=(const ViewCache&) = delete;

    // Returns at once: the nearest stored view (over the symmetry group) at the wanted level
    // if resident; else that view at the resident level nearest below (then above) it; else
    // the nearest resident view at its best level; else nothing. Queues the decode of the
    // nearest view: its coarsest level first, then the wanted one.
    AcquiredView acquire(const glm::dvec3& direction, std::uint32_t wanted_level);

    // The same for one given stored view (a blend's second view): that view at the wanted
    // level or the resident level nearest below (then above) it, else nothing; queues it
    // when not exact. Never a stand-in from another view.
    AcquiredView acquire_view(const ViewMatch& match, std::uint32_t wanted_level);

    // Queues, below every demand request, the stored views the camera will pass within the
    // prefetch horizon when its view direction turns with `angular_velocity` (axis × rad/s,
    // stone frame): every such view at the coarsest level first, nearest in time first, then
    // at the finer levels up to `wanted_level`. Replaces the previous prefetch. Returns the
    // number of requests queued.
    std::size_t prefetch(const glm::dvec3& direction, const glm::dvec3& angular_velocity,
                         std::uint32_t wanted_level);
    // The same for several stones of one kind, placed apart in a piece, each with its own
    // heading (direction and turn, in the stone's frame): their views ahead in turn, every
    // stone's coarsest first. Replaces the previous prefetch.
    std::size_t prefetch(std::span<const ViewHeading> headings, std::uint32_t wanted_level);

    bool resident(std::uint32_t view, std::uint32_t level) const;
    bool bad(std::uint32_t view, std::uint32_t level) const;
    // Waits until the queue is empty and the worker idle (tests, benchmarks, warm-up).
    bool wait_idle(std::chrono::milliseconds timeout) const;
    ViewCacheStats stats() const;
    const ViewSource& source() const { return *source_; }

  private:
    using Key = std::uint64_t;
    struct Entry {
        std::shared_ptr<const DecodedView> view;
        std::size_t bytes = 0;
        std::list<Key>::iterator lru;
    };
    enum class Kind : std::uint8_t { demand, prefetch };
    struct Request {
        Key key = 0;
        Kind kind = Kind::demand;
        std::uint64_t order = 0;  // demand: newest first; prefetch: lowest first
    };

    Key key(std::uint32_t view, std::uint32_t level) const;
    // All with mutex_ held.
    void enqueue(Key k, Kind kind, std::uint64_t order);
    void demand(std::uint32_t view, std::uint32_t wanted_level);
    bool wanted(Key k) const;
    std::size_t next_request() const;
    int best_level(std::uint32_t view, std::uint32_t wanted_level) const;
    void touch(Entry& entry);
    void insert(Key k, std::shared_ptr<const DecodedView> view, std::size_t bytes);
    void worker();

    std::shared_ptr<const ViewSource> source_;
    ViewCacheOptions options_;
    ErrorFn on_error_;
    std::uint32_t levels_ = 0;

    mutable std::mutex mutex_;
    std::condition_variable work_ready_;
    mutable std::condition_variable idle_;
    bool stopping_ = false;
    bool busy_ = false;
    std::vector<Request> queue_;
    std::uint64_t demand_counter_ = 0;
    std::unordered_map<Key, Entry> resident_;
    std::list<Key> lru_;  // most recently used first
    // acquire()'s fallback scratch, kept to spare an allocation per frame (mutex_ held).
    std::vector<std::uint32_t> fallback_views_;
    std::vector<glm::dvec3> fallback_images_;
    std::unordered_set<Key> bad_;
    Key in_flight_ = ~Key{0};
    ViewCacheStats stats_;
    std::thread thread_;
};

}  // namespace gem
