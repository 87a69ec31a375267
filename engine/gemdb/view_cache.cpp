#include "gemdb/view_cache.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <optional>

#include "gemdb/reader.hpp"
#include "gemdb/view_cache_motion.hpp"

namespace gem {

DatabaseViewSource::DatabaseViewSource(std::shared_ptr<const Database> database)
    : database_(std::move(database)) {
    assert(database_ != nullptr);
}

const ViewGrid& DatabaseViewSource::grid() const {
    return database_->grid();
}

std::uint32_t DatabaseViewSource::level_count() const {
    return database_->level_count();
}

Result<DecodedView> DatabaseViewSource::decode(std::uint32_t view, std::uint32_t level) const {
    return database_->decode(view, level);
}

std::uint64_t DatabaseViewSource::decoded_bytes_at_least(std::uint32_t view,
                                                         std::uint32_t level) const {
    // decode() first inflates the whole raw payload, and the decoded arrays are larger still
    // (every 16-bit field widens to a float or a vec3).
    return database_->payload(view, level).raw_bytes;
}

std::size_t decoded_view_bytes(const DecodedView& v) {
    auto bytes = [](const auto& array) {
        return array.capacity() * sizeof(typename std::decay_t<decltype(array)>::value_type);
    };
    return bytes(v.ray_offset) + bytes(v.ray_count) + bytes(v.truncated_weight) +
           bytes(v.direction) + bytes(v.weight) + bytes(v.path_mm) + bytes(v.position) +
           bytes(v.bounces) + bytes(v.facet) + bytes(v.dir_dn);
}

ViewCache::ViewCache(std::shared_ptr<const ViewSource> source, const ViewCacheOptions& options,
                     ErrorFn on_error)
    : source_(std::move(source)), options_(options), on_error_(std::move(on_error)) {
    assert(source_ != nullptr && source_->grid().size() > 0);
    levels_ = source_->level_count();
    assert(levels_ > 0);
    queue_.reserve(options_.max_demand_requests + 4 * options_.prefetch_max_views * levels_);
    thread_ = std::thread([this] { worker(); });
}

ViewCache::~ViewCache() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
        queue_.clear();
    }
    work_ready_.notify_all();
    thread_.join();
}

ViewCache::Key ViewCache::key(std::uint32_t view, std::uint32_t level) const {
    return static_cast<Key>(view) * levels_ + level;
}

bool ViewCache::wanted(Key k) const {
    return k != in_flight_ && !resident_.contains(k) && !bad_.contains(k);
}

void ViewCache::enqueue(Key k, Kind kind, std::uint64_t order) {
    if (!wanted(k)) return;
    for (Request& r : queue_) {
        if (r.key != k) continue;
        // A view asked for by a frame outranks the same view prefetched.
        if (kind == Kind::demand) r = {k, kind, std::max(order, r.order)};
        return;
    }
    queue_.push_back({k, kind, order});
}

std::size_t ViewCache::next_request() const {
    assert(!queue_.empty());
    std::size_t best = 0;
    for (std::size_t i = 1; i < queue_.size(); ++i) {
        const Request& a = queue_[i];
        const Request& b = queue_[best];
        if (a.kind != b.kind) {
            if (a.kind == Kind::demand) best = i;
        } else if (a.kind == Kind::demand ? a.order > b.order : a.order < b.order) {
            best = i;
        }
    }
    return best;
}

int ViewCache::best_level(std::uint32_t view, std::uint32_t wanted_level) const {
    for (int l = static_cast<int>(wanted_level); l >= 0; --l) {
        if (resident_.contains(key(view, static_cast<std::uint32_t>(l)))) return l;
    }
    for (std::uint32_t l = wanted_level + 1; l < levels_; ++l) {
        if (resident_.contains(key(view, l))) return static_cast<int>(l);
    }
    return -1;
}

void ViewCache::touch(Entry& entry) {
    lru_.splice(lru_.begin(), lru_, entry.lru);
}

