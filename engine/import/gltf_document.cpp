// The glTF library is Debian's tinygltf 2.7 (libtinygltf-dev): the one packaged reader of glTF
// 2.0 that handles .glb and .gltf with external buffers and keeps every extension as a value
// (cgltf and fastgltf read the gem extensions typed, but Debian 12 packages neither). Its
// implementation is compiled into this file rather than linked from Debian's libtinygltf2d, so
// that images are never decoded (a piece shades by its material factors; textures are counted
// and ignored). Writing is gltf_write.cpp; the compressed meshes' codecs gltf_compression.cpp.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
// The library's implementation is compiled once, above; gltf_values.hpp includes its
// declarations again.
#undef TINYGLTF_IMPLEMENTATION

#include "import/gltf_document.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "import/gltf_compression.hpp"
#include "import/gltf_values.hpp"
#include "import/import_text.hpp"

namespace gem::import {

namespace {

// Extensions a file may require that this reader honours: Draco's and meshopt's compression,
// GPU instancing, the gem materials (read), the quantised positions (decoded below), and ones
// whose absence changes only textures or highlights (ignored).
const std::set<std::string> kReadable = {
    "KHR_draco_mesh_compression", "EXT_meshopt_compression",
    "EXT_mesh_gpu_instancing",    "KHR_materials_ior",
    "KHR_materials_transmission", "KHR_materials_volume",
    "KHR_materials_dispersion",   "KHR_mesh_quantization",
    "KHR_materials_specular",     "KHR_materials_emissive_strength",
    "KHR_texture_transform"};

// The JSON of a .glb (its first chunk) or of a .gltf, for a look at what the file requires
// before the library reads it: a file compressed with Draco would fail inside the library with
// a message about byte lengths, not about the extension it lacks.
Result<std::string_view> json_of(std::string_view bytes) {
    if (bytes.size() < 4 || bytes.substr(0, 4) != "glTF") return bytes;
    if (bytes.size() < 20) return Error{"a .glb shorter than its header (truncated)"};
    std::uint32_t header[5];
    std::memcpy(header, bytes.data(), sizeof header);
    const std::uint32_t json_length = header[3];
    if (header[1] != 2) return Error{"a .glb of version " + std::to_string(header[1]) + ", not 2"};
    if (header[4] != 0x4E4F534Au) return Error{"a .glb whose first chunk is not its JSON"};
    if (json_length > bytes.size() - 20)
        return Error{"a .glb cut short inside its JSON (truncated)"};
    return bytes.substr(20, json_length);
}

// The file's JSON checked before the library reads it: every extension it requires is one
// read here. Returned changed where the library would refuse what the compression extensions
// allow: EXT_meshopt_compression's fallback buffers (no data) are given one byte each, since
// the library would look for them in the .glb's binary chunk or a file (nothing reads them);
// Draco primitives lose their indices accessor (below).
Result<std::optional<std::string>> check_json(std::string_view json) {
    nlohmann::json doc = nlohmann::json::parse(json.begin(), json.end(), nullptr, false);
    if (doc.is_discarded() || !doc.is_object()) return Error{"not glTF: its JSON does not parse"};
    if (const auto required = doc.find("extensionsRequired"); required != doc.end()) {
        if (!required->is_array()) return Error{"extensionsRequired is not a list"};
        for (const nlohmann::json& name : *required) {
            if (!name.is_string()) return Error{"extensionsRequired holds a non-string"};
            const std::string n = name.get<std::string>();
            if (kReadable.contains(n)) continue;
            return Error{"it requires the extension " + n + ", which this reader does not know"};
        }
    }
    bool changed = false;
    if (const auto buffers = doc.find("buffers"); buffers != doc.end() && buffers->is_array()) {
        for (nlohmann::json& buffer : *buffers) {
            if (!buffer.is_object() || buffer.contains("uri")) continue;
            const nlohmann::json* ext = nullptr;
            if (auto e = buffer.find("extensions"); e != buffer.end() && e->is_object()) {
                if (auto m = e->find("EXT_meshopt_compression"); m != e->end()) ext = &*m;
            }
            if (ext == nullptr || !ext->is_object() || ext->value("fallback", false) != true) {
                continue;
            }
            buffer["uri"] = "data:application/octet-stream;base64,AA==";
            buffer["byteLength"] = 1;
            changed = true;
        }
    }
    // A Draco primitive's indices accessor has no buffer view (its faces are in the Draco
    // data), which the library refuses: the faces are read from Draco, so it is dropped.
    if (const auto meshes = doc.find("meshes"); meshes != doc.end() && meshes->is_array()) {
        for (nlohmann::json& mesh : *meshes) {
            if (!mesh.is_object() || !mesh.contains("primitives") ||
                !mesh["primitives"].is_array()) {
                continue;
            }
            for (nlohmann::json& primitive : mesh["primitives"]) {
                if (!primitive.is_object()) continue;
                const auto ext = primitive.find("extensions");
                if (ext == primitive.end() || !ext->is_object() ||
                    !ext->contains("KHR_draco_mesh_compression")) {
                    continue;
                }
                changed = primitive.erase("indices") > 0 || changed;
            }
        }
    }
    if (!changed) return std::optional<std::string>();
    return std::optional<std::string>(doc.dump());
}

// A .glb with its JSON chunk replaced by `json` (padded with spaces, as the format asks) and
// its other chunks as they were.
std::string glb_with_json(std::string_view glb, const std::string& json) {
    std::uint32_t old_length = 0;
    std::memcpy(&old_length, glb.data() + 12, 4);
    const std::string_view rest = glb.substr(20 + std::size_t(old_length));
    std::string padded = json;
    padded.resize((padded.size() + 3) / 4 * 4, ' ');
    std::string out;
    const auto put = [&](std::uint32_t x) { out.append(reinterpret_cast<const char*>(&x), 4); };
    put(0x46546C67u);  // "glTF"
    put(2);
    put(static_cast<std::uint32_t>(12 + 8 + padded.size() + rest.size()));
    put(static_cast<std::uint32_t>(padded.size()));
    put(0x4E4F534Au);  // "JSON"
    out += padded;
    out += rest;
    return out;
}

// Images are not decoded: they are counted, and a piece is shaded by its material factors.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void* counter) {
    ++*static_cast<std::size_t*>(counter);
    return true;
}

// EXT_meshopt_compression: each compressed buffer view decoded (gltf_compression.hpp) into a
// buffer of its own, which the view then reads plainly.
Result<bool> decode_meshopt(tinygltf::Model& model) {
    for (std::size_t i = 0; i < model.bufferViews.size(); ++i) {
        tinygltf::BufferView& view = model.bufferViews[i];
        const auto ext = view.extensions.find("EXT_meshopt_compression");
        if (ext == view.extensions.end()) continue;
        const tinygltf::Value& e = ext->second;
        const std::string what = "buffer view " + std::to_string(i) + " (meshopt)";
        const double buffer = number(e, "buffer", -1.0), offset = number(e, "byteOffset", 0.0),
                     length = number(e, "byteLength", -1.0), stride = number(e, "byteStride", 0.0),
                     count = number(e, "count", -1.0);
        const std::string mode = text(e, "mode", ""), filter = text(e, "filter", "NONE");
        if (!(buffer >= 0.0 && buffer < double(model.buffers.size()))) {
            return Error{what + ": its buffer does not exist"};
        }
        const std::vector<unsigned char>& source = model.buffers[std::size_t(buffer)].data;
        if (!(offset >= 0.0 && length >= 0.0 && offset + length <= double(source.size()))) {
            return Error{what + ": reaches outside its buffer"};
        }
        if (!(count >= 0.0 && count <= 4294967295.0 && stride >= 0.0 && stride <= 4294967295.0)) {
            return Error{what + ": a count or stride out of range"};  // before the casts below
        }
        auto out = decode_meshopt_view(source.data() + std::size_t(offset), std::size_t(length),
                                       std::size_t(count), std::size_t(stride), mode, filter);
        if (!out) return Error{what + ": " + out.error()};
        tinygltf::Buffer decoded;
        decoded.data = std::move(out).value();
        model.buffers.push_back(std::move(decoded));
        view.buffer = static_cast<int>(model.buffers.size()) - 1;
        view.byteOffset = 0;
        view.byteLength = model.buffers.back().data.size();
    }
    return true;
}

// An accessor's elements as doubles, `components` each; integers are decoded as the glTF
// specification says for normalised ones (KHR_mesh_quantization), as they are otherwise.
Result<std::vector<double>> read_accessor(const tinygltf::Model& model, int index, int components,
                                          const std::string& what) {
    if (index < 0 || index >= static_cast<int>(model.accessors.size())) {
        return Error{what + ": accessor " + std::to_string(index) + " does not exist"};
    }
    const tinygltf::Accessor& a = model.accessors[index];
    if (a.sparse.isSparse) return Error{what + ": sparse accessors are not read"};
    if (tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type)) != components) {
        return Error{what + ": accessor " + std::to_string(index) + " has the wrong shape"};
    }
    const int size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    if (size <= 0) return Error{what + ": accessor " + std::to_string(index) + " has no type"};
    if (a.bufferView < 0 || a.bufferView >= static_cast<int>(model.bufferViews.size())) {
        return Error{what + ": accessor " + std::to_string(index) + " has no buffer view"};
    }
    const tinygltf::BufferView& view = model.bufferViews[a.bufferView];
    if (view.buffer < 0 || view.buffer >= static_cast<int>(model.buffers.size())) {
        return Error{what + ": buffer view " + std::to_string(a.bufferView) + " has no buffer"};
    }
    const std::vector<unsigned char>& data = model.buffers[view.buffer].data;
    const int stride = a.ByteStride(view);
    const std::size_t element = static_cast<std::size_t>(components) * size;
    const std::size_t view_end = view.byteOffset + view.byteLength;
    const std::size_t start = view.byteOffset + a.byteOffset;
    const auto outside = [&] {
        return Error{what + ": accessor " + std::to_string(index) + " reaches outside its buffer"};
    };
    if (stride <= 0 || view_end > data.size() || view_end < view.byteOffset) return outside();
    if (a.count > 0) {
        if (start > view_end ||
            a.count - 1 > (view_end - start) / static_cast<std::size_t>(stride)) {
            return outside();
        }
        if (start + (a.count - 1) * stride + element > view_end) return outside();
    }
    std::vector<double> out(a.count * components);
    for (std::size_t i = 0; i < a.count; ++i) {
        const unsigned char* p = data.data() + start + i * stride;
        for (int c = 0; c < components; ++c, p += size) {
            double v = 0.0;
            switch (a.componentType) {
                case TINYGLTF_COMPONENT_TYPE_FLOAT: {
                    float f;
                    std::memcpy(&f, p, 4);
                    v = f;
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_BYTE: {
                    std::int8_t x;
                    std::memcpy(&x, p, 1);
                    v = a.normalized ? std::max(x / 127.0, -1.0) : x;
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                    v = a.normalized ? *p / 255.0 : *p;
                    break;
                case TINYGLTF_COMPONENT_TYPE_SHORT: {
                    std::int16_t x;
                    std::memcpy(&x, p, 2);
                    v = a.normalized ? std::max(x / 32767.0, -1.0) : x;
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                    std::uint16_t x;
                    std::memcpy(&x, p, 2);
                    v = a.normalized ? x / 65535.0 : x;
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
                    std::uint32_t x;
                    std::memcpy(&x, p, 4);
                    v = x;
                    break;
                }
                default:
                    return Error{what + ": accessor " + std::to_string(index) +
                                 " has a component type this reader does not read"};
            }
            out[i * components + c] = v;
        }
    }
    return out;
}

glm::dmat4 local_transform(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        glm::dmat4 m;
        for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = node.matrix[i];  // column-major
        return m;
    }
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3) {
        m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
    }
    if (node.rotation.size() == 4) {
        const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        m = m * glm::dmat4(glm::mat3_cast(glm::normalize(q)));
    }
    if (node.scale.size() == 3) {
        m = m *
            glm::dmat4(glm::dmat3(glm::dvec3(node.scale[0], 0, 0), glm::dvec3(0, node.scale[1], 0),
                                  glm::dvec3(0, 0, node.scale[2])));
    }
    return m;
}

