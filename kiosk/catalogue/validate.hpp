#pragma once
// Whether a catalogue directory may go on screen: the manifest parses, there is at least one
// stone, every database opens (header, section and index checksums) and every stored view's
// payload checksum verifies, and every OBJ ring loads. Every fault is one line naming the
// catalogue, the file (relative to the directory) and the fault, e.g.
//   catalogue 'spring' rejected: stones/ruby.gemdb: view 12 level 0: checksum mismatch

#include <filesystem>
#include <stop_token>

#include "catalogue/catalogue.hpp"
#include "catalogue/catalogue_signature.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

// `dir` may be a symlink (state/current): the Catalogue names the directory it resolves to,
// and holds the databases and meshes it checked. Where `trust` requires it, the manifest's
// signature and the files' digests are checked first (catalogue_signature.hpp); the digests a
// manifest gives are checked in any case. Gives up between files once `stop` is requested (the
// watcher's shutdown).
// Whether the files' digests are checked: always for a delivery. The kiosk's own installed copy
// is not hashed again at start: it was checked when it was installed, it lies where only the
// kiosk writes, and its databases' own checksums (checked still) find damage; so a restart
// does not hash a whole catalogue before its first frame.
enum class DigestCheck { check, skip };
// Which stones are opened and checked: all, or only the first that can be shown (those before
// it that cannot are left out as usual), so that a catalogue of hundreds of entries shows its
// first at once; the Catalogue then counts the others as unchecked, and
// CatalogueCompletion checks them on a thread of its own.
enum class Entries { all, first };
Result<Catalogue> validate_catalogue(const std::filesystem::path& dir,
                                     const CatalogueTrust& trust = {}, std::stop_token stop = {},
                                     DigestCheck digests = DigestCheck::check,
                                     Entries entries = Entries::all);

}  // namespace gem::kiosk
