#include "app/config_check.hpp"

#include <string>
#include <vector>

#include "app/catalogue_setup.hpp"

namespace gem::kiosk {

int check_config(const std::filesystem::path& file, std::ostream& out) {
    const ConfigLoad load = load_config(file);
    std::vector<std::string> problems = load.errors;
    if (load.parsed) {
        const std::vector<KeptKey> keys =
            read_trusted_key_files(load.config.catalogue.trusted_keys, problems);
        (void)trust_of_keys(true, keys, problems);
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