std::string node_name(const tinygltf::Model& model, int index) {
    const std::string& name = model.nodes[index].name;
    return "node " + std::to_string(index) + (name.empty() ? "" : " '" + name + "'");
}

// EXT_mesh_gpu_instancing: the node's mesh drawn once per instance, each placed by its
// translation, rotation and scale (in that order: T R S, within the node's frame). Nothing
// when the node has no instances.
Result<std::optional<std::vector<glm::dmat4>>> instances_of(const tinygltf::Model& model,
                                                            int node_index) {
    const tinygltf::Node& node = model.nodes[node_index];
    const auto ext = node.extensions.find("EXT_mesh_gpu_instancing");
    if (ext == node.extensions.end()) return std::optional<std::vector<glm::dmat4>>();
    const std::string what = node_name(model, node_index) + " (EXT_mesh_gpu_instancing)";
    const tinygltf::Value& attributes = ext->second.Get("attributes");
    if (!attributes.IsObject()) return Error{what + ": no attributes"};
    struct Attribute {
        const char* name;
        int components;
        std::vector<double> values;
    };
    Attribute read[] = {{"TRANSLATION", 3, {}}, {"ROTATION", 4, {}}, {"SCALE", 3, {}}};
    std::size_t count = 0;
    bool any = false;
    for (Attribute& a : read) {
        if (!attributes.Has(a.name)) continue;
        const tinygltf::Value& index = attributes.Get(a.name);
        if (!index.IsNumber()) return Error{what + ": " + a.name + " is not an accessor"};
        auto values = read_accessor(model, static_cast<int>(index.GetNumberAsDouble()),
                                    a.components, what + " " + a.name);
        if (!values) return Error{values.error()};
        const std::size_t n = values.value().size() / static_cast<std::size_t>(a.components);
        if (any && n != count) return Error{what + ": its attributes differ in count"};
        count = n;
        any = true;
        a.values = std::move(values).value();
    }
    if (!any) return Error{what + ": no TRANSLATION, ROTATION or SCALE"};
    std::vector<glm::dmat4> out(count, glm::dmat4(1.0));
    for (std::size_t i = 0; i < count; ++i) {
        glm::dmat4 m(1.0);
        if (!read[0].values.empty()) {
            m[3] = glm::dvec4(read[0].values[3 * i], read[0].values[3 * i + 1],
                              read[0].values[3 * i + 2], 1.0);
        }
        if (!read[1].values.empty()) {
            const double* q = &read[1].values[4 * i];
            const glm::dquat r(q[3], q[0], q[1], q[2]);
            if (!(glm::length(r) > 0.0)) return Error{what + ": a rotation of no length"};
            m = m * glm::dmat4(glm::mat3_cast(glm::normalize(r)));
        }
        if (!read[2].values.empty()) {
            const double* k = &read[2].values[3 * i];
            m = m * glm::dmat4(glm::dmat3(glm::dvec3(k[0], 0, 0), glm::dvec3(0, k[1], 0),
                                          glm::dvec3(0, 0, k[2])));
        }
        for (int c = 0; c < 4; ++c) {
            if (!all_finite(glm::dvec3(m[c])))
                return Error{what + ": a transform that is not a number"};
        }
        out[i] = m;
    }
    return std::optional<std::vector<glm::dmat4>>(std::move(out));
}

