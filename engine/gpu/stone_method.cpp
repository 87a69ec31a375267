#include "gpu/stone_method.hpp"

#include <cassert>

namespace gem::gpu {

// Each entry is defined in its method's file.
extern const MethodEntry kTraceMethod, kTableMethod, kPhongMethod;

namespace {

// The registry: one entry per method, the most accurate first.
constexpr const MethodEntry* kMethods[] = {&kTraceMethod, &kTableMethod, &kPhongMethod};

}  // namespace

Result<bool> StoneMethod::draw_alone(std::size_t kind, const StoneFrame& frame,
                                     const StoneModel& model) {
    (void)kind;
    (void)frame;
    (void)model;
    return Error{"this stone method has no models to draw a stone alone with"};
}

std::span<const MethodEntry* const> stone_methods() {
    return kMethods;
}

const MethodEntry* find_stone_method(std::string_view name) {
    for (const MethodEntry* entry : kMethods) {
        if (entry->name == name) return entry;
    }
    return nullptr;
}

std::string stone_method_names() {
    std::string names;
    for (const MethodEntry* entry : kMethods) {
        if (!names.empty()) names += ", ";
        names += entry->name;
    }
    return names;
}

const MethodEntry& fallback_stone_method() {
    for (const MethodEntry* entry : kMethods) {
        if (!entry->needs_database && entry->draws_pieces && entry->refracts) return *entry;
    }
    assert(false && "the registry has a refracting method that needs no tables");
    return *kMethods[0];
}

const MethodEntry& tables_method() {
    for (const MethodEntry* entry : kMethods) {
        if (entry->needs_database) return *entry;
    }
    return fallback_stone_method();
}

std::vector<MethodRung> method_rungs(const RungContext& context) {
    std::vector<MethodRung> rungs;
    for (const MethodEntry* entry : kMethods) {
        if (entry->rungs == nullptr) continue;
        for (MethodRung& rung : entry->rungs(context)) rungs.push_back(std::move(rung));
    }
    return rungs;
}

}  // namespace gem::gpu
