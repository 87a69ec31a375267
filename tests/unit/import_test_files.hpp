#pragma once
// Files for the import tests: the hand-written fixtures, and scratch copies that a test edits
// to make one fault at a time.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace gem::import_test {

inline std::filesystem::path model(const std::string& name) {
    return std::filesystem::path(GEM_FIXTURES_DIR) / "models" / name;
}

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

inline std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

inline std::filesystem::path write_artifact(const std::string& name, const std::string& text) {
    const auto path = std::filesystem::path(GEM_ARTIFACT_DIR) / "import" / name;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

}  // namespace gem::import_test