// KHR_draco_mesh_compression: the primitive's positions and triangles decoded from its buffer
// view (gltf_compression.hpp), with the grid its positions were quantised to. The file's
// normals are not read from Draco: a metal part averages its own.
Result<bool> decode_draco(const tinygltf::Model& model, const tinygltf::Value& ext,
                          const std::string& what, GltfPart& part) {
    const double view_index = number(ext, "bufferView", -1.0);
    if (!(view_index >= 0.0 && view_index < double(model.bufferViews.size()))) {
        return Error{what + " (Draco): its buffer view does not exist"};
    }
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(view_index)];
    if (view.buffer < 0 || view.buffer >= static_cast<int>(model.buffers.size())) {
        return Error{what + " (Draco): its buffer does not exist"};
    }
    const std::vector<unsigned char>& data = model.buffers[std::size_t(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
        return Error{what + " (Draco): reaches outside its buffer"};
    }
    const double position_id = number(ext.Get("attributes"), "POSITION", -1.0);
    if (!(position_id >= 0.0)) return Error{what + " (Draco): no POSITION"};
    auto mesh = decode_draco_mesh(data.data() + view.byteOffset, view.byteLength,
                                  static_cast<std::uint32_t>(position_id));
    if (!mesh) return Error{what + " (Draco): " + mesh.error()};
    part.positions = std::move(mesh.value().positions);
    part.triangles = std::move(mesh.value().triangles);
    part.position_step = mesh.value().position_step;
    for (const glm::dvec3& p : part.positions) {
        if (!all_finite(p)) return Error{what + " (Draco): a position that is not a number"};
    }
    return true;
}

