// libFuzzer target: any bytes handed to the GemCad design reader (parse_gemcad), and every
// stone it accepts checked as a solid. The reader must answer each input with a stone or an
// Error naming the file, never a crash, a sanitizer report, an assertion or a runaway
// allocation. Seeds: the test designs (tests/fixtures/models/*.asc, shared/data/gemcad).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geometry/validate.hpp"
#include "import/load_model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // Designs are a few kB; a longer input only slows the search down.
    if (size > 64 * 1024) return 0;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto stone = gem::parse_gemcad(text, "fuzz.asc");
    if (stone) (void)gem::check_solid(stone.value());
    return 0;
}
