// libFuzzer target: any bytes handed to the glTF piece reader (parse_gltf_piece: the glTF
// library, the accessors, the node tree, the stones' facets and the piece check). The reader
// must answer each input with a piece or an Error naming the file, never a crash, a sanitizer
// report, an assertion or a runaway allocation. A piece it gives is grouped as the GPU groups
// its stones (piece/sight_groups.hpp): every stone in one group, each seen from a finite point;
// and its sight mesh (piece/sight_mesh.hpp) is built: every leaf's triangles within the mesh,
// every inner node's right child after it, every float finite.
// Seeds: gem_fuzz_seeds' glTF pieces.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "piece/gltf_piece.hpp"
#include "piece/sight_groups.hpp"
#include "piece/sight_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 256 * 1024) return 0;  // the seeds are a few kilobytes
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    // No folder to look in: a .gltf naming outside buffers gets an error, not a file.
    auto piece = gem::parse_gltf_piece(bytes, "fuzz.glb", "/nonexistent");
    if (!piece) return 0;
    std::vector<int> seen(piece.value().stones.size(), 0);
    for (const gem::SightGroup& g : gem::sight_groups(piece.value())) {
        if (!std::isfinite(g.centre.x) || !std::isfinite(g.centre.y) ||
            !std::isfinite(g.centre.z)) {
            __builtin_trap();
        }
        for (const std::size_t i : g.stones) ++seen.at(i);
    }
    for (const int n : seen) {
        if (n != 1) __builtin_trap();
    }
    const gem::Piece& p = piece.value();
    std::vector<gem::PlacedStone> placed;
    for (const gem::PieceStone& s : p.stones) {
        placed.push_back({&p.kinds.at(s.kind), s.placement, &p.kinds.at(s.kind).material});
    }
    const gem::SightMesh mesh = gem::sight_mesh(p.metal, placed);
    if (mesh.nodes.size() % 8 != 0 || mesh.triangles.size() != 24 * mesh.triangle_count) {
        __builtin_trap();
    }
    for (const float f : mesh.nodes) {
        if (!std::isfinite(f)) __builtin_trap();
    }
    for (const float f : mesh.triangles) {
        if (!std::isfinite(f)) __builtin_trap();
    }
    const std::size_t node_count = mesh.nodes.size() / 8;
    for (std::size_t i = 0; i < node_count; ++i) {
        const auto first = static_cast<std::size_t>(mesh.nodes[8 * i + 3]);
        const auto count = static_cast<std::size_t>(mesh.nodes[8 * i + 7]);
        if (count > 0 ? first + count > mesh.triangle_count : first <= i || first >= node_count) {
            __builtin_trap();
        }
    }
    return 0;
}
