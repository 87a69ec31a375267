#pragma once
// Making the display the [display] options ask for: "drm" (a real screen) or "headless".
// Opening a DRM display where there is none fails with one message naming the device(s)
// tried and why; the caller decides what to do (the app may fall back to headless).

#include <memory>
#include <string>
#include <vector>

#include "display/display.hpp"
#include "display/display_options.hpp"
#include "display/seat.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

// The card nodes to try: `device` alone when set (it must exist), else every card<N> in
// `dri_dir`, in number order. Errors name the path and the reason.
Result<std::vector<std::string>> drm_card_candidates(const std::string& device,
                                                     const std::string& dri_dir = "/dev/dri");

// DRM through `seat` (the input module shares it); headless ignores it.
Result<std::unique_ptr<Display>> open_display(const DisplayOptions& options,
                                              std::shared_ptr<Seat> seat);
// DRM opens its own seat, once a card has been found.
Result<std::unique_ptr<Display>> open_display(const DisplayOptions& options);

}  // namespace gem::kiosk
