// The stone methods' makers for fuzz_config alone: the config reader takes the method names
// from the registry (gpu/stone_method.cpp), which names these GL makers; the reader never
// calls them, so they fail here rather than bring the GPU code into the fuzz build.
#include "gpu/stone_method.hpp"

namespace gem::gpu {

namespace {
Result<std::unique_ptr<StoneMethod>> not_in_the_fuzz_build(const FrameSetup&,
                                                           const std::vector<const Stone*>&) {
    return Error{"no GL in the config fuzz target"};
}
}  // namespace

Result<std::unique_ptr<StoneMethod>> make_trace_stones(const FrameSetup& setup,
                                                       const std::vector<const Stone*>& kinds) {
    return not_in_the_fuzz_build(setup, kinds);
}
Result<std::unique_ptr<StoneMethod>> make_table_stones(const FrameSetup& setup,
                                                       const std::vector<const Stone*>& kinds) {
    return not_in_the_fuzz_build(setup, kinds);
}
Result<std::unique_ptr<StoneMethod>> make_phong_stones(const FrameSetup& setup,
                                                       const std::vector<const Stone*>& kinds) {
    return not_in_the_fuzz_build(setup, kinds);
}

}  // namespace gem::gpu
