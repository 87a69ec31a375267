#pragma once
// A glTF 2.0 file (.glb, or .gltf with its buffers) read into plain parts: every mesh primitive
// placed in the scene (its triangles in the mesh's own frame and the node's transform to the
// scene, glTF's metres, +y up) and the materials it names, with the Khronos gem extensions
// (KHR_materials_ior, _transmission, _volume, _dispersion), the surface ones (_specular,
// _clearcoat) and a vendor's gem material read. This header is the whole of the glTF library
// (Debian's tinygltf 2.7, compiled in: gltf_document.cpp says why) that the rest of the
// project sees: gltf_document.cpp reads, gltf_material.cpp reads the materials, gltf_write.cpp
// writes, and gltf_compression.cpp decodes Draco and meshopt meshes. What a piece makes of the
// parts is piece/gltf_piece.hpp.
//
// Refused with one message naming the file and the fault: a file that is not glTF, a truncated
// .glb, an accessor or compressed data reaching outside its buffer or not decoding, a node tree
// with a cycle, a position, normal or transform that is not a number, an extension the file
// requires that is not read here. Triangle strips and fans become triangles; points and lines
// (curves CAD leaves in an export) are skipped with a warning. EXT_mesh_gpu_instancing's
// instances are parts of their own.

#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "util/result.hpp"

namespace gem::import {

struct GltfMaterial {
    std::string name;
    glm::dvec3 base_colour{1.0};  // linear, the metallic-roughness model's base colour factor
    double metallic = 1.0;
    double roughness = 1.0;
    double transmission = 0.0;           // KHR_materials_transmission
    std::optional<double> ior;           // KHR_materials_ior (n at the D line)
    std::optional<double> dispersion;    // KHR_materials_dispersion: 20 / Abbe number
    glm::dvec3 attenuation_colour{1.0};  // KHR_materials_volume
    double attenuation_distance_m = std::numeric_limits<double>::infinity();
    double thickness_m = 0.0;  // KHR_materials_volume's thicknessFactor: 0 is thin-walled
    double clearcoat = 0.0;    // KHR_materials_clearcoat: the coat's share (said, not drawn)
    double specular = 1.0;     // KHR_materials_specular: scales a dielectric's F0, tinted by colour
    glm::dvec3 specular_colour{1.0};
    // A vendor's gem material (WEBGI_materials_diamond, written by web jewellery viewers and
    // their CAD plug-ins): the extension's name and what it says of the stone. Its fields are
    // documented only by the exporters that write them (docs/gltf.md).
    struct VendorGem {
        std::string extension;
        std::optional<double> ior;     // refractiveIndex
        std::optional<double> spread;  // dispersion: the index's offset from green to red and blue
        std::optional<glm::dvec3> colour;  // color, linear
    };
    std::optional<VendorGem> vendor_gem;
    std::vector<std::string> extensions;  // every extension the material carries
};

// One primitive of one mesh, as one node places it.
struct GltfPart {
    std::string node;  // names, for recognising stones and for messages
    std::string mesh;
    int mesh_index = 0;
    int primitive = 0;
    int material = -1;                  // into GltfDocument::materials; -1: the default material
    glm::dmat4 to_scene{1.0};           // the node's transform, metres
    std::vector<glm::dvec3> positions;  // the mesh's own frame
    std::vector<glm::dvec3> normals;    // by position, when the file gives them; else empty
    // One step of the file's quantised positions (KHR_mesh_quantization), in the mesh's
    // frame; 0 for float positions.
    double position_step = 0.0;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

struct GltfDocument {
    std::vector<GltfMaterial> materials;
    std::vector<GltfPart> parts;
    std::size_t images_ignored = 0;  // textures are not read (pieces shade by material factors)
    // What was read past or repaired, one line each ("node 'Curve 3', mesh 'Rail' primitive 0:
    // lines (mode 1) skipped: only triangles are drawn").
    std::vector<std::string> warnings;
};

// The document as a .glb: each part one node (its transform written as a translation, rotation
// and scale where it is one, else as a matrix); parts of one mesh_index share one mesh, the
// first such part's triangles; each material with the extensions its fields set
// (KHR_materials_transmission where transmissive, _ior, _dispersion, and _volume where it has
// a thickness). `generator` goes into the file's asset.
Result<std::string> glb_bytes(const GltfDocument& doc, const std::string& generator);

// A node's transform as a rotation and one positive scale, when it is one (no mirror, no uneven
// scale, within 1e-6): what a placed stone's node must be to stay its mesh's kind, and what
// the writer writes as translation, rotation and scale.
std::optional<std::pair<glm::dmat3, double>> rotation_and_scale(const glm::dmat4& m);

Result<GltfDocument> read_gltf(const std::filesystem::path& path);
// The same from the file's bytes: `name` stands for the file in messages, `base` is where a
// .gltf's buffers are looked for.
Result<GltfDocument> parse_gltf(std::string_view bytes, const std::string& name,
                                const std::filesystem::path& base);

}  // namespace gem::import
