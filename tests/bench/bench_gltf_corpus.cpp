// The glTF corpus of files made as other tools make them (tests/support/cad_corpus.hpp),
// written to a folder and each read as the kiosk reads a catalogue's piece, timed: what
// docs/gltf.md's corpus table gives, with the lines the reader said. Also writes the two large
// files (a 900k-triangle shank, a ring of 121 stones) for the load and frame times.
//
//   bench_gltf_corpus DIR [--runs N]      (default 5 runs; the median is printed)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "../support/cad_corpus.hpp"
#include "piece/gltf_piece.hpp"
#include "piece/piece_file.hpp"

int main(int argc, char** argv) {
    if (argc != 2 && argc != 4) {
        std::fprintf(stderr, "usage: bench_gltf_corpus DIR [--runs N]\n");
        return 2;
    }
    const int runs = argc == 4 ? std::max(1, std::atoi(argv[3])) : 5;
    namespace cad = gem::test_support::cad;
    std::vector<cad::CorpusFile> files = cad::write_corpus(argv[1]);
    for (auto& f : cad::write_large(argv[1])) files.push_back(std::move(f));
    for (const cad::CorpusFile& f : files) {
        std::vector<double> ms;
        std::vector<std::string> log;
        gem::Result<gem::Piece> piece = gem::Error{""};
        for (int r = 0; r < runs; ++r) {
            log.clear();
            const auto start = std::chrono::steady_clock::now();
            piece = gem::load_piece(f.path, &log);
            ms.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
        }
        std::sort(ms.begin(), ms.end());
        std::printf("%s (%s): %s, read in %.1f ms (median of %d)\n", f.name.c_str(), f.what.c_str(),
                    piece ? gem::describe(piece.value()).c_str() : piece.error().c_str(),
                    ms[ms.size() / 2], runs);
        for (const std::string& line : log) {
            if (line.starts_with(gem::kWarningLine)) std::printf("    %s\n", line.c_str());
        }
    }
    return 0;
}
