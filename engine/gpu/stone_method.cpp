#include "gpu/stone_method.hpp"

namespace gem::gpu {

// Each method's maker, defined in the method's own file.
using MakeStones = Result<std::unique_ptr<StoneMethod>>(const FrameSetup& setup,
                                                        const std::vector<const Stone*>& kinds);
MakeStones make_trace_stones;  // trace_method.cpp
MakeStones make_table_stones;  // table_method.cpp
MakeStones make_phong_stones;  // phong_method.cpp

namespace {

// One line per method, the most accurate first: its name, whether it needs tables and draws
// pieces, its maker.
constexpr MethodEntry kMethods[] = {
    {"trace", false, true, make_trace_stones},
    {"table", true, false, make_table_stones},
    {"phong", false, true, make_phong_stones},
};

}  // namespace

Result<bool> StoneMethod::draw_alone(std::size_t kind, const StoneFrame& frame,
                                     const StoneModel& model) {
    (void)kind;
    (void)frame;
    (void)model;
    return Error{"this stone method has no models to draw a stone alone with"};
}

std::span<const MethodEntry> stone_methods() {
    return kMethods;
}

const MethodEntry* find_stone_method(std::string_view name) {
    for (const MethodEntry& entry : kMethods) {
        if (entry.name == name) return &entry;
    }
    return nullptr;
}

std::string stone_method_names() {
    std::string names;
    for (const MethodEntry& entry : kMethods) {
        if (!names.empty()) names += ", ";
        names += entry.name;
    }
    return names;
}

}  // namespace gem::gpu
