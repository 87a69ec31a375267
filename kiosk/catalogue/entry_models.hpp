#pragma once
// What a catalogue entry is drawn from, built from its files: a piece's stones and metal, a
// design's stone, an OBJ ring's mesh. Validation builds each to check it, but a catalogue holds
// them only for the entry it shows first: a chain's catalogue of hundreds of pieces held every
// piece's meshes (about half a MiB an entry). The others are built again when they come near
// the screen (near_entries.hpp). A database entry's mapping is not a model: the catalogue
// keeps it.

#include <string>
#include <vector>

#include "catalogue/catalogue.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

// Builds the entry's models into it: its stones (a piece's or a design's), then its OBJ ring.
// Errors name the file and the fault, as the engine's loaders say them.
Result<bool> build_entry_models(CatalogueStone& entry);
// The two parts apart, for validation, which leaves out an entry whose stones fail but
// rejects a catalogue whose ring fails. `said`, when given, gets what a glTF piece's reader
// says of the file (how it found its stones, and kWarningLine lines for what it repaired).
Result<bool> build_entry_stones(CatalogueStone& entry, std::vector<std::string>* said = nullptr);
Result<bool> build_entry_ring(CatalogueStone& entry);

// Whether an entry names models it does not hold (validated, then dropped).
bool lacks_models(const CatalogueStone& entry);

// Lets go of the entry's models; the files stay named, so build_entry_models makes them again.
void drop_entry_models(CatalogueStone& entry);

// The same manifest entry: its name and the files it is drawn from.
bool same_entry(const CatalogueStone& a, const CatalogueStone& b);

}  // namespace gem::kiosk
