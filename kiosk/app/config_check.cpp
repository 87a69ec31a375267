#include "app/config_check.hpp"

#include <string>
#include <vector>

#include "catalogue/catalogue_signature.hpp"
#include "settings/config_fallback.hpp"

namespace gem::kiosk {

int check_config(const std::filesystem::path& file, std::ostream& out) {
    const ConfigLoad load = load_config(file);
    std::vector<std::string> problems = load.errors;
    if (load.parsed) {
        const std::vector<KeptKey> keys =
            read_trusted_key_files(load.config.catalogue.trusted_keys, problems);
        std::vector<TrustedKeyText> texts;
        for (const KeptKey& key : keys)
            texts.push_back(TrustedKeyText{key.file.string(), key.text});
        std::vector<std::string> unparsed;
        (void)parse_trust(true, texts, unparsed);
        for (const std::string& why : unparsed) problems.push_back("trusted key left out: " + why);
    }
    for (const std::string& problem : problems) out << problem << "\n";
    if (problems.empty()) {
        out << file.string() << ": no problems\n";
    } else {
        out << file.string() << ": " << problems.size()
            << (problems.size() == 1 ? " problem" : " problems")
            << (load.parsed ? "" : "; the kiosk would set the whole file aside") << "\n";
    }
    return static_cast<int>(problems.size());
}

}  // namespace gem::kiosk
