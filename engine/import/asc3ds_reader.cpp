// 3D Studio (DOS) ASCII export, the .asc mesh format: per object a "Named object:" line, a
// "Tri-mesh, Vertices: N Faces: M" line, a vertex list ("Vertex 0:  X:1.0 Y:2.0 Z:3.0") and a
// face list ("Face 0:  A:0 B:1 C:2 AB:1 BC:1 CA:1"). Lights, cameras, smoothing groups,
// materials and page breaks are read past. All mesh objects are merged into one stone.

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <string>

#include "import/import_text.hpp"
#include "import/load_model.hpp"
#include "import/mesh_soup.hpp"

namespace gem {
namespace {

bool is_separator(char c) {
    return std::isspace(static_cast<unsigned char>(c)) || c == ',';
}

// The value written after "key:" (spaces allowed around the colon), where the key starts a
// word; "A:" is not found inside "CA:1".
std::optional<std::string_view> field(std::string_view line, std::string_view key) {
    for (std::size_t at = 0; (at = line.find(key, at)) != std::string_view::npos; ++at) {
        if (at > 0 && !is_separator(line[at - 1]) && line[at - 1] != ':') continue;
        std::size_t i = at + key.size();
        while (i < line.size() && line[i] == ' ') ++i;
        if (i >= line.size() || line[i] != ':') continue;
        ++i;
        while (i < line.size() && line[i] == ' ') ++i;
        const std::size_t start = i;
        while (i < line.size() && !is_separator(line[i])) ++i;
        return line.substr(start, i - start);
    }
    return std::nullopt;
}

struct MeshObject {
    std::string name;
    std::size_t first_vertex = 0;  // where its vertices start in the merged soup
    long long vertex_count = 0;
    long long face_count = 0;
    long long faces_read = 0;
    std::vector<bool> vertex_seen;
    std::size_t declared_on = 0;  // the Tri-mesh line, for messages about missing entries
};

class Asc3dsParser {
  public:
    explicit Asc3dsParser(const std::filesystem::path& path) : path_(path) {}

    Result<Stone> parse(std::string_view text) {
        text_bytes_ = text.size();
        import::LineCursor cursor(text);
        std::string_view line;
        while (cursor.next(line)) {
            line_ = cursor.line_number();
            if (auto problem = parse_line(line)) return *problem;
        }
        if (auto problem = finish_object()) return *problem;
        if (!any_mesh_) return import::file_error(path_, "no Tri-mesh object in the file");
        return import::stone_from_soup(path_, soup_);
    }

  private:
    std::size_t text_bytes_ = 0;
    std::optional<Error> parse_line(std::string_view line) {
        const auto tokens = import::split_tokens(line);
        if (tokens.empty()) return std::nullopt;
        if (import::istarts_with(tokens[0], "Named")) return finish_object();
        if (import::istarts_with(tokens[0], "Tri-mesh")) return start_mesh(line);
        if (import::iequals(tokens[0], "Vertex") && tokens.size() > 1 &&
            !import::istarts_with(tokens[1], "list")) {
            return read_vertex(line, tokens[1]);
        }
        if (import::iequals(tokens[0], "Face") && tokens.size() > 1 &&
            !import::istarts_with(tokens[1], "list")) {
            return read_face(line, tokens[1]);
        }
        return std::nullopt;
    }

    Error error(const std::string& message) const {
        return import::line_error(path_, line_, message);
    }

    std::optional<long long> count_field(std::string_view line, std::string_view key) {
        const auto text = field(line, key);
        return text ? import::parse_integer(*text) : std::nullopt;
    }

    std::optional<Error> start_mesh(std::string_view line) {
        if (auto problem = finish_object()) return problem;
        const auto vertices = count_field(line, "Vertices");
        const auto faces = count_field(line, "Faces");
        if (!vertices || !faces || *vertices < 0 || *faces < 0) {
            return error("Tri-mesh line needs 'Vertices: N' and 'Faces: M'");
        }
        // Every vertex and face takes a line of its own, so counts larger than the file are
        // damage; checking first keeps a corrupt count from allocating gigabytes.
        const auto total = soup_.positions.size() + static_cast<unsigned long long>(*vertices);
        if (static_cast<unsigned long long>(*vertices) > text_bytes_ ||
            static_cast<unsigned long long>(*faces) > text_bytes_ || total > UINT32_MAX) {
            return error("Tri-mesh counts (" + std::to_string(*vertices) + " vertices, " +
                         std::to_string(*faces) + " faces) do not fit in the file");
        }
        object_ = MeshObject{};
        object_->first_vertex = soup_.positions.size();
        object_->vertex_count = *vertices;
        object_->face_count = *faces;
        object_->vertex_seen.assign(std::size_t(*vertices), false);
        object_->declared_on = line_;
        soup_.positions.resize(soup_.positions.size() + std::size_t(*vertices), glm::dvec3(0.0));
        any_mesh_ = true;
        return std::nullopt;
    }

