// Loading the kiosk's config file: the top-level keys, and dispatch to the tables
// (option_sections.cpp, preset_sections.cpp).
#include "settings/kiosk_config.hpp"

#include "import/import_text.hpp"
#include "settings/config_sections.hpp"

namespace gem::kiosk {

namespace {

constexpr KeySpec<KioskConfig> kTopKeys[] = {
    {"log_level",
     [](ConfigReader& r, const toml::node& n, std::string_view k, KioskConfig& c) {
         std::size_t i = 0;
         if (!r.choice(n, k, {"error", "warning", "notice", "info", "debug"}, i)) return;
         constexpr LogLevel levels[] = {LogLevel::error, LogLevel::warning, LogLevel::notice,
                                        LogLevel::info, LogLevel::debug};
         c.log_level = levels[i];
     }},
    {"crossfade_s", [](ConfigReader& r, const toml::node& n, std::string_view k,
                       KioskConfig& c) { r.number(n, k, 0.0, 10.0, c.crossfade_s); }},
};

const SectionSpec* find_section(std::string_view name) {
    for (std::span<const SectionSpec> sections : {option_sections(), preset_sections()}) {
        for (const SectionSpec& s : sections) {
            if (s.name == name) return &s;
        }
    }
    return nullptr;
}

void read_top(ConfigReader& r, const toml::table& root, KioskConfig& config) {
    for (auto&& [key, value] : root) {
        if (const SectionSpec* section = find_section(key.str())) {
            section->read(r, value, config);
            continue;
        }
        const KeySpec<KioskConfig>* spec = nullptr;
        for (const KeySpec<KioskConfig>& s : kTopKeys) {
            if (s.name == key.str()) spec = &s;
        }
        if (spec == nullptr) {
            r.error(key.source().begin.line, key.str(), "unknown key");
            continue;
        }
        spec->read(r, value, key.str(), config);
    }
}

}  // namespace

const char* to_string(DesignTablesMode mode) {
    switch (mode) {
        case DesignTablesMode::automatic:
            return "auto";
        case DesignTablesMode::always:
            return "always";
        case DesignTablesMode::never:
            return "never";
    }
    return "?";
}

ConfigLoad parse_config(std::string_view text, std::string_view name,
                        const std::filesystem::path& base_dir) {
    ConfigLoad load;
    toml::table root;
    try {
        root = toml::parse(text, name);
    } catch (const toml::parse_error& e) {
        // One syntax error makes the rest of the file's meaning uncertain, so none of it is used.
        const toml::source_position at = e.source().begin;
        load.errors.push_back(std::string(name) + ":" + std::to_string(at.line) + ":" +
                              std::to_string(at.column) + ": " + std::string(e.description()));
        load.parsed = false;
        return load;
    }
    ConfigReader reader{std::string(name), base_dir};
    read_top(reader, root, load.config);
    load.errors = reader.take_errors();
    return load;
}

ConfigLoad load_config(const std::filesystem::path& file) {
    auto text = import::read_whole_file(file);
    if (!text) {
        ConfigLoad load;
        load.errors.push_back(text.error());
        load.parsed = false;
        return load;
    }
    return parse_config(text.value(), file.string(), file.parent_path());
}

std::vector<std::string> known_config_keys() {
    std::vector<std::string> keys;
    for (const KeySpec<KioskConfig>& s : kTopKeys) keys.emplace_back(s.name);
    for (std::span<const SectionSpec> sections : {option_sections(), preset_sections()}) {
        for (const SectionSpec& s : sections) s.list_keys(keys);
    }
    return keys;
}

}  // namespace gem::kiosk