AcquiredView ViewCache::acquire(const glm::dvec3& direction, std::uint32_t wanted_level) {
    wanted_level = std::min(wanted_level, levels_ - 1);
    const ViewGrid& grid = source_->grid();
    // The grid is immutable, so the lookup runs before the lock is taken.
    std::array<ViewMatch, 8> near{};
    const std::size_t found = grid.nearest_k(direction, near);
    assert(found > 0);

    AcquiredView out;
    std::lock_guard lock(mutex_);
    auto take = [&](const ViewMatch& match, int level) {
        Entry& entry = resident_.at(key(match.view, static_cast<std::uint32_t>(level)));
        touch(entry);
        out.view = entry.view;
        out.match = match;
        out.level = static_cast<std::uint32_t>(level);
    };
    bool chosen = false;
    for (std::size_t i = 0; i < found && !chosen; ++i) {
        const int level = best_level(near[i].view, wanted_level);
        if (level < 0) continue;
        take(near[i], level);
        out.exact = i == 0 && out.level == wanted_level;
        chosen = true;
    }
    if (!chosen && !resident_.empty()) {
        // None of the close views is in yet: the nearest of all resident ones stands in.
        // Each resident view counts once however many of its levels are in; acos falls as
        // its argument rises, so the largest (clamped) cosine is the smallest angle and only
        // the winner's is turned into one.
        fallback_views_.clear();
        for (const auto& entry : resident_) {
            fallback_views_.push_back(static_cast<std::uint32_t>(entry.first / levels_));
        }
        std::sort(fallback_views_.begin(), fallback_views_.end());
        fallback_views_.erase(std::unique(fallback_views_.begin(), fallback_views_.end()),
                              fallback_views_.end());
        const glm::dvec3 asked = glm::normalize(direction);
        fallback_images_.clear();
        for (const glm::dmat3& g : grid.group()) fallback_images_.push_back(g * asked);
        ViewMatch best{fallback_views_.front(), 0, 0.0};
        double best_cosine = -std::numeric_limits<double>::infinity();
        for (const std::uint32_t view : fallback_views_) {
            const glm::dvec3& stored = grid.direction(view);
            for (std::size_t g = 0; g < fallback_images_.size(); ++g) {
                const double cosine = std::clamp(glm::dot(fallback_images_[g], stored), -1.0, 1.0);
                if (cosine > best_cosine) {
                    best_cosine = cosine;
                    best.view = view;
                    best.symmetry = static_cast<std::uint32_t>(g);
                }
            }
        }
        // An empty group (never built by ViewGrid) keeps nearest_image()'s "no match" angle.
        best.angle = fallback_images_.empty() ? 4.0 : std::acos(best_cosine);
        take(best, best_level(best.view, wanted_level));
    }
    out.exact ? ++stats_.hits : ++stats_.misses;

    if (!out.exact) demand(near[0].view, wanted_level);
    return out;
}

AcquiredView ViewCache::acquire_view(const ViewMatch& match, std::uint32_t wanted_level) {
    wanted_level = std::min(wanted_level, levels_ - 1);
    AcquiredView out;
    out.match = match;
    std::lock_guard lock(mutex_);
    const int level = best_level(match.view, wanted_level);
    if (level >= 0) {
        Entry& entry = resident_.at(key(match.view, static_cast<std::uint32_t>(level)));
        touch(entry);
        out.view = entry.view;
        out.level = static_cast<std::uint32_t>(level);
        out.exact = out.level == wanted_level;
    }
    out.exact ? ++stats_.hits : ++stats_.misses;
    if (!out.exact) demand(match.view, wanted_level);
    return out;
}

void ViewCache::demand(std::uint32_t view, std::uint32_t wanted_level) {
    // The wanted level first, the coarse one on top of it: it is cheap and shows the right
    // direction soon.
    enqueue(key(view, wanted_level), Kind::demand, ++demand_counter_);
    if (wanted_level > 0 && best_level(view, wanted_level) < 0) {
        enqueue(key(view, 0), Kind::demand, ++demand_counter_);
    }
    if (queue_.size() > options_.max_demand_requests) {
        // Frames ask every few milliseconds; requests the camera has left behind go.
        const std::uint64_t keep_from = demand_counter_ >= options_.max_demand_requests
                                            ? demand_counter_ - options_.max_demand_requests
                                            : 0;
        std::erase_if(queue_, [&](const Request& r) {
            return r.kind == Kind::demand && r.order <= keep_from;
        });
    }
    work_ready_.notify_one();
}

std::size_t ViewCache::prefetch(const glm::dvec3& direction, const glm::dvec3& angular_velocity,
                                std::uint32_t wanted_level) {
    const ViewHeading heading{direction, angular_velocity};
    return prefetch(std::span<const ViewHeading>(&heading, 1), wanted_level);
}

