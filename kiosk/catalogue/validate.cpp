#include "catalogue/validate.hpp"

#include <system_error>

#include "catalogue/catalogue_signature.hpp"
#include "catalogue/entry_models.hpp"
#include "catalogue/manifest.hpp"
#include "catalogue/payload_checksums.hpp"
#include "delivery/catalogue_files.hpp"
#include "piece/gltf_piece.hpp"

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
        std::vector<std::string> said;  // a glTF piece says how it found its stones
        Result<bool> built = build_entry_stones(stone, &said);
        if (!built) {
            // A piece or design that cannot be read (a missing stone file, stones that
            // intersect, a setting parameter out of range: piece/piece_file.hpp names the file
            // and key) leaves its entry out, not the catalogue.
            const std::filesystem::path& file = stone.piece.empty() ? stone.design : stone.piece;
            catalogue.left_out.push_back(
                (stone.piece.empty() ? "stone '" : "piece '") + stone.name +
                "' left out: " + relative_message(built.error(), file, real));
            continue;
        }
        for (const std::string& line : said) {
            if (line.starts_with(kWarningLine)) {
                catalogue.warnings.push_back("piece '" + stone.name +
                                             "': " + line.substr(kWarningLine.size()));
            } else {
                catalogue.notes.push_back("piece '" + stone.name + "': " + line);
            }
        }
        if (stone.piece.empty() && stone.design.empty()) {
            auto opened = open_intact_database(stone.database);
            if (!opened) return reject(relative_message(opened.error(), stone.database, real));
            stone.opened = std::move(opened).value();
        }
        Result<bool> ring = build_entry_ring(stone);
        if (!ring) return reject(relative_message(ring.error(), stone.ring_obj, real));
        // Only the entry shown first keeps what was built: the others are built again when
        // they come near the screen (entry_models.hpp), so a catalogue of hundreds of pieces
        // does not hold every piece's meshes.
        if (!kept.empty()) drop_entry_models(stone);
        kept.push_back(std::move(stone));
    }
    if (kept.empty()) return reject(catalogue.left_out.front());
    catalogue.stones = std::move(kept);
    return catalogue;
}

}  // namespace gem::kiosk
