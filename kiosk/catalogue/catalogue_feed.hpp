#pragma once
// The catalogues a kiosk session shows, from the one it starts with to each one staff deliver:
// the startup catalogue opened at its first entry and checked whole while that one is shown
// (CatalogueCompletion), deliveries picked up as they are installed (CatalogueWatcher), and
// what validation said of each in the journal. A catalogue that cannot be opened or watched is
// said once; the kiosk runs without it (it shows its background, and takes the first valid
// catalogue delivered).

#include <memory>
#include <optional>
#include <vector>

#include "catalogue/catalogue.hpp"
#include "catalogue/catalogue_completion.hpp"
#include "catalogue/catalogue_watcher.hpp"

namespace gem::kiosk {

class CatalogueFeed {
  public:
    explicit CatalogueFeed(const CatalogueOptions& options);

    // The catalogue shown; null when none could be opened.
    const Catalogue* shown() const { return shown_ ? &*shown_ : nullptr; }
    void add_poll_fds(std::vector<int>& fds) const;

    enum class Arrival {
        none,
        completed,  // the catalogue shown, checked whole: its other entries join it
        switched,   // another catalogue shown (a delivery, or the default where the copy failed)
    };
    // What arrived since the last call (a switch outranks a completion).
    Arrival dispatch();
    // SIGHUP: the inbox looked at again.
    void rescan();

  private:
    void complete(Result<Catalogue> whole, Arrival& arrival);
    void switch_to(Catalogue catalogue, Arrival& arrival);

    std::optional<Catalogue> shown_;
    std::unique_ptr<CatalogueCompletion> completion_;  // the startup catalogue's later entries
    std::unique_ptr<CatalogueWatcher> watcher_;
};

}  // namespace gem::kiosk
