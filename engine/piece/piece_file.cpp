#include "piece/piece_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "import/import_text.hpp"
#include "piece/gltf_piece.hpp"
#include "piece/metal_obj.hpp"
#include "piece/piece_check.hpp"
#include "piece/settings.hpp"
#include "piece/stone_shape.hpp"
#include "scene/stone_file.hpp"
#include "scene/toml_reader.hpp"

namespace gem {

namespace {

using Problem = std::optional<Error>;

constexpr double kPi = 3.14159265358979323846;

// A stone as the file names it: a stone description and the width it is scaled to.
struct StoneChoice {
    std::filesystem::path file;
    double width_mm = 0.0;  // 0: the description's own size
};

class PieceReader {
  public:
    PieceReader(std::string name, std::filesystem::path base)
        : r_(name, base), name_(std::move(name)) {}

    Result<Piece> read(const toml::table& doc) {
        for (auto&& [key, node] : doc) {
            const std::string k(key.str());
            if (k != "piece" && k != "centre" && k != "small" && k != "stone") {
                return *r_.unknown(key, "");
            }
        }
        const toml::table* piece = doc["piece"].as_table();
        if (piece == nullptr) return Error{name_ + ": no [piece] table"};
        if (auto e = read_piece(*piece)) return *e;
        if (setting_ == "free") return read_free(doc);
        return read_setting(doc);
    }

  private:
    Problem read_piece(const toml::table& t) {
        for (auto&& [key, node] : t) {
            const std::string k(key.str());
            const std::string full = "piece." + k;
            lines_["piece." + k] = node.source().begin.line;
            Problem e;
            if (k == "name") {
                e = r_.string(node, full, name_value_);
            } else if (k == "setting") {
                e = r_.string(node, full, setting_);
                if (!e && setting_ != "free" && !parse_setting_kind(setting_)) {
                    e = r_.error(node, full,
                                 "unknown setting '" + setting_ +
                                     "' (solitaire, halo, three-stone, band, free)");
                }
            } else if (k == "metal") {
                std::string text;
                e = r_.string(node, full, text);
                if (!e) {
                    const std::optional<Metal> metal = parse_metal(text);
                    if (!metal) {
                        e = r_.error(node, full,
                                     "unknown metal '" + text + "' (" + kMetalNames + ")");
                    } else {
                        params_.metal = *metal;
                    }
                }
            } else if (k == "roughness") {
                e = r_.number(node, full, params_.roughness);
            } else if (k == "finger_diameter_mm") {
                e = r_.number(node, full, params_.shank.finger_diameter_mm);
            } else if (k == "band_width_mm") {
                e = r_.number(node, full, params_.shank.width_mm);
            } else if (k == "band_thickness_mm") {
                e = r_.number(node, full, params_.shank.thickness_mm);
            } else if (k == "metal_model") {
                std::string text;
                e = r_.string(node, full, text);
                metal_model_ = r_.path(text);
                metal_model_line_ = node.source().begin.line;
            } else {
                e = r_.unknown(key, "piece");
            }
            if (e) return e;
        }
        if (name_value_.empty()) return Error{name_ + ": piece.name: missing"};
        if (setting_.empty()) return Error{name_ + ": piece.setting: missing"};
        return std::nullopt;
    }

    // stone, width_mm and, in a setting's table, the setting's own keys.
    Problem read_stone_table(const toml::table& t, const std::string& table, StoneChoice& choice,
                             std::map<std::string, const toml::node*>* rest) {
        for (auto&& [key, node] : t) {
            const std::string k(key.str());
            const std::string full = table + "." + k;
            lines_[full] = node.source().begin.line;
            Problem e;
            if (k == "stone") {
                std::string text;
                e = r_.string(node, full, text);
                choice.file = r_.path(text);
            } else if (k == "width_mm") {
                e = r_.positive(node, full, choice.width_mm);
            } else if (rest != nullptr) {
                (*rest)[k] = &node;
            } else {
                e = r_.unknown(key, table);
            }
            if (e) return e;
        }
        if (choice.file.empty()) return Error{name_ + ": " + table + ".stone: missing"};
        return std::nullopt;
    }

