#include "settings/last_good_config.hpp"

#include <sstream>

#include <toml++/toml.h>

#include "import/import_text.hpp"
#include "util/atomic_file.hpp"

namespace gem::kiosk {

namespace fs = std::filesystem;

namespace {

std::string serialise(const KeptConfig& kept) {
    toml::table root{{"source", kept.source.string()}, {"config", kept.text}};
    toml::array keys;
    for (const KeptKey& key : kept.keys) {
        keys.push_back(toml::table{{"file", key.file.string()}, {"text", key.text}});
    }
    root.insert("key", std::move(keys));
    std::ostringstream out;
    out << "# gemkiosk: the last config that parsed and validated, with the keys it trusted.\n"
           "# Written by the kiosk; a config that does not parse falls back to this one.\n"
        << root << "\n";
    return out.str();
}

Result<std::string> string_field(const toml::table& table, std::string_view key,
                                 const std::string& where) {
    if (auto text = table[key].value<std::string>()) return *text;
    return Error{where + ": '" + std::string(key) + "' is missing or not a string"};
}

}  // namespace

Result<bool> keep_last_good_config(const fs::path& state_dir, const KeptConfig& kept) {
    if (auto before = read_last_good_config(state_dir); before && before.value() == kept) {
        return false;
    }
    std::error_code ec;
    fs::create_directories(state_dir, ec);
    const std::string text = serialise(kept);
    auto written = write_file_atomic(state_dir / kLastGoodConfigName, text.data(), text.size());
    if (!written) return Error{written.error()};
    return true;
}

Result<KeptConfig> read_last_good_config(const fs::path& state_dir) {
    const fs::path file = state_dir / kLastGoodConfigName;
    auto bytes = import::read_whole_file(file);
    if (!bytes) return Error{bytes.error()};
    toml::table root;
    try {
        root = toml::parse(bytes.value(), file.string());
    } catch (const toml::parse_error& e) {
        return Error{file.string() + ":" + std::to_string(e.source().begin.line) + ": damaged (" +
                     std::string(e.description()) + ")"};
    }
    KeptConfig kept;
    auto source = string_field(root, "source", file.string());
    auto text = string_field(root, "config", file.string());
    if (!source) return Error{source.error()};
    if (!text) return Error{text.error()};
    kept.source = source.value();
    kept.text = std::move(text).value();
    if (const toml::node* keys = root.get("key")) {
        const toml::array* list = keys->as_array();
        if (list == nullptr) return Error{file.string() + ": 'key' is not a list of tables"};
        for (const toml::node& entry : *list) {
            const toml::table* table = entry.as_table();
            if (table == nullptr) return Error{file.string() + ": 'key' is not a list of tables"};
            auto key_file = string_field(*table, "file", file.string());
            auto key_text = string_field(*table, "text", file.string());
            if (!key_file) return Error{key_file.error()};
            if (!key_text) return Error{key_text.error()};
            kept.keys.push_back(KeptKey{key_file.value(), std::move(key_text).value()});
        }
    }
    return kept;
}

}  // namespace gem::kiosk