Result<GltfPart> part_of(const tinygltf::Model& model, int node, int primitive,
                         const glm::dmat4& to_scene) {
    const tinygltf::Mesh& mesh = model.meshes[model.nodes[node].mesh];
    const tinygltf::Primitive& p = mesh.primitives[primitive];
    const std::string what = node_name(model, node) + ", mesh '" + mesh.name + "' primitive " +
                             std::to_string(primitive);
    if (p.material >= static_cast<int>(model.materials.size())) {
        return Error{what + ": material " + std::to_string(p.material) + " does not exist"};
    }
    GltfPart part;
    part.node = model.nodes[node].name;
    part.mesh = mesh.name;
    part.mesh_index = model.nodes[node].mesh;
    part.primitive = primitive;
    part.material = p.material;
    part.to_scene = to_scene;
    if (const auto draco = p.extensions.find("KHR_draco_mesh_compression");
        draco != p.extensions.end()) {
        if (auto ok = decode_draco(model, draco->second, what, part); !ok) return Error{ok.error()};
        return part;
    }
    const auto position = p.attributes.find("POSITION");
    if (position == p.attributes.end()) return Error{what + ": no POSITION"};
    auto xyz = read_accessor(model, position->second, 3, what + " positions");
    if (!xyz) return Error{xyz.error()};
    const tinygltf::Accessor& stored = model.accessors[position->second];
    if (stored.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
        // Quantised positions (KHR_mesh_quantization): one step of the integer, decoded.
        const int bits =
            8 * tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(stored.componentType));
        const bool is_signed = stored.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
                               stored.componentType == TINYGLTF_COMPONENT_TYPE_SHORT;
        part.position_step =
            stored.normalized ? 1.0 / (std::ldexp(1.0, bits - (is_signed ? 1 : 0)) - 1.0) : 1.0;
    }
    const std::vector<double>& v = xyz.value();
    part.positions.resize(v.size() / 3);
    for (std::size_t i = 0; i < part.positions.size(); ++i) {
        part.positions[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
        if (!all_finite(part.positions[i]))
            return Error{what + ": a position that is not a number"};
    }
    if (const auto normal = p.attributes.find("NORMAL"); normal != p.attributes.end()) {
        auto n = read_accessor(model, normal->second, 3, what + " normals");
        if (!n) return Error{n.error()};
        if (n.value().size() != v.size())
            return Error{what + ": normals and positions differ in count"};
        part.normals.resize(part.positions.size());
        for (std::size_t i = 0; i < part.normals.size(); ++i) {
            part.normals[i] = {n.value()[3 * i], n.value()[3 * i + 1], n.value()[3 * i + 2]};
            if (!all_finite(part.normals[i]))
                return Error{what + ": a normal that is not a number"};
        }
    }
    std::vector<double> indices;
    if (p.indices >= 0) {
        auto read = read_accessor(model, p.indices, 1, what + " indices");
        if (!read) return Error{read.error()};
        indices = std::move(read).value();
    } else {
        for (std::size_t i = 0; i < part.positions.size(); ++i) indices.push_back(double(i));
    }
    if (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP || p.mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        // As triangles, each wound as the strip's or fan's first (glTF 2.0, 3.7.2.1).
        std::vector<double> list;
        for (std::size_t i = 2; i < indices.size(); ++i) {
            if (p.mode == TINYGLTF_MODE_TRIANGLE_FAN) {
                list.insert(list.end(), {indices[0], indices[i - 1], indices[i]});
            } else if (i % 2 == 0) {
                list.insert(list.end(), {indices[i - 2], indices[i - 1], indices[i]});
            } else {
                list.insert(list.end(), {indices[i - 1], indices[i - 2], indices[i]});
            }
        }
        indices = std::move(list);
    } else if (indices.size() % 3 != 0) {
        // A list cut short: the whole triangles are kept.
        indices.resize(indices.size() / 3 * 3);
    }
    part.triangles.resize(indices.size() / 3);
    for (std::size_t t = 0; t < part.triangles.size(); ++t) {
        for (int c = 0; c < 3; ++c) {
            const double i = indices[3 * t + c];
            if (!(i >= 0.0 && i < static_cast<double>(part.positions.size()))) {
                return Error{what + ": an index past its positions"};
            }
            part.triangles[t][c] = static_cast<std::uint32_t>(i);
        }
    }
    return part;
}

}  // namespace

