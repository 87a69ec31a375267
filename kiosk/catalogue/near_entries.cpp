#include "catalogue/near_entries.hpp"

#include <pthread.h>
#include <sched.h>

#include "catalogue/entry_models.hpp"
#include "service/log.hpp"

namespace gem::kiosk {

namespace {

Result<CatalogueStone> built(CatalogueStone entry) {
    Result<bool> models = build_entry_models(entry);
    if (!models) return Error{"catalogue entry '" + entry.name + "': " + models.error()};
    return entry;
}

}  // namespace

NearEntries::~NearEntries() {
    drop_ahead();
}

Result<CatalogueStone> NearEntries::bring(const CatalogueStone& entry) {
    if (!lacks_models(entry)) return entry;
    if (ahead_.valid() && same_entry(*ahead_entry_, entry)) {
        ahead_entry_.reset();
        return ahead_.get();
    }
    drop_ahead();
    return built(entry);
}

void NearEntries::build_ahead(const CatalogueStone& entry) {
    if (ahead_.valid() && same_entry(*ahead_entry_, entry)) return;
    drop_ahead();
    if (!lacks_models(entry)) return;
    ahead_entry_ = entry;
    ahead_ = std::async(std::launch::async, [entry] {
        const sched_param idle{};
        if (::pthread_setschedparam(::pthread_self(), SCHED_IDLE, &idle) != 0) {
            log_debug("catalogue: the next entry is built at normal priority");
        }
        return built(entry);
    });
}

void NearEntries::drop_ahead() {
    if (ahead_.valid()) ahead_.wait();
    ahead_ = {};
    ahead_entry_.reset();
}

}  // namespace gem::kiosk
