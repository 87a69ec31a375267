// gemtables piece: a piece (a TOML description, its setting built, or a glTF file) written as
// a .glb for a web catalogue or CAD (piece/gltf_piece_writer.hpp says what goes into it).
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "commands.hpp"
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

}  // namespace gem::tables
