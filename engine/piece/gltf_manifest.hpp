#pragma once
// The manifest a jeweller may put beside a glTF piece (RING.glb → RING.glb.toml) to say which
// parts are stones, and of what, when the file's materials and names do not: it wins over them.
//
//   [[stone]]
//   name = "Body_012"      # a node's, mesh's or material's name, exactly as the file has it
//   material = "ruby"      # optional: a built-in material, over the file's extensions
//
//   [[metal]]
//   name = "Gem seat"      # a part that is metal whatever its material or name says
//
// Every error names the file, the line and the key.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "optics/material.hpp"
#include "util/result.hpp"

namespace gem {

struct GltfManifest {
    struct Stone {
        std::string name;
        std::optional<Material> material;
    };
    std::filesystem::path file;  // for log lines
    std::vector<Stone> stones;
    std::vector<std::string> metal;

    // The entry naming any of these names, if one does.
    const Stone* stone_named(const std::vector<std::string>& names) const;
    bool metal_named(const std::vector<std::string>& names) const;
};

// The manifest beside `piece_file` (its name with ".toml" added), if there is one.
Result<std::optional<GltfManifest>> load_gltf_manifest(const std::filesystem::path& piece_file);
Result<GltfManifest> parse_gltf_manifest(std::string_view text, const std::string& name);

}  // namespace gem
