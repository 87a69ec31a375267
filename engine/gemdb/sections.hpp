#pragma once
// Encoding and decoding of the .gemdb metadata sections (stone, material, camera, build
// parameters, view grid). Decoders validate every count and value and report what is wrong;
// the reader adds the file name.

#include <cstdint>
#include <span>

#include "gemdb/bytes.hpp"
#include "gemdb/database_types.hpp"
#include "gemdb/quantise.hpp"
#include "gemdb/view_grid.hpp"
#include "geometry/stone.hpp"
#include "util/result.hpp"

namespace gem {

struct ParamsSection {
    BuildParams params;
    PositionBox box;  // the exit-position quantisation box
};

void write_stone_section(ByteWriter& out, const Stone& stone);  // all but the material
void write_material_section(ByteWriter& out, const Material& material);
void write_camera_section(ByteWriter& out, const CameraModel& camera);
// What a database's tables depend on of its stone: the stone and material sections, as stored.
// Two stones with the same bytes are served by the same tables.
void write_stone_identity(ByteWriter& out, const Stone& stone);
bool same_stored_stone(const Stone& a, const Stone& b);
void write_params_section(ByteWriter& out, const BuildParams& params, const PositionBox& box);
void write_grid_section(ByteWriter& out, const ViewGrid& grid);

Result<Stone> read_stone_section(std::span<const std::uint8_t> bytes);
Result<Material> read_material_section(std::span<const std::uint8_t> bytes);
Result<CameraModel> read_camera_section(std::span<const std::uint8_t> bytes);
Result<ParamsSection> read_params_section(std::span<const std::uint8_t> bytes);
Result<ViewGrid> read_grid_section(std::span<const std::uint8_t> bytes,
                                   const std::vector<glm::dmat3>& symmetry);

}  // namespace gem
