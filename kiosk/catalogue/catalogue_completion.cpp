#include "catalogue/catalogue_completion.hpp"

#include <pthread.h>
#include <sched.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "catalogue/catalogue_store.hpp"
#include "catalogue/event_fd.hpp"
#include "service/log.hpp"

namespace gem::kiosk {

Result<std::unique_ptr<CatalogueCompletion>> CatalogueCompletion::start(
    const CatalogueOptions& options) {
    const int ready_fd = make_event_fd();
    if (ready_fd < 0) return Error{std::string("eventfd: ") + std::strerror(errno)};
    std::unique_ptr<CatalogueCompletion> c(new CatalogueCompletion(ready_fd));
    c->thread_ = std::jthread([c = c.get(), options](std::stop_token stop) {
        // Only on a core the kiosk leaves idle: the frames on screen and the method probe's
        // timings (render.method auto) go first; on llvmpipe a validation beside them took
        // the probe from 1.4 to 7 s and would skew what it measures.
        const sched_param idle{};
        if (::pthread_setschedparam(::pthread_self(), SCHED_IDLE, &idle) != 0) {
            log_debug("catalogue: the rest is checked at normal priority");
        }
        Result<Catalogue> whole = load_startup_catalogue(options, Entries::all, stop);
        {
            std::lock_guard lock(c->mutex_);
            c->done_ = std::move(whole);
        }
        signal_event_fd(c->ready_fd_);
    });
    return c;
}

CatalogueCompletion::~CatalogueCompletion() {
    thread_.request_stop();
    if (thread_.joinable()) thread_.join();
    ::close(ready_fd_);
}

std::optional<Result<Catalogue>> CatalogueCompletion::take() {
    drain_event_fd(ready_fd_);
    std::lock_guard lock(mutex_);
    return std::exchange(done_, std::nullopt);
}

}  // namespace gem::kiosk
