// libFuzzer target: any bytes handed to Database::open, and every view of what it accepts
// decoded. The reader must answer each input with a database or an Error, never a crash,
// a sanitizer report, an assertion or a runaway allocation.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "tables/reader.hpp"

namespace {

// The reader maps files, and offers no path from memory, so each input goes through one
// file per process.
const std::filesystem::path& input_path() {
    static const std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("gem_fuzz_gemdb_" + std::to_string(::getpid()) + ".gemdb");
    return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::filesystem::path& path = input_path();
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (f == nullptr) return 0;
    const bool written = std::fwrite(data, 1, size, f) == size;
    std::fclose(f);
    if (!written) return 0;

    gem::Result<gem::Database> db = gem::Database::open(path);
    if (!db) return 0;
    const gem::Database& d = db.value();
    // Bounded, so one accepted input with a huge grid cannot stall the run.
    std::uint32_t decoded = 0;
    for (std::uint32_t v = 0; v < d.view_count() && decoded < 64; ++v) {
        for (std::uint32_t l = 0; l < d.level_count(); ++l, ++decoded) {
            gem::Result<gem::DecodedView> view = d.decode(v, l);
            if (view.ok() && !view.value().ray_count.empty()) {
                // Touch the last ray the offsets claim, so a bad offset shows under ASan.
                const auto& x = view.value();
                const std::size_t last = x.ray_count.size() - 1;
                if (x.ray_count[last] > 0) {
                    volatile float w = x.weight[x.ray_offset[last] + x.ray_count[last] - 1];
                    (void)w;
                }
            }
        }
    }
    (void)d.grid().nearest(glm::dvec3(0.3, 0.8, -0.5));
    return 0;
}
