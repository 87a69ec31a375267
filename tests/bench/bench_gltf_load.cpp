// How long a piece of 56 stones takes to load: from its TOML (the setting built), and from the
// .glb gemtables piece writes of it, as written and as gltfpack passes it on (meshopt
// compressed; quantised to gltfpack's 14 bits). The loads are interleaved, one of each per
// round, and the median of the rounds printed, with the file sizes.
//
//   bench_gltf_load [ROUNDS]      (default 9)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "piece/gltf_piece.hpp"
#include "piece/gltf_piece_writer.hpp"
#include "piece/piece_file.hpp"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
    const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 9;
    const fs::path dir = fs::temp_directory_path() / "gem-bench-gltf";
    fs::create_directories(dir);
    // The eternity band with 1.1 mm stones: 56 of them round the finger.
    const fs::path toml = dir / "band50.toml";
    std::ofstream(toml) << "[piece]\nname = \"Band of 1.1 mm stones\"\nsetting = \"band\"\n"
                        << "metal = \"platinum\"\nfinger_diameter_mm = 17.3\n"
                        << "band_thickness_mm = 1.4\n\n[small]\nstone = \""
                        << (fs::path(GEM_CONFIG_DIR) / "stones" / "melee-diamond.toml").string()
                        << "\"\nwidth_mm = 1.1\ngap_mm = 0.12\n";
    auto piece = gem::load_piece(toml);
    if (!piece) {
        std::fprintf(stderr, "bench_gltf_load: %s\n", piece.error().c_str());
        return 1;
    }
    struct Input {
        std::string what;
        fs::path file;
        std::vector<double> ms;
    };
    std::vector<Input> inputs = {{"TOML (setting built)", toml, {}},
                                 {".glb as written", dir / "band50.glb", {}}};
    if (auto ok = gem::write_piece_glb(piece.value(), inputs[1].file); !ok) {
        std::fprintf(stderr, "bench_gltf_load: %s\n", ok.error().c_str());
        return 1;
    }
    for (const auto& [what, options] : {std::pair{"gltfpack -noq -c (meshopt)", "-noq -c"},
                                        std::pair{"gltfpack (14-bit quantised)", ""}}) {
        const fs::path out = dir / ("band50-" + std::to_string(inputs.size()) + ".glb");
        const std::string command = "gltfpack -i '" + inputs[1].file.string() + "' -o '" +
                                    out.string() + "' " + options + " > /dev/null 2>&1";
        if (std::system(command.c_str()) == 0) {
            inputs.push_back({what, out, {}});
        } else {
            std::printf("(no %s: gltfpack did not run)\n", what);
        }
    }
    for (int r = 0; r < rounds; ++r) {
        for (Input& in : inputs) {
            const auto start = std::chrono::steady_clock::now();
            auto read = gem::load_piece(in.file);
            const auto end = std::chrono::steady_clock::now();
            if (!read || read.value().stones.size() != piece.value().stones.size()) {
                std::fprintf(stderr, "bench_gltf_load: %s: %s\n", in.what.c_str(),
                             read ? "a different number of stones" : read.error().c_str());
                return 1;
            }
            in.ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
        }
    }
    std::printf("%s; %d rounds, medians:\n", gem::describe(piece.value()).c_str(), rounds);
    for (Input& in : inputs) {
        std::sort(in.ms.begin(), in.ms.end());
        std::printf("  %-30s %8.1f ms  (min %.1f, max %.1f)  %9llu bytes\n", in.what.c_str(),
                    in.ms[in.ms.size() / 2], in.ms.front(), in.ms.back(),
                    static_cast<unsigned long long>(fs::file_size(in.file)));
    }
    return 0;
}
