// libFuzzer target: any bytes handed to the STL reader (parse_stl: binary or ASCII, chosen by
// size and content as for a file), and every stone it accepts checked as a solid. Seeds:
// tests/fixtures/models and cuts written as CAD tools write STL (model_seeds.hpp).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geometry/validate.hpp"
#include "import/load_model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 256 * 1024) return 0;
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    auto stone = gem::parse_stl(bytes, "fuzz.stl");
    if (stone) (void)gem::check_solid(stone.value());
    return 0;
}
