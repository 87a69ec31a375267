// libFuzzer target: any bytes handed to both Wavefront OBJ readers, the stone's (parse_obj,
// then checked as a solid) and the metal's (parse_metal_obj: a ring drawn in CAD). Each must
// answer with a model or an Error naming the file, never a crash, a sanitizer report, an
// assertion or a runaway allocation. Seeds: tests/fixtures/models and cuts written as CAD
// tools write OBJ (model_seeds.hpp).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geometry/validate.hpp"
#include "import/load_model.hpp"
#include "piece/metal_obj.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 256 * 1024) return 0;  // the seeds are a few kilobytes
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto stone = gem::parse_obj(text, "fuzz.obj");
    if (stone) (void)gem::check_solid(stone.value());
    (void)gem::parse_metal_obj(text, "fuzz-ring.obj", gem::Metal::yellow_gold, 0.2);
    return 0;
}
