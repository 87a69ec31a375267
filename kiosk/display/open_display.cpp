#include "display/open_display.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <sys/stat.h>

#include "display/drm_display.hpp"
#include "display/headless_display.hpp"

namespace gem::kiosk {
namespace {

// "card12" -> 12; -1 for anything else (renderD128, by-path, ...).
long card_number(const std::string& name) {
    if (name.rfind("card", 0) != 0 || name.size() == 4) return -1;
    for (std::size_t i = 4; i < name.size(); ++i) {
        if (name[i] < '0' || name[i] > '9') return -1;
    }
    return std::strtol(name.c_str() + 4, nullptr, 10);
}

Result<std::vector<std::string>> drm_cards(const DisplayOptions& options) {
    auto cards = drm_card_candidates(options.device);
    if (!cards) return Error{"DRM display: " + cards.error()};
    return cards;
}

}  // namespace

Result<std::vector<std::string>> drm_card_candidates(const std::string& device,
                                                     const std::string& dri_dir) {
    if (!device.empty()) {
        struct stat st {};
        if (stat(device.c_str(), &st) != 0) {
            return Error{device + ": " + std::strerror(errno)};
        }
        return std::vector<std::string>{device};
    }
    std::error_code error;
    std::filesystem::directory_iterator it(dri_dir, error);
    if (error) {
        return Error{"no DRM card: " + dri_dir + ": " + error.message() + " (tried " + dri_dir +
                     "/card*; is a GPU driver loaded?)"};
    }
    std::vector<std::pair<long, std::string>> found;
    for (const auto& entry : it) {
        const std::string name = entry.path().filename().string();
        const long n = card_number(name);
        if (n >= 0) found.emplace_back(n, entry.path().string());
    }
    if (found.empty()) {
        return Error{"no DRM card: " + dri_dir + " has no card* node (tried " + dri_dir +
                     "/card*)"};
    }
    std::sort(found.begin(), found.end());
    std::vector<std::string> cards;
    for (auto& [n, path] : found) cards.push_back(std::move(path));
    return cards;
}

Result<std::unique_ptr<Display>> open_display(const DisplayOptions& options,
                                              std::shared_ptr<Seat> seat) {
    if (options.backend == "headless") {
        auto display = HeadlessDisplay::make(options);
        if (!display) return Error{display.error()};
        return std::unique_ptr<Display>(std::move(display).value());
    }
    if (options.backend != "drm") {
        return Error{"display backend '" + options.backend + "': expected drm or headless"};
    }
    auto cards = drm_cards(options);
    if (!cards) return Error{cards.error()};
    if (!seat) seat = Seat::open();
    auto display = DrmDisplay::make(options, std::move(seat), cards.value());
    if (!display) return Error{display.error()};
    return std::unique_ptr<Display>(std::move(display).value());
}

Result<std::unique_ptr<Display>> open_display(const DisplayOptions& options) {
    return open_display(options, nullptr);
}

}  // namespace gem::kiosk
