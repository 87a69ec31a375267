#pragma once
// catalogue.toml, the manifest of a catalogue directory:
//
//   [catalogue]
//   name = "spring"                      # required
//
//   [[stone]]                            # one or more
//   name = "Blue oval sapphire"          # required, unique; shown to staff in logs
//   database = "stones/sapphire.gemdb"   # relative to the directory; or, instead:
//   design = "stones/sapphire.toml"      # a stone description as in config/stones/ (a cut or
//                                        # a model file, and a material): drawn by the exact
//                                        # trace, no tables needed; or, instead:
//   piece = "pieces/halo.toml"           # a piece as in config/pieces/ (its setting, metal and
//                                        # stones; their files inside the directory too)
//   ring = "parametric"                  # "parametric" (default) | "none" | "rings/x.obj"
//   metal = "white_gold"                 # yellow_gold (default) | white_gold | platinum | silver
//   colour = [0.1, 0.2, 0.7]             # optional: stone colour I_o, linear RGB 0..1
//   absorption_per_mm = [0.3, 0.2, 0.0]  # optional: Beer-Lambert sigma per channel, 1/mm
//                                        # (ring, metal, colour and absorption: not with a
//                                        # piece, whose own file gives them)
//   background = "velvet"                # optional preset names
//   lighting = "shop-window"
//
//   [blake2b]                             # optional, required where trusted keys are listed:
//   "stones/sapphire.gemdb" = "9f86..."  # every other file and its digest, written by gemtables
//                                        # (delivery/catalogue_files.hpp); the last table
//
// Unknown keys are errors. Every error names the file, the line and the key, as the stone
// files do (config/stones/README.md): "catalogue.toml:12: stone.metal: unknown metal 'bronze'".
// Files must lie inside the directory (relative, no ".."), because only the directory is
// copied when the catalogue is installed.

#include <filesystem>
#include <string>
#include <string_view>

#include "catalogue/catalogue.hpp"
#include "delivery/catalogue_files.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

using tables::kManifestName;
using tables::kSignatureName;

// `dir`/catalogue.toml's bytes, read once so that what a signature is checked against is what
// is parsed.
Result<std::string> read_manifest_text(const std::filesystem::path& dir);

// Parses a manifest's text; paths come back absolute under `dir`, nothing is opened yet
// (CatalogueStone::opened and ring_mesh stay empty).
Result<Catalogue> parse_manifest(std::string_view text, const std::filesystem::path& dir);
// read_manifest_text, then parse_manifest.
Result<Catalogue> read_manifest(const std::filesystem::path& dir);

}  // namespace gem::kiosk
