#pragma once
// A .glb written byte by byte, as the glTF 2.0 specification lays it out (a 12-byte header, a
// JSON chunk, a binary chunk, each padded to 4 bytes), without the library the reader uses: the
// files the glTF tests and the fuzzer's seeds read. Meshes are float positions and uint32
// indices in the one buffer; materials and nodes are JSON as the caller writes them.

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace gem::test_support {

// A .glb under construction: meshes of float positions and uint32 indices in one buffer.
class Glb {
  public:
    using json = nlohmann::json;

    // A mesh of `positions` (metres) and triangles, with `material` (-1: none); its index.
    int mesh(const std::string& name, const std::vector<glm::dvec3>& positions,
             const std::vector<std::array<std::uint32_t, 3>>& triangles, int material) {
        const int pos = accessor(floats(positions), 5126, "VEC3", positions.size());
        std::vector<std::uint32_t> flat;
        for (const auto& t : triangles) flat.insert(flat.end(), t.begin(), t.end());
        const int ind = accessor(bytes_of(flat), 5125, "SCALAR", flat.size());
        json primitive = {{"attributes", {{"POSITION", pos}}}, {"indices", ind}};
        if (material >= 0) primitive["material"] = material;
        doc_["meshes"].push_back({{"name", name}, {"primitives", {primitive}}});
        return static_cast<int>(doc_["meshes"].size()) - 1;
    }
    int material(json m) {
        doc_["materials"].push_back(std::move(m));
        return static_cast<int>(doc_["materials"].size()) - 1;
    }
    int node(json n) {
        doc_["nodes"].push_back(std::move(n));
        const int i = static_cast<int>(doc_["nodes"].size()) - 1;
        doc_["scenes"][0]["nodes"].push_back(i);
        return i;
    }
    // A node that is not a root of the scene (a child another node lists); its index.
    int child(json n) {
        doc_["nodes"].push_back(std::move(n));
        return static_cast<int>(doc_["nodes"].size()) - 1;
    }
    // A mesh of the primitives given as JSON (from the accessors below); its index.
    int mesh_of(const std::string& name, json primitives) {
        doc_["meshes"].push_back({{"name", name}, {"primitives", std::move(primitives)}});
        return static_cast<int>(doc_["meshes"].size()) - 1;
    }
    // Accessors of float vec3s (positions, normals) and of uint32 indices.
    int vec3s(const std::vector<glm::dvec3>& v) {
        return accessor(floats(v), 5126, "VEC3", v.size());
    }
    int indices(const std::vector<std::uint32_t>& v) {
        return accessor(bytes_of(v), 5125, "SCALAR", v.size());
    }
    json& doc() { return doc_; }
    // Raw bytes appended to the buffer as a view of their own (compressed data); its index.
    int view(const std::string& data) {
        while (bin_.size() % 4 != 0) bin_.push_back('\0');
        doc_["bufferViews"].push_back(
            {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", data.size()}});
        bin_ += data;
        return static_cast<int>(doc_["bufferViews"].size()) - 1;
    }

    void write(const std::filesystem::path& path) const {
        json doc = doc_;
        doc["asset"] = {{"version", "2.0"}};
        doc["scene"] = 0;
        doc["buffers"] = {{{"byteLength", bin_.size()}}};
        std::string text = doc.dump();
        while (text.size() % 4 != 0) text.push_back(' ');
        std::string bin = bin_;
        while (bin.size() % 4 != 0) bin.push_back('\0');
        std::string out = "glTF";
        put(out, 2);
        put(out, static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
        put(out, static_cast<std::uint32_t>(text.size()));
        put(out, 0x4E4F534Au);  // JSON
        out += text;
        put(out, static_cast<std::uint32_t>(bin.size()));
        put(out, 0x004E4942u);  // BIN
        out += bin;
        std::ofstream(path, std::ios::binary) << out;
    }

  private:
    static void put(std::string& s, std::uint32_t v) { s.append(reinterpret_cast<char*>(&v), 4); }
    template <class T>
    static std::string bytes_of(const std::vector<T>& v) {
        return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
    }
    static std::string floats(const std::vector<glm::dvec3>& p) {
        std::vector<float> f;
        for (const glm::dvec3& x : p) f.insert(f.end(), {float(x.x), float(x.y), float(x.z)});
        return bytes_of(f);
    }
    int accessor(const std::string& data, int component, const char* type, std::size_t count) {
        doc_["accessors"].push_back({{"bufferView", view(data)},
                                     {"componentType", component},
                                     {"type", type},
                                     {"count", count}});
        return static_cast<int>(doc_["accessors"].size()) - 1;
    }
    json doc_ = {{"scenes", {{{"nodes", json::array()}}}}};
    std::string bin_;
};

}  // namespace gem::test_support
