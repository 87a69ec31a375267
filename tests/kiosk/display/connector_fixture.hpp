#pragma once
// Reads the recorded connector lists of tests/fixtures/drm/ (format in its README.md).

#include <string>
#include <vector>

#include "display/drm_select.hpp"

namespace gem::kiosk::test {

struct RecordedConnectors {
    std::vector<ConnectorInfo> connectors;
    // Per connector, per mode: the refresh modetest printed for it (its own computation,
    // clock * 1000 / (htotal * vtotal), without the interlace adjustment).
    std::vector<std::vector<double>> printed_refresh;
};

// Fails the calling test (ADD_FAILURE) on an unreadable file or a malformed line.
RecordedConnectors read_recorded_connectors(const std::string& file_name);

}  // namespace gem::kiosk::test
