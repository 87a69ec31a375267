#pragma once
// A catalogue: the stones a kiosk shows, as staff deliver them in a directory holding
// catalogue.toml (the manifest, manifest.hpp) and the files it names. A Catalogue from
// validate_catalogue (validate.hpp) holds the very databases it checked, already mapped, so the
// render loop never opens or trusts a file itself.

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "catalogue/catalogue_signature.hpp"
#include "gemdb/reader.hpp"
#include "piece/piece.hpp"
#include "piece/ring_mesh.hpp"

namespace gem::kiosk {

struct CatalogueOptions {
    // Staff drop catalogue directories here (systemd/ makes it writable for them); those
    // refused are set aside there as <name>.rejected (catalogue_store.hpp).
    std::filesystem::path inbox_dir = "/var/lib/gemkiosk/inbox";
    // Further places to look, such as a USB stick's mount point; one that does not exist yet
    // is looked at again when the mount table changes or on rescan().
    std::vector<std::filesystem::path> extra_dirs;
    // The kiosk's state directory (config [catalogue] state_dir): installed copies in
    // state/catalogues/<name>-<n> and the symlink state/current (catalogue_store.hpp).
    std::filesystem::path state_dir = "/var/lib/gemkiosk";
    // The catalogue shipped with the kiosk, used when state/current is missing or damaged.
    std::filesystem::path default_catalogue = "/usr/share/gemkiosk/catalogue";
    // A directory is considered only once no file in it has changed size or mtime for this
    // long: a copy in progress (cp, a file manager, rsync) keeps changing them.
    std::chrono::milliseconds settle_time{5000};
    // Keys a catalogue's manifest must be signed with (config [catalogue] trusted_keys, read at
    // start); not required: catalogues are taken unsigned (catalogue_signature.hpp).
    CatalogueTrust trust;
    // Non-empty: no delivered catalogue is installed, and this says why at every delivery (the
    // kiosk's config could not be read or parsed: kiosk/settings/config_fallback.hpp). The
    // catalogue is left where it is, to be installed once the kiosk starts on a good config.
    std::string deliveries_refused_because;
};

enum class RingKind {
    parametric,  // made to fit the stone (make_ring)
    none,        // a loose stone
    obj,         // a Wavefront OBJ in the stone frame (piece/metal_obj.hpp)
};

struct CatalogueStone {
    std::string name;                        // shown to staff in logs
    std::filesystem::path database;          // absolute, inside the catalogue directory
    std::shared_ptr<const Database> opened;  // the mapping validation checked
    // Instead of a database: a stone description (a .toml as in config/stones/: a cut, or a
    // model file, and a material), drawn by the exact trace, which needs no tables.
    std::filesystem::path design;           // absolute, inside the catalogue directory
    std::shared_ptr<const Stone> designed;  // the stone validation built from it
    // Instead of either: a piece description (a .toml as in config/pieces/: a setting, its
    // metal and stones), every stone drawn by the exact trace.
    std::filesystem::path piece;          // absolute, inside the catalogue directory
    std::shared_ptr<const Piece> placed;  // the piece validation built from it
    RingKind ring = RingKind::parametric;
    std::filesystem::path ring_obj;              // RingKind::obj: absolute path
    std::shared_ptr<const MetalMesh> ring_mesh;  // RingKind::obj: the mesh loaded
    Metal metal = Metal::yellow_gold;
    // Shading-time material overrides (the database records the defaults).
    std::optional<glm::dvec3> colour;
    std::optional<glm::dvec3> absorption_per_mm;
    // Preset names resolved by the settings module; empty: the kiosk's default.
    std::string background;
    std::string lighting;
};

struct Catalogue {
    std::string name;
    std::filesystem::path directory;  // canonical: an installed copy, never the symlink
    std::vector<CatalogueStone> stones;
    // Stones validation left out (a design that cannot be read), one message each; the rest
    // of the catalogue is shown.
    std::vector<std::string> left_out;
    // What validation found worth saying of the stones kept: how a glTF piece's stones were
    // recognised and what they are made of, a line each.
    std::vector<std::string> notes;
    // What a glTF piece's reader repaired or read past ("piece 'X': FILE: ..."), a line each:
    // the piece is shown, and staff may want to look at the file.
    std::vector<std::string> warnings;
    // The manifest's [blake2b] table: every other file (relative) and its digest in hex.
    std::map<std::string, std::string> digests;
    // The key that signed the manifest, as minisign prints its id; empty when unsigned.
    std::string signed_by;
    // Entries after `stones` not opened yet: the catalogue was opened for its first stone only
    // (validate.hpp, Entries::first), and holds nothing of them until they are checked.
    std::size_t unchecked = 0;
};

}  // namespace gem::kiosk
