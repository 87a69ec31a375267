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
// Unknown keys are errors. Every error names the file, the line and the key, as the stone
// files do (config/stones/README.md): "catalogue.toml:12: stone.metal: unknown metal 'bronze'".
// Files must lie inside the directory (relative, no ".."), because only the directory is
// copied when the catalogue is installed.

#include <filesystem>

#include "catalogue/catalogue.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

inline constexpr const char* kManifestName = "catalogue.toml";

// Parses `dir`/catalogue.toml; paths come back absolute, nothing is opened yet
// (CatalogueStone::opened and ring_mesh stay empty).
Result<Catalogue> read_manifest(const std::filesystem::path& dir);

}  // namespace gem::kiosk
