// Writing a GltfDocument as a .glb with tinygltf (its implementation is compiled in
// gltf_document.cpp, with the same options, which every file including it must define alike).
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "import/gltf_document.hpp"

namespace gem::import {

namespace {

// Appends `values` to the buffer as one view and one accessor of `type`; returns the accessor.
template <typename T>
int add_accessor(tinygltf::Model& model, const std::vector<T>& values, int components,
                 int component_type, int type, int target) {
    tinygltf::Buffer& buffer = model.buffers[0];
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.data.size();
    view.byteLength = values.size() * sizeof(T);
    view.target = target;
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    buffer.data.insert(buffer.data.end(), bytes, bytes + view.byteLength);
    model.bufferViews.push_back(view);
    tinygltf::Accessor accessor;
    accessor.bufferView = static_cast<int>(model.bufferViews.size()) - 1;
    accessor.componentType = component_type;
    accessor.type = type;
    accessor.count = values.size() / static_cast<std::size_t>(components);
    if (type == TINYGLTF_TYPE_VEC3) {  // positions need their bounds; normals may have them
        accessor.minValues.assign(3, HUGE_VAL);
        accessor.maxValues.assign(3, -HUGE_VAL);
        for (std::size_t i = 0; i < values.size(); ++i) {
            accessor.minValues[i % 3] = std::min(accessor.minValues[i % 3], double(values[i]));
            accessor.maxValues[i % 3] = std::max(accessor.maxValues[i % 3], double(values[i]));
        }
    }
    model.accessors.push_back(accessor);
    return static_cast<int>(model.accessors.size()) - 1;
}

std::vector<float> floats_of(const std::vector<glm::dvec3>& v) {
    std::vector<float> out;
    out.reserve(3 * v.size());
    for (const glm::dvec3& p : v) out.insert(out.end(), {float(p.x), float(p.y), float(p.z)});
    return out;
}

tinygltf::Value object_of(std::initializer_list<std::pair<const char*, tinygltf::Value>> kv) {
    tinygltf::Value::Object o;
    for (const auto& [k, v] : kv) o[k] = v;
    return tinygltf::Value(std::move(o));
}

tinygltf::Value colour_value(const glm::dvec3& c) {
    return tinygltf::Value(
        tinygltf::Value::Array{tinygltf::Value(c.x), tinygltf::Value(c.y), tinygltf::Value(c.z)});
}

tinygltf::Material material_for_file(const GltfMaterial& m, std::set<std::string>& used) {
    tinygltf::Material out;
    out.name = m.name;
    out.pbrMetallicRoughness.baseColorFactor = {m.base_colour.x, m.base_colour.y, m.base_colour.z,
                                                1.0};
    out.pbrMetallicRoughness.metallicFactor = m.metallic;
    out.pbrMetallicRoughness.roughnessFactor = m.roughness;
    const auto add = [&](const char* name, tinygltf::Value value) {
        out.extensions[name] = std::move(value);
        used.insert(name);
    };
    if (m.transmission > 0.0) {
        add("KHR_materials_transmission",
            object_of({{"transmissionFactor", tinygltf::Value(m.transmission)}}));
    }
    if (m.ior) add("KHR_materials_ior", object_of({{"ior", tinygltf::Value(*m.ior)}}));
    if (m.thickness_m > 0.0) {
        tinygltf::Value::Object volume;
        volume["thicknessFactor"] = tinygltf::Value(m.thickness_m);
        if (std::isfinite(m.attenuation_distance_m)) {
            volume["attenuationDistance"] = tinygltf::Value(m.attenuation_distance_m);
            volume["attenuationColor"] = colour_value(m.attenuation_colour);
        }
        add("KHR_materials_volume", tinygltf::Value(std::move(volume)));
    }
    if (m.dispersion) {
        add("KHR_materials_dispersion",
            object_of({{"dispersion", tinygltf::Value(*m.dispersion)}}));
    }
    return out;
}

// A node's transform as glTF's translation, rotation and scale when it is a rotation and one
// positive scale; else its matrix.
void set_transform(tinygltf::Node& node, const glm::dmat4& m) {
    const auto rigid = rotation_and_scale(m);
    if (!rigid) {
        node.matrix.assign(glm::value_ptr(m), glm::value_ptr(m) + 16);
        return;
    }
    const auto& [r, s] = *rigid;
    const glm::dquat q = glm::normalize(glm::quat_cast(r));
    if (m[3] != glm::dvec4(0, 0, 0, 1)) node.translation = {m[3].x, m[3].y, m[3].z};
    if (std::abs(q.w) < 1.0 - 1e-15) node.rotation = {q.x, q.y, q.z, q.w};
    if (std::abs(s - 1.0) > 1e-15) node.scale = {s, s, s};
}

}  // namespace

Result<std::string> glb_bytes(const GltfDocument& doc, const std::string& generator) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = generator;
    model.buffers.emplace_back();
    std::set<std::string> used;
    for (const GltfMaterial& m : doc.materials) {
        model.materials.push_back(material_for_file(m, used));
    }
    model.extensionsUsed.assign(used.begin(), used.end());
    std::map<int, int> mesh_of;  // the document's mesh_index → the file's mesh
    model.scenes.emplace_back();
    for (const GltfPart& part : doc.parts) {
        if (part.material >= static_cast<int>(doc.materials.size())) {
            return Error{"part '" + part.node + "' names a material that does not exist"};
        }
        auto [it, fresh] = mesh_of.try_emplace(part.mesh_index, int(model.meshes.size()));
        if (fresh) {
            tinygltf::Primitive primitive;
            primitive.mode = TINYGLTF_MODE_TRIANGLES;
            primitive.material = part.material;
            primitive.attributes["POSITION"] =
                add_accessor(model, floats_of(part.positions), 3, TINYGLTF_COMPONENT_TYPE_FLOAT,
                             TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
            if (!part.normals.empty()) {
                if (part.normals.size() != part.positions.size()) {
                    return Error{"part '" + part.node +
                                 "' has normals and positions that differ in count"};
                }
                primitive.attributes["NORMAL"] =
                    add_accessor(model, floats_of(part.normals), 3, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                 TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
            }
            std::vector<std::uint32_t> indices;
            indices.reserve(3 * part.triangles.size());
            for (const auto& t : part.triangles) {
                for (std::uint32_t c : t) {
                    if (c >= part.positions.size()) {
                        return Error{"part '" + part.node + "' has an index past its positions"};
                    }
                    indices.push_back(c);
                }
            }
            primitive.indices =
                add_accessor(model, indices, 1, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                             TINYGLTF_TYPE_SCALAR, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
            tinygltf::Mesh mesh;
            mesh.name = part.mesh;
            mesh.primitives.push_back(std::move(primitive));
            model.meshes.push_back(std::move(mesh));
        }
        tinygltf::Node node;
        node.name = part.node;
        node.mesh = it->second;
        set_transform(node, part.to_scene);
        model.scenes[0].nodes.push_back(static_cast<int>(model.nodes.size()));
        model.nodes.push_back(std::move(node));
    }
    model.buffers[0].data.resize((model.buffers[0].data.size() + 3) / 4 * 4, 0);
    model.defaultScene = 0;
    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, false, true)) {
        return Error{"the glTF library could not write the piece"};
    }
    return out.str();
}

}  // namespace gem::import