    // The stone a choice names, at its width.
    Result<Stone> load_sized(const StoneChoice& choice, const std::string& key) const {
        Result<Stone> loaded = load_stone_file(choice.file);
        if (!loaded) return where(key, loaded.error());
        Stone stone = std::move(loaded).value();
        if (choice.width_mm > 0.0) {
            stone = stone_at_width(std::move(stone), choice.width_mm);
        }
        return stone;
    }

    // The piece's kind for a choice: one Stone for every equal choice.
    Result<std::size_t> kind_of(const StoneChoice& choice, const std::string& key, Piece& piece) {
        const auto id = std::make_pair(choice.file.lexically_normal().string(), choice.width_mm);
        if (auto it = kinds_.find(id); it != kinds_.end()) return it->second;
        Result<Stone> stone = load_sized(choice, key);
        if (!stone) return Error{stone.error()};
        piece.kinds.push_back(std::move(stone).value());
        piece.kind_sources.push_back({choice.file, choice.width_mm});
        kinds_[id] = piece.kinds.size() - 1;
        return piece.kinds.size() - 1;
    }

    Result<Piece> read_setting(const toml::table& doc) {
        params_.kind = *parse_setting_kind(setting_);
        std::optional<Stone> stones[2];
        std::vector<KindSource> sources;  // the kinds the setting makes, in its order
        const char* tables[2] = {"centre", "small"};
        for (int i = 0; i < 2; ++i) {
            const toml::table* t = doc[tables[i]].as_table();
            if (t == nullptr) continue;
            StoneChoice choice;
            std::map<std::string, const toml::node*> rest;
            if (auto e = read_stone_table(*t, tables[i], choice, &rest)) return *e;
            for (auto& [k, node] : rest) {
                if (auto e = setting_key(tables[i], k, *node)) return *e;
            }
            Result<Stone> stone = load_sized(choice, std::string(tables[i]) + ".stone");
            if (!stone) return Error{stone.error()};
            stones[i] = std::move(stone).value();
            sources.push_back({choice.file, choice.width_mm});
        }
        if (doc["stone"])
            return Error{name_ + ": [[stone]] is for free pieces (setting = \"free\")"};
        Result<Piece> made = make_setting(params_, name_value_, stones[0], stones[1]);
        if (!made) return setting_error(made.error());
        // The setting's kinds are its centre's and small stones', in that order.
        if (made.value().kinds.size() == sources.size()) made.value().kind_sources = sources;
        return made;
    }

    Problem setting_key(const std::string& table, const std::string& k, const toml::node& node) {
        const std::string full = table + "." + k;
        if (table == "centre") {
            if (k == "claws") return r_.integer(node, full, 2, 12, params_.claws.claws);
            if (k == "claw_width_mm") return r_.number(node, full, params_.claws.width_mm);
            if (k == "claw_tip_height_pct")
                return r_.number(node, full, params_.claws.tip_height_pct);
        } else {
            if (k == "count") return r_.integer(node, full, 0, 1000, params_.row.count);
            if (k == "gap_mm") return r_.number(node, full, params_.row.gap_mm);
            if (k == "bead_pct") return r_.number(node, full, params_.row.bead_pct);
            if (k == "wall_mm") return r_.number(node, full, params_.row.wall_mm);
        }
        return r_.error(node, full, "unknown key");
    }

    // A setting's error starts with the parameter's key: put the file, line and table before it.
    Error setting_error(const std::string& message) const {
        const std::size_t colon = message.find(':');
        if (colon != std::string::npos) {
            const std::string key = message.substr(0, colon);
            for (const char* table : {"piece.", "centre.", "small."}) {
                if (auto it = lines_.find(table + key); it != lines_.end()) {
                    return r_.error_at(it->second, table + key, message.substr(colon + 2));
                }
            }
        }
        return Error{name_ + ": " + message};
    }

    Error where(const std::string& key, const std::string& message) const {
        if (auto it = lines_.find(key); it != lines_.end()) {
            return r_.error_at(it->second, key, message);
        }
        return Error{name_ + ": " + key + ": " + message};
    }

