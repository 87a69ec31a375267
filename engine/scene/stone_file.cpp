#include "scene/stone_file.hpp"

#include <fstream>
#include <sstream>

#include <toml++/toml.h>

#include "scene/scene.hpp"
#include "scene/scene_build.hpp"
#include "scene/toml_reader.hpp"

namespace gem {

namespace {

// A stone file is a scene file cut down to what a database depends on: the camera, lights
// and environment are chosen at shading time, so a stone file that sets them is a mistake.
Result<bool> check_tables(const std::string& text, const std::string& name) {
    Result<toml::table> parsed = parse_toml(text, name);
    if (!parsed) return Error{parsed.error()};
    const toml::table& doc = parsed.value();
    for (auto&& [key, node] : doc) {
        if (key.str() == "stone" || key.str() == "material") continue;
        return Error{name + ":" + std::to_string(key.source().begin.line) + ": " +
                     std::string(key.str()) +
                     ": unknown key (a stone file holds only [stone] and [material])"};
    }
    return true;
}

}  // namespace

Result<Stone> load_stone_file(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        return Error{"cannot read " + name + ": no such file"};
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error{"cannot read " + name + ": cannot open the file"};
    std::ostringstream text;
    text << in.rdbuf();
    if (auto ok = check_tables(text.str(), name); !ok) return Error{ok.error()};
    Result<Scene> scene = parse_scene(text.str(), name, path.parent_path());
    if (!scene) return Error{scene.error()};
    Result<Stone> stone = build_stone(scene.value());
    if (!stone) return Error{name + ": " + stone.error()};
    return stone;
}

}  // namespace gem
