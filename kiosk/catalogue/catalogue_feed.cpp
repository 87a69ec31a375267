#include "catalogue/catalogue_feed.hpp"

#include <string>

#include "catalogue/catalogue_store.hpp"
#include "service/log.hpp"

namespace gem::kiosk {

namespace {

// What validation said of a catalogue about to be shown: stones left out, notes, warnings;
// past what it said of `said` (the same catalogue opened for its first stone), which were
// logged then.
void log_catalogue_lines(const Catalogue& catalogue, const Catalogue* said = nullptr) {
    const auto past = [](const std::vector<std::string>& lines, std::size_t logged,
                         void (*log)(std::string_view)) {
        for (std::size_t i = logged; i < lines.size(); ++i) log(lines[i]);
    };
    past(catalogue.left_out, said ? said->left_out.size() : 0, log_error);
    past(catalogue.notes, said ? said->notes.size() : 0, log_info);
    past(catalogue.warnings, said ? said->warnings.size() : 0, log_warning);
}

}  // namespace

CatalogueFeed::CatalogueFeed(const CatalogueOptions& options) {
    // Its first stone only: the rest is validated while that one is shown.
    auto startup = load_startup_catalogue(options, Entries::first);
    if (startup) {
        const Catalogue& c = startup.value();
        log_info("catalogue '" + c.name + "' with " +
                 std::to_string(c.stones.size() + c.unchecked) + " stones from " +
                 c.directory.string() +
                 (c.unchecked > 0 ? "; the first shown, the rest checked while it is" : ""));
        log_catalogue_lines(c);
        if (c.unchecked > 0) {
            auto completion = CatalogueCompletion::start(options);
            if (completion) {
                completion_ = std::move(completion).value();
            } else {
                log_error("catalogue: only its first stone is shown (" + completion.error() + ")");
            }
        }
        shown_ = std::move(startup).value();
    } else {
        // The kiosk still runs: it shows its background and takes the first valid catalogue
        // staff deliver.
        log_error("no catalogue to show: " + startup.error());
    }
    auto watcher = CatalogueWatcher::start(options);
    if (watcher) {
        watcher_ = std::move(watcher).value();
    } else {
        log_error("new catalogues will not be picked up: " + watcher.error());
    }
}

void CatalogueFeed::add_poll_fds(std::vector<int>& fds) const {
    if (watcher_) fds.push_back(watcher_->event_fd());
    if (completion_) fds.push_back(completion_->event_fd());
}

CatalogueFeed::Arrival CatalogueFeed::dispatch() {
    Arrival arrival = Arrival::none;
    if (completion_) {
        if (auto whole = completion_->take()) {
            completion_.reset();
            complete(std::move(*whole), arrival);
        }
    }
    if (watcher_) {
        if (auto incoming = watcher_->take_switch()) switch_to(std::move(*incoming), arrival);
    }
    return arrival;
}

void CatalogueFeed::rescan() {
    log_info("rescanning the catalogue inbox (SIGHUP)");
    if (watcher_) watcher_->rescan();
}

void CatalogueFeed::complete(Result<Catalogue> whole, Arrival& arrival) {
    if (!whole) {
        // Neither the installed copy nor the shipped catalogue validates whole: what is on
        // screen was checked, and nothing more is taken from them.
        log_error(whole.error() + "; only the stone on screen, checked, is shown");
        return;
    }
    if (!shown_ || whole.value().directory != shown_->directory) {
        switch_to(std::move(whole).value(), arrival);  // the copy failed: the default
        return;
    }
    // The same catalogue: what validation said beyond the first stone, and the other stones
    // join the one on screen.
    const Catalogue& c = whole.value();
    log_catalogue_lines(c, &*shown_);
    log_info("catalogue '" + c.name + "': every entry checked, " + std::to_string(c.stones.size()) +
             " to show" +
             (c.left_out.empty() ? "" : ", " + std::to_string(c.left_out.size()) + " left out"));
    shown_ = std::move(whole).value();
    arrival = Arrival::completed;
}

void CatalogueFeed::switch_to(Catalogue catalogue, Arrival& arrival) {
    completion_.reset();  // a delivery outranks what the startup catalogue would have become
    log_notice("showing catalogue '" + catalogue.name + "' (" +
               std::to_string(catalogue.stones.size()) + " stones" +
               (catalogue.signed_by.empty() ? "" : ", signed by key " + catalogue.signed_by) +
               ") from " + catalogue.directory.string());
    log_catalogue_lines(catalogue);
    shown_ = std::move(catalogue);
    arrival = Arrival::switched;
}

}  // namespace gem::kiosk
