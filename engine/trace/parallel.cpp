#include "trace/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace gem {

unsigned worker_count() {
    return std::max(1u, std::thread::hardware_concurrency());
}

void parallel_for(std::size_t count, const std::function<void(std::size_t, std::size_t)>& fn,
                  std::size_t chunk) {
    if (count == 0) return;
    chunk = std::max<std::size_t>(chunk, 1);
    const std::size_t chunks = (count + chunk - 1) / chunk;
    const auto threads = static_cast<std::size_t>(std::min<std::size_t>(worker_count(), chunks));
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        for (;;) {
            const std::size_t begin = next.fetch_add(chunk, std::memory_order_relaxed);
            if (begin >= count) return;
            fn(begin, std::min(begin + chunk, count));
        }
    };
    if (threads <= 1) {
        work();
        return;
    }
    std::vector<std::thread> pool;
    pool.reserve(threads - 1);
    for (std::size_t i = 1; i < threads; ++i) pool.emplace_back(work);
    work();  // the calling thread takes chunks too
    for (std::thread& t : pool) t.join();
}

}  // namespace gem
