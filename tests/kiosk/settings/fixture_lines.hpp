#pragma once
// Where a fixture text puts a key: the config tests find expected line numbers by searching
// the text they wrote, never by asking the loader.

#include <string_view>

#include <gtest/gtest.h>

namespace gem::kiosk {

// 1-based number of the line of `text` that contains `needle` (its `nth` occurrence).
inline int line_of(std::string_view text, std::string_view needle, int nth = 1) {
    std::size_t at = std::string_view::npos;
    for (std::size_t from = 0; nth > 0; --nth, from = at + 1) {
        at = text.find(needle, from);
        if (at == std::string_view::npos) {
            ADD_FAILURE() << "fixture has no " << needle;
            return -1;
        }
    }
    int line = 1;
    for (std::size_t i = 0; i < at; ++i) line += text[i] == '\n' ? 1 : 0;
    return line;
}

}  // namespace gem::kiosk