std::size_t ViewCache::prefetch(std::span<const ViewHeading> headings, std::uint32_t wanted_level) {
    wanted_level = std::min(wanted_level, levels_ - 1);
    std::vector<std::vector<std::uint32_t>> ahead;
    ahead.reserve(headings.size());
    for (const ViewHeading& h : headings) {
        ahead.push_back(views_ahead(source_->grid(), h.direction, h.angular_velocity,
                                    options_.prefetch_horizon_s, options_.prefetch_max_views));
    }
    std::lock_guard lock(mutex_);
    std::erase_if(queue_, [](const Request& r) { return r.kind == Kind::prefetch; });
    std::uint64_t order = 0;
    std::size_t queued = 0;
    for (std::uint32_t level = 0; level <= wanted_level; ++level) {
        for (const std::vector<std::uint32_t>& views : ahead) {
            for (std::uint32_t view : views) {
                const Key k = key(view, level);
                if (!wanted(k)) continue;
                const std::size_t before = queue_.size();
                enqueue(k, Kind::prefetch, order++);
                queued += queue_.size() - before;
            }
        }
    }
    if (queued > 0) work_ready_.notify_one();
    return queued;
}

bool ViewCache::resident(std::uint32_t view, std::uint32_t level) const {
    std::lock_guard lock(mutex_);
    return resident_.contains(key(view, level));
}

bool ViewCache::bad(std::uint32_t view, std::uint32_t level) const {
    std::lock_guard lock(mutex_);
    return bad_.contains(key(view, level));
}

bool ViewCache::wait_idle(std::chrono::milliseconds timeout) const {
    std::unique_lock lock(mutex_);
    return idle_.wait_for(lock, timeout, [&] { return queue_.empty() && !busy_; });
}

ViewCacheStats ViewCache::stats() const {
    std::lock_guard lock(mutex_);
    ViewCacheStats s = stats_;
    s.views_resident = resident_.size();
    s.queued = queue_.size();
    return s;
}

void ViewCache::insert(Key k, std::shared_ptr<const DecodedView> view, std::size_t bytes) {
    assert(bytes <= options_.memory_bytes);
    while (stats_.bytes_resident + bytes > options_.memory_bytes) {
        assert(!lru_.empty());
        const auto victim = resident_.find(lru_.back());
        // Frames holding the view keep it alive through their shared_ptr.
        stats_.bytes_resident -= victim->second.bytes;
        resident_.erase(victim);
        lru_.pop_back();
        ++stats_.evictions;
    }
    lru_.push_front(k);
    resident_.emplace(k, Entry{std::move(view), bytes, lru_.begin()});
    stats_.bytes_resident += bytes;
}

void ViewCache::worker() {
    std::unique_lock lock(mutex_);
    for (;;) {
        work_ready_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
        if (stopping_) return;
        const std::size_t i = next_request();
        const Key k = queue_[i].key;
        queue_[i] = queue_.back();
        queue_.pop_back();
        in_flight_ = k;
        busy_ = true;
        lock.unlock();

        const auto view = static_cast<std::uint32_t>(k / levels_);
        const auto level = static_cast<std::uint32_t>(k % levels_);
        const auto start = std::chrono::steady_clock::now();
        auto too_large = [&](std::uint64_t bytes) {
            return "view " + std::to_string(view) + " level " + std::to_string(level) + " needs " +
                   std::to_string(bytes) + " bytes, more than the cache's memory bound of " +
                   std::to_string(options_.memory_bytes);
        };
        std::optional<std::string> failure;
        std::shared_ptr<const DecodedView> shared;
        std::size_t bytes = 0;
        if (const std::uint64_t at_least = source_->decoded_bytes_at_least(view, level);
            at_least > options_.memory_bytes) {
            failure = too_large(at_least);
        } else if (Result<DecodedView> decoded = source_->decode(view, level); !decoded) {
            failure = decoded.error();
        } else {
            bytes = decoded_view_bytes(decoded.value());
            if (bytes > options_.memory_bytes) {
                failure = too_large(bytes);
            } else {
                shared = std::make_shared<const DecodedView>(std::move(decoded).value());
            }
        }
        const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;

        lock.lock();
        ++stats_.decodes;
        stats_.decode_seconds += took.count();
        in_flight_ = ~Key{0};
        if (failure) {
            bad_.insert(k);
            ++stats_.failures;
        } else {
            insert(k, std::move(shared), bytes);
        }
        if (failure && on_error_) {
            // The callback may call back into the cache (e.g. stats()), so no lock is held.
            lock.unlock();
            on_error_(view, level, *failure);
            lock.lock();
        }
        busy_ = false;
        if (queue_.empty()) idle_.notify_all();
    }
}

}  // namespace gem
