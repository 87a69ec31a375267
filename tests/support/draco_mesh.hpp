#pragma once
// A mesh compressed with Draco (KHR_draco_mesh_compression) added to a test .glb, encoded by
// Draco's own encoder with its positions quantised to `bits`, as CAD and web exporters write
// them (Blender's default is 14 bits, three.js's 11).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include "glb_writer.hpp"

namespace gem::test_support {

inline int draco_mesh(Glb& glb, const std::string& name, const std::vector<glm::dvec3>& positions,
                      const std::vector<std::array<std::uint32_t, 3>>& triangles, int material,
                      int bits) {
    draco::Mesh mesh;
    mesh.set_num_points(static_cast<std::uint32_t>(positions.size()));
    draco::GeometryAttribute position;
    position.Init(draco::GeometryAttribute::POSITION, nullptr, 3, draco::DT_FLOAT32, false, 12, 0);
    const int id = mesh.AddAttribute(position, true, static_cast<std::uint32_t>(positions.size()));
    glm::dvec3 lo(1e300), hi(-1e300);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const float p[3] = {float(positions[i].x), float(positions[i].y), float(positions[i].z)};
        mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(std::uint32_t(i)), p);
        lo = glm::min(lo, positions[i]);
        hi = glm::max(hi, positions[i]);
    }
    for (const auto& t : triangles) {
        mesh.AddFace({draco::PointIndex(t[0]), draco::PointIndex(t[1]), draco::PointIndex(t[2])});
    }
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, bits);
    draco::EncoderBuffer encoded;
    if (!encoder.EncodeMeshToBuffer(mesh, &encoded).ok()) return -1;
    const int view = glb.view(std::string(encoded.data(), encoded.size()));
    using json = Glb::json;
    json& doc = glb.doc();
    doc["accessors"].push_back({{"componentType", 5126},
                                {"type", "VEC3"},
                                {"count", positions.size()},
                                {"min", {lo.x, lo.y, lo.z}},
                                {"max", {hi.x, hi.y, hi.z}}});
    const int pos = static_cast<int>(doc["accessors"].size()) - 1;
    doc["accessors"].push_back(
        {{"componentType", 5125}, {"type", "SCALAR"}, {"count", 3 * triangles.size()}});
    const int ind = static_cast<int>(doc["accessors"].size()) - 1;
    json primitive = {{"attributes", {{"POSITION", pos}}},
                      {"indices", ind},
                      {"extensions",
                       {{"KHR_draco_mesh_compression",
                         {{"bufferView", view},
                          {"attributes", {{"POSITION", mesh.attribute(id)->unique_id()}}}}}}}};
    if (material >= 0) primitive["material"] = material;
    doc["meshes"].push_back({{"name", name}, {"primitives", {primitive}}});
    doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    return static_cast<int>(doc["meshes"].size()) - 1;
}

}  // namespace gem::test_support
