#pragma once
// The rest of the catalogue the kiosk started with. load_startup_catalogue() opens only its
// first stone before the first frame (with hundreds of entries, opening every piece took
// seconds), so this validates the whole catalogue again on a thread of its own while that
// stone is on screen, and hands the result to the main loop between frames, as the watcher
// hands a delivery. What it hands is what load_startup_catalogue() gives with every entry
// checked: the same installed copy, or the shipped default where the copy's later entries
// fail (and then a warning saying why), or why neither can be shown.

#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "catalogue/catalogue.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

class CatalogueCompletion {
  public:
    // Errors: no eventfd (then the caller validates in its own thread, or shows the first only).
    static Result<std::unique_ptr<CatalogueCompletion>> start(const CatalogueOptions& options);
    // Stops the validation between files and waits for it.
    ~CatalogueCompletion();
    CatalogueCompletion(const CatalogueCompletion&) = delete;
    CatalogueCompletion& operator=(const CatalogueCompletion&) = delete;

    // Readable (poll(2) POLLIN) once take() has the result.
    int event_fd() const { return ready_fd_; }
    // The whole catalogue, or why none could be shown, once; nothing while it is validating.
    std::optional<Result<Catalogue>> take();

  private:
    explicit CatalogueCompletion(int ready_fd) : ready_fd_(ready_fd) {}

    const int ready_fd_;
    std::mutex mutex_;
    std::optional<Result<Catalogue>> done_;  // guarded by mutex_
    std::jthread thread_;                    // last: started after everything it uses exists
};

}  // namespace gem::kiosk