std::optional<std::pair<glm::dmat3, double>> rotation_and_scale(const glm::dmat4& m) {
    const glm::dmat3 a(m);
    const double det = glm::determinant(a);
    if (!(det > 0.0)) return std::nullopt;
    const double s = std::cbrt(det);
    const glm::dmat3 r = a / s;
    const glm::dmat3 e = glm::transpose(r) * r - glm::dmat3(1.0);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            if (std::abs(e[i][j]) > 1e-6) return std::nullopt;
        }
    }
    return std::make_pair(r, s);
}

Result<GltfDocument> read_gltf(const std::filesystem::path& path) {
    Result<std::string> bytes = read_whole_file(path);
    if (!bytes) return Error{bytes.error()};
    return parse_gltf(bytes.value(), path.string(), path.parent_path());
}

Result<GltfDocument> parse_gltf(std::string_view data, const std::string& name,
                                const std::filesystem::path& base_dir) {
    const auto fail = [&](const std::string& why) { return Error{name + ": " + why}; };
    if (data.size() > std::numeric_limits<unsigned int>::max()) return fail("larger than 4 GB");
    auto json = json_of(data);
    if (!json) return fail(json.error());
    auto checked = check_json(json.value());
    if (!checked) return fail(checked.error());
    const bool binary = data.size() >= 4 && data.compare(0, 4, "glTF") == 0;
    std::string rewritten;
    if (checked.value()) {
        rewritten = binary ? glb_with_json(data, *checked.value()) : *checked.value();
        data = rewritten;
    }

    GltfDocument doc;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skip_image, &doc.images_ignored);
    tinygltf::Model model;
    std::string error, warning;
    const std::string base = base_dir.string();
    const bool ok =
        binary ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                             reinterpret_cast<const unsigned char*>(data.data()),
                                             static_cast<unsigned int>(data.size()), base)
               : loader.LoadASCIIFromString(&model, &error, &warning, data.data(),
                                            static_cast<unsigned int>(data.size()), base);
    if (!ok) {
        while (!error.empty() && (error.back() == '\n' || error.back() == ' ')) error.pop_back();
        return fail("not read as glTF: " +
                    (error.empty() ? std::string("no reason given") : error));
    }
    if (auto decoded = decode_meshopt(model); !decoded) return fail(decoded.error());
    for (const tinygltf::Material& m : model.materials) doc.materials.push_back(material_of(m));

    // The scene's node trees, each node's transform composed from its root; a node met again
    // on its own path is a cycle, and a node met twice has two parents: both are refused.
    const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (model.scenes.empty() || scene >= static_cast<int>(model.scenes.size())) {
        return fail("no scene to show");
    }
    std::vector<int> visits(model.nodes.size(), 0);
    struct Step {
        int node;
        glm::dmat4 parent;
    };
    std::vector<Step> stack;
    // In the file's order: roots and children pushed last first.
    const std::vector<int>& roots = model.scenes[scene].nodes;
    for (auto r = roots.rbegin(); r != roots.rend(); ++r) stack.push_back({*r, glm::dmat4(1.0)});
    while (!stack.empty()) {
        const Step step = stack.back();
        stack.pop_back();
        if (step.node < 0 || step.node >= static_cast<int>(model.nodes.size())) {
            return fail("node " + std::to_string(step.node) + " does not exist");
        }
        if (++visits[step.node] > 1) {
            return fail(node_name(model, step.node) +
                        " is reached twice (a cycle, or two parents) in the node tree");
        }
        const tinygltf::Node& node = model.nodes[step.node];
        const glm::dmat4 to_scene = step.parent * local_transform(node);
        for (int c = 0; c < 4; ++c) {
            if (!all_finite(glm::dvec3(to_scene[c])) || !std::isfinite(to_scene[c].w)) {
                return fail(node_name(model, step.node) + ": a transform that is not a number");
            }
        }
        if (node.mesh >= static_cast<int>(model.meshes.size())) {
            return fail(node_name(model, step.node) + ": its mesh does not exist");
        }
        if (node.mesh >= 0) {
            auto instances = instances_of(model, step.node);
            if (!instances) return fail(instances.error());
            const tinygltf::Mesh& mesh = model.meshes[node.mesh];
            for (int p = 0; p < static_cast<int>(mesh.primitives.size()); ++p) {
                const int mode = mesh.primitives[p].mode;
                if (mode != -1 && mode != TINYGLTF_MODE_TRIANGLES &&
                    mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
                    doc.warnings.push_back(node_name(model, step.node) + ", mesh '" + mesh.name +
                                           "' primitive " + std::to_string(p) + ": " +
                                           (mode == TINYGLTF_MODE_POINTS       ? "points"
                                            : mode <= TINYGLTF_MODE_LINE_STRIP ? "lines"
                                                                               : "not triangles") +
                                           " (mode " + std::to_string(mode) +
                                           ") skipped: only triangles are drawn");
                    continue;
                }
                auto part = part_of(model, step.node, p, to_scene);
                if (!part) return fail(part.error());
                if (!instances.value()) {
                    doc.parts.push_back(std::move(part).value());
                    continue;
                }
                const std::vector<glm::dmat4>& each = *instances.value();
                for (std::size_t i = 0; i < each.size(); ++i) {
                    GltfPart placed = part.value();
                    placed.node += " instance " + std::to_string(i);
                    placed.to_scene = to_scene * each[i];
                    doc.parts.push_back(std::move(placed));
                }
            }
        }
        for (auto c = node.children.rbegin(); c != node.children.rend(); ++c) {
            stack.push_back({*c, to_scene});
        }
    }
    return doc;
}

}  // namespace gem::import