    Result<Piece> read_free(const toml::table& doc) {
        if (doc["centre"] || doc["small"]) {
            return Error{name_ +
                         ": [centre] and [small] are for settings; a free piece lists [[stone]]"};
        }
        if (metal_model_.empty()) return Error{name_ + ": piece.metal_model: missing"};
        Piece piece;
        piece.name = name_value_;
        Result<MetalMesh> metal = load_metal_obj(metal_model_, params_.metal, params_.roughness);
        if (!metal) return r_.error_at(metal_model_line_, "piece.metal_model", metal.error());
        piece.metal = std::move(metal).value();
        const toml::array* list = doc["stone"].as_array();
        if (list == nullptr || list->empty())
            return Error{name_ + ": no [[stone]] in a free piece"};
        for (std::size_t i = 0; i < list->size(); ++i) {
            const toml::table* t = (*list)[i].as_table();
            const std::string table = "stone[" + std::to_string(i + 1) + "]";
            if (t == nullptr) return r_.error((*list)[i], table, "expected a table");
            StoneChoice choice;
            glm::dvec3 position(0.0), rotation(0.0);
            std::string role = i == 0 ? "centre" : "stone " + std::to_string(i + 1);
            std::map<std::string, const toml::node*> rest;
            if (auto e = read_stone_table(*t, table, choice, &rest)) return *e;
            for (auto& [k, node] : rest) {
                Problem e;
                if (k == "position_mm") {
                    e = r_.vec3(*node, table + "." + k, position);
                } else if (k == "rotation_deg") {
                    e = r_.vec3(*node, table + "." + k, rotation);
                } else if (k == "role") {
                    e = r_.string(*node, table + "." + k, role);
                } else {
                    e = r_.error(*node, table + "." + k, "unknown key");
                }
                if (e) return *e;
            }
            auto kind = kind_of(choice, table + ".stone", piece);
            if (!kind) return Error{kind.error()};
            piece.stones.push_back({kind.value(), {rotation_of(rotation), position}, role});
        }
        if (auto ok = check_piece(piece); !ok) return Error{name_ + ": " + ok.error()};
        return piece;
    }

    // Turned about x, then y, then z, by the angles in degrees.
    static glm::dmat3 rotation_of(const glm::dvec3& deg) {
        const glm::dvec3 a = deg * (kPi / 180.0);
        const double cx = std::cos(a.x), sx = std::sin(a.x);
        const double cy = std::cos(a.y), sy = std::sin(a.y);
        const double cz = std::cos(a.z), sz = std::sin(a.z);
        const glm::dmat3 rx(1, 0, 0, 0, cx, sx, 0, -sx, cx);
        const glm::dmat3 ry(cy, 0, -sy, 0, 1, 0, sy, 0, cy);
        const glm::dmat3 rz(cz, sz, 0, -sz, cz, 0, 0, 0, 1);
        return rz * ry * rx;
    }

    Reader r_;
    std::string name_;
    std::string name_value_;
    std::string setting_;
    SettingParams params_;
    std::filesystem::path metal_model_;
    std::size_t metal_model_line_ = 0;
    std::map<std::string, std::size_t> lines_;  // the line of each dotted key read
    std::map<std::pair<std::string, double>, std::size_t> kinds_;
};

}  // namespace

Result<Piece> parse_piece(std::string_view text, const std::string& name,
                          const std::filesystem::path& base) {
    Result<toml::table> parsed = parse_toml(text, name);
    if (!parsed) return Error{parsed.error()};
    const toml::table& doc = parsed.value();
    return PieceReader(name, base).read(doc);
}

Result<Piece> load_piece(const std::filesystem::path& path, std::vector<std::string>* log) {
    std::string extension = path.extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".glb" || extension == ".gltf") return load_gltf_piece(path, log);
    Result<std::string> text = import::read_whole_file(path);
    if (!text) return Error{text.error()};
    return parse_piece(text.value(), path.string(), path.parent_path());
}

}  // namespace gem
