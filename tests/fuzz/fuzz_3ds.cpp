// libFuzzer target: any bytes handed to the 3D Studio ASCII reader (parse_3ds_ascii), and
// every stone it accepts checked as a solid. Seeds: tests/fixtures/models and cuts written as
// 3ds Max's ASCII export writes them (model_seeds.hpp).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geometry/validate.hpp"
#include "import/load_model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 256 * 1024) return 0;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto stone = gem::parse_3ds_ascii(text, "fuzz.asc");
    if (stone) (void)gem::check_solid(stone.value());
    return 0;
}
