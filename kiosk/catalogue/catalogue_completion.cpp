#include "catalogue/catalogue_completion.hpp"

#include <cerrno>
#include <cstring>
#include <string>

#include "catalogue/catalogue_store.hpp"
#include "catalogue/event_fd.hpp"

namespace gem::kiosk {

Result<std::unique_ptr<CatalogueCompletion>> CatalogueCompletion::start(
    const CatalogueOptions& options) {
    const int ready_fd = make_event_fd();
    if (ready_fd < 0) return Error{std::string("eventfd: ") + std::strerror(errno)};
    std::unique_ptr<CatalogueCompletion> c(new CatalogueCompletion(ready_fd));
    c->thread_ = std::jthread([c = c.get(), options](std::stop_token stop) {
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
