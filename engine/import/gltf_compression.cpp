#include "import/gltf_compression.hpp"

#include <cmath>

#include <draco/attributes/attribute_quantization_transform.h>
#include <draco/compression/decode.h>
#include <meshoptimizer.h>

namespace gem::import {

// The decoder asserts on parameters its format cannot have: they are checked first.
Result<std::vector<unsigned char>> decode_meshopt_view(const unsigned char* data,
                                                       std::size_t length, std::size_t n,
                                                       std::size_t size, const std::string& mode,
                                                       const std::string& filter) {
    if (!(size >= 1 && size <= 256 && n <= (std::size_t(1) << 30) / size)) {
        return Error{"a count or stride out of range"};
    }
    const bool index_size = size == 2 || size == 4;
    std::vector<unsigned char> out(n * size);
    int status = -1;
    if (mode == "ATTRIBUTES" && size % 4 == 0) {
        status = meshopt_decodeVertexBuffer(out.data(), n, size, data, length);
    } else if (mode == "TRIANGLES" && index_size && n % 3 == 0) {
        status = meshopt_decodeIndexBuffer(out.data(), n, size, data, length);
    } else if (mode == "INDICES" && index_size) {
        status = meshopt_decodeIndexSequence(out.data(), n, size, data, length);
    } else {
        return Error{"mode '" + mode + "' with a stride of " + std::to_string(size) +
                     " is not meshopt's"};
    }
    if (status != 0) return Error{"its data does not decode"};
    if (filter == "OCTAHEDRAL" && (size == 4 || size == 8)) {
        meshopt_decodeFilterOct(out.data(), n, size);
    } else if (filter == "QUATERNION" && size == 8) {
        meshopt_decodeFilterQuat(out.data(), n, size);
    } else if (filter == "EXPONENTIAL" && size % 4 == 0) {
        meshopt_decodeFilterExp(out.data(), n, size);
    } else if (filter != "NONE") {
        return Error{"filter '" + filter + "' with a stride of " + std::to_string(size) +
                     " is not meshopt's"};
    }
    return out;
}

Result<DracoMesh> decode_draco_mesh(const unsigned char* data, std::size_t size,
                                    std::uint32_t position_id) {
    DracoMesh out;
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(data), size);
    draco::Decoder decoder;
    decoder.SetSkipAttributeTransform(draco::GeometryAttribute::POSITION);
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok()) {
        return Error{"does not decode: " + decoded.status().error_msg_string()};
    }
    const draco::Mesh& mesh = *decoded.value();
    const draco::PointAttribute* positions = mesh.GetAttributeByUniqueId(position_id);
    if (positions == nullptr || positions->num_components() != 3) {
        return Error{"its POSITION is not three numbers a point"};
    }
    out.positions.resize(mesh.num_points());
    draco::AttributeQuantizationTransform quantised;
    if (quantised.InitFromAttribute(*positions)) {
        const int bits = quantised.quantization_bits();
        if (bits < 1 || bits > 30) return Error{"a quantisation out of range"};
        const double step = quantised.range() / (std::ldexp(1.0, bits) - 1.0);
        out.position_step = step;
        for (draco::PointIndex i(0); i < mesh.num_points(); ++i) {
            std::int32_t q[3];
            if (!positions->ConvertValue<std::int32_t, 3>(positions->mapped_index(i), q)) {
                return Error{"a position does not decode"};
            }
            for (int c = 0; c < 3; ++c) {
                out.positions[i.value()][c] = quantised.min_value(c) + q[c] * step;
            }
        }
    } else {
        for (draco::PointIndex i(0); i < mesh.num_points(); ++i) {
            float f[3];
            if (!positions->ConvertValue<float, 3>(positions->mapped_index(i), f)) {
                return Error{"a position does not decode"};
            }
            out.positions[i.value()] = {f[0], f[1], f[2]};
        }
    }
    out.triangles.resize(mesh.num_faces());
    for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f) {
        const draco::Mesh::Face& face = mesh.face(f);
        for (int c = 0; c < 3; ++c) {
            if (face[c].value() >= mesh.num_points()) {
                return Error{"an index past its positions"};
            }
            out.triangles[f.value()][c] = face[c].value();
        }
    }
    return out;
}

}  // namespace gem::import
