#include "catalogue/validate.hpp"

#include <system_error>

#include "catalogue/catalogue_signature.hpp"
#include "catalogue/manifest.hpp"
#include "catalogue/payload_checksums.hpp"
#include "delivery/catalogue_files.hpp"
#include "piece/gltf_piece.hpp"
#include "piece/metal_obj.hpp"
#include "piece/piece_file.hpp"
#include "scene/stone_file.hpp"

namespace gem::kiosk {

namespace {

// The engine's messages start with the absolute path; staff know the catalogue's own names.
std::string relative_message(const std::string& message, const std::filesystem::path& file,
                             const std::filesystem::path& dir) {
    const std::string absolute = file.string();
    const std::string relative = file.lexically_relative(dir).string();
    if (message.rfind(absolute, 0) == 0) return relative + message.substr(absolute.size());
    return relative + ": " + message;
}

}  // namespace

Result<Catalogue> validate_catalogue(const std::filesystem::path& dir, const CatalogueTrust& trust,
                                     std::stop_token stop, DigestCheck digests, Entries entries) {
    std::string label = dir.filename().string();
    auto reject = [&](const std::string& fault) {
        return Error{"catalogue '" + label + "' rejected: " + fault};
    };
    std::error_code ec;
    const std::filesystem::path real = std::filesystem::canonical(dir, ec);
    if (ec) return reject(dir.string() + ": " + ec.message());
    if (!std::filesystem::is_directory(real, ec)) return reject(dir.string() + ": not a directory");

    // The manifest's bytes are read once: what its signature is checked against is what is
    // parsed, and nothing of a catalogue from an unknown signer is parsed at all.
    Result<std::string> text = read_manifest_text(real);
    if (!text) return reject(text.error());
    std::string signed_by;
    if (trust.required) {
        Result<std::string> key = check_manifest_signature(real, text.value(), trust);
        if (!key) return reject(key.error());
        signed_by = key.value();
    }
    Result<Catalogue> manifest = parse_manifest(text.value(), real);
    if (!manifest) return reject(manifest.error());
    Catalogue catalogue = std::move(manifest).value();
    catalogue.signed_by = signed_by;
    label = catalogue.name;
    if (trust.required && catalogue.digests.empty()) {
        return reject(std::string(kManifestName) +
                      ": names no file's digest ([blake2b]: gemtables catalogue or gemtables "
                      "seal writes it), so its signature does not cover the catalogue");
    }
    if (!catalogue.digests.empty() && digests == DigestCheck::check) {
        if (stop.stop_requested()) return reject("validation stopped (shutting down)");
        Result<bool> whole = tables::check_catalogue_digests(real, catalogue.digests);
        if (!whole) return reject(whole.error());
    }
    std::vector<CatalogueStone> kept;
    for (std::size_t i = 0; i < catalogue.stones.size(); ++i) {
        CatalogueStone& stone = catalogue.stones[i];
        if (entries == Entries::first && !kept.empty()) {
            catalogue.unchecked = catalogue.stones.size() - i;
            break;
        }
        if (stop.stop_requested()) return reject("validation stopped (shutting down)");
        if (!stone.piece.empty()) {
            // A piece that cannot be read (a missing stone file, stones that intersect, a
            // setting parameter out of range: piece/piece_file.hpp names the file and key)
            // leaves its entry out, not the catalogue.
            std::vector<std::string> recognised;  // a glTF piece says how it found its stones
            Result<Piece> placed = load_piece(stone.piece, &recognised);
            if (!placed) {
                catalogue.left_out.push_back("piece '" + stone.name + "' left out: " +
                                             relative_message(placed.error(), stone.piece, real));
                continue;
            }
            for (const std::string& line : recognised) {
                if (line.starts_with(kWarningLine)) {
                    catalogue.warnings.push_back("piece '" + stone.name +
                                                 "': " + line.substr(kWarningLine.size()));
                } else {
                    catalogue.notes.push_back("piece '" + stone.name + "': " + line);
                }
            }
            stone.placed = std::make_shared<const Piece>(std::move(placed).value());
        } else if (!stone.design.empty()) {
            // A design that cannot be read leaves its stone out, not the catalogue.
            Result<Stone> designed = load_stone_file(stone.design);
            if (!designed) {
                catalogue.left_out.push_back(
                    "stone '" + stone.name +
                    "' left out: " + relative_message(designed.error(), stone.design, real));
                continue;
            }
            stone.designed = std::make_shared<const Stone>(std::move(designed).value());
        } else {
            auto opened = open_intact_database(stone.database);
            if (!opened) return reject(relative_message(opened.error(), stone.database, real));
            stone.opened = std::move(opened).value();
        }
        if (stone.ring == RingKind::obj) {
            Result<MetalMesh> mesh =
                load_metal_obj(stone.ring_obj, stone.metal, RingParams{}.roughness);
            if (!mesh) return reject(relative_message(mesh.error(), stone.ring_obj, real));
            stone.ring_mesh = std::make_shared<const MetalMesh>(std::move(mesh).value());
        }
        kept.push_back(std::move(stone));
    }
    if (kept.empty()) return reject(catalogue.left_out.front());
    catalogue.stones = std::move(kept);
    return catalogue;
}

}  // namespace gem::kiosk
