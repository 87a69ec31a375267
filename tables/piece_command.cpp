// gemtables piece: a piece (a TOML description, its setting built, or a glTF file) written as
// a .glb for a web catalogue or CAD (piece/gltf_piece_writer.hpp says what goes into it).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "commands.hpp"
#include "piece/gltf_piece.hpp"
#include "piece/gltf_piece_writer.hpp"
#include "piece/piece_file.hpp"

namespace gem::tables {

int run_piece(const std::string& piece_file, const std::string& out) {
    std::vector<std::string> log;
    Result<Piece> piece = load_piece(piece_file, &log);
    for (const std::string& line : log) std::fprintf(stderr, "gemtables: %s\n", line.c_str());
    if (!piece) return fail(piece.error());
    if (auto written = write_piece_glb(piece.value(), out); !written) {
        return fail(written.error());
    }
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(out, ec);
    std::printf("%s\nwrote %s (%llu bytes)\n", describe(piece.value()).c_str(), out.c_str(),
                static_cast<unsigned long long>(ec ? 0 : bytes));
    return 0;
}

int run_piece_check(const std::string& piece_file) {
    std::vector<std::string> log;
    const auto start = std::chrono::steady_clock::now();
    Result<Piece> piece = load_piece(piece_file, &log);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::size_t warnings = 0;
    for (const std::string& line : log) {
        std::printf("%s\n", line.c_str());
        if (line.starts_with(kWarningLine)) ++warnings;
    }
    if (!piece) {
        std::printf("refused after %.1f ms: %s\n", ms, piece.error().c_str());
        return 1;
    }
    std::printf("%s\nread in %.1f ms, %zu warning(s)\n", describe(piece.value()).c_str(), ms,
                warnings);
    return 0;
}

}  // namespace gem::tables