    // "3:", "3" or "3:X:1.0": the entry's number within its object.
    std::optional<long long> entry_number(std::string_view token) const {
        return import::parse_integer(token.substr(0, token.find(':')));
    }

    std::optional<Error> read_vertex(std::string_view line, std::string_view number) {
        if (!object_) return error("vertex outside a Tri-mesh object");
        const auto i = entry_number(number);
        if (!i || *i < 0 || *i >= object_->vertex_count) {
            return error("vertex number '" + std::string(number) + "' out of range (" +
                         std::to_string(object_->vertex_count) + " vertices)");
        }
        if (object_->vertex_seen[std::size_t(*i)]) {
            return error("vertex " + std::to_string(*i) + " given twice");
        }
        glm::dvec3 p{0.0};
        const char* keys[3] = {"X", "Y", "Z"};
        for (int c = 0; c < 3; ++c) {
            const auto text = field(line, keys[c]);
            if (!text) return error(std::string("vertex has no ") + keys[c] + ": coordinate");
            const auto value = import::parse_number(*text);
            if (!value) {
                return error(std::string(keys[c]) + " coordinate '" + std::string(*text) +
                             "' is not a number");
            }
            p[c] = *value;
        }
        object_->vertex_seen[std::size_t(*i)] = true;
        soup_.positions[object_->first_vertex + std::size_t(*i)] = p;
        return std::nullopt;
    }

    std::optional<Error> read_face(std::string_view line, std::string_view number) {
        if (!object_) return error("face outside a Tri-mesh object");
        const auto i = entry_number(number);
        if (!i || *i < 0 || *i >= object_->face_count) {
            return error("face number '" + std::string(number) + "' out of range (" +
                         std::to_string(object_->face_count) + " faces)");
        }
        std::array<std::uint32_t, 3> t{};
        const char* keys[3] = {"A", "B", "C"};
        for (int c = 0; c < 3; ++c) {
            const auto text = field(line, keys[c]);
            if (!text) return error(std::string("face has no ") + keys[c] + ": vertex");
            const auto index = import::parse_integer(*text);
            if (!index) {
                return error(std::string("face vertex ") + keys[c] + " '" + std::string(*text) +
                             "' is not an index");
            }
            if (*index < 0 || *index >= object_->vertex_count) {
                return error("face index " + std::to_string(*index) + " out of range (" +
                             std::to_string(object_->vertex_count) + " vertices)");
            }
            t[std::size_t(c)] =
                static_cast<std::uint32_t>(object_->first_vertex + std::size_t(*index));
        }
        soup_.triangles.push_back(t);
        ++object_->faces_read;
        return std::nullopt;
    }

    std::optional<Error> finish_object() {
        if (!object_) return std::nullopt;
        const MeshObject& o = *object_;
        const auto missing = std::count(o.vertex_seen.begin(), o.vertex_seen.end(), false);
        std::optional<Error> problem;
        if (missing > 0) {
            problem =
                import::line_error(path_, o.declared_on,
                                   "Tri-mesh declares " + std::to_string(o.vertex_count) +
                                       " vertices but " + std::to_string(missing) + " are missing");
        } else if (o.faces_read != o.face_count) {
            problem =
                import::line_error(path_, o.declared_on,
                                   "Tri-mesh declares " + std::to_string(o.face_count) +
                                       " faces but " + std::to_string(o.faces_read) + " are given");
        }
        object_.reset();
        return problem;
    }

    std::filesystem::path path_;
    std::size_t line_ = 0;
    import::TriangleSoup soup_;
    std::optional<MeshObject> object_;
    bool any_mesh_ = false;
};

}  // namespace

Result<Stone> load_3ds_ascii(const std::filesystem::path& path) {
    auto bytes = import::read_whole_file(path);
    if (!bytes) return Error{bytes.error()};
    return parse_3ds_ascii(bytes.value(), path);
}

Result<Stone> parse_3ds_ascii(std::string_view text, const std::filesystem::path& path) {
    if (text.empty()) return import::file_error(path, "empty file");
    return Asc3dsParser(path).parse(text);
}

}  // namespace gem
