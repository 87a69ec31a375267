#include "piece/gltf_manifest.hpp"

#include <algorithm>
#include <system_error>

#include "import/import_text.hpp"
#include "scene/toml_reader.hpp"

namespace gem {

namespace {

bool any_of_names(const std::string& name, const std::vector<std::string>& names) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

const GltfManifest::Stone* GltfManifest::stone_named(const std::vector<std::string>& names) const {
    for (const Stone& s : stones) {
        if (any_of_names(s.name, names)) return &s;
    }
    return nullptr;
}

bool GltfManifest::metal_named(const std::vector<std::string>& names) const {
    return std::any_of(metal.begin(), metal.end(),
                       [&](const std::string& m) { return any_of_names(m, names); });
}

Result<GltfManifest> parse_gltf_manifest(std::string_view text, const std::string& name) {
    auto parsed = parse_toml(text, name);
    if (!parsed) return Error{parsed.error()};
    const toml::table& doc = parsed.value();
    const Reader r(name, {});
    GltfManifest out;
    out.file = name;
    for (const auto& [key, node] : doc) {
        const std::string table(key.str());
        if (table != "stone" && table != "metal") return *r.unknown(key, "");
        const toml::array* entries = node.as_array();
        if (entries == nullptr || !entries->is_array_of_tables()) {
            return r.error(node, table, "expected [[" + table + "]] tables");
        }
        for (const toml::node& entry : *entries) {
            GltfManifest::Stone stone;
            bool named = false;
            for (const auto& [k, value] : *entry.as_table()) {
                const std::string full = table + "." + std::string(k.str());
                if (k == "name") {
                    if (auto e = r.string(value, full, stone.name)) return *e;
                    if (stone.name.empty()) return r.error(value, full, "must not be empty");
                    named = true;
                } else if (k == "material" && table == "stone") {
                    std::string material;
                    if (auto e = r.string(value, full, material)) return *e;
                    stone.material = find_material(material);
                    if (!stone.material) {
                        return r.error(value, full,
                                       "'" + material + "' is not a built-in material");
                    }
                } else {
                    return *r.unknown(k, table);
                }
            }
            if (!named) return r.error(entry, table + ".name", "missing");
            if (table == "stone") {
                out.stones.push_back(std::move(stone));
            } else {
                out.metal.push_back(stone.name);
            }
        }
    }
    return out;
}

Result<std::optional<GltfManifest>> load_gltf_manifest(const std::filesystem::path& piece_file) {
    std::filesystem::path file = piece_file;
    file += ".toml";
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) return std::optional<GltfManifest>();
    Result<std::string> text = import::read_whole_file(file);
    if (!text) return Error{text.error()};
    auto manifest = parse_gltf_manifest(text.value(), file.string());
    if (!manifest) return Error{manifest.error()};
    return std::optional<GltfManifest>(std::move(manifest).value());
}

}  // namespace gem
