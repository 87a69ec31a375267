// The stone methods' registry entries for fuzz_config alone: the config reader takes the method
// names from the registry (gpu/stone_method.cpp), whose entries each method's file defines
// with its GL maker and programs. The reader reads only the names, so these stand-ins carry the
// names alone rather than bring the GPU code into the fuzz build.
#include "gpu/stone_method.hpp"

namespace gem::gpu {

extern const MethodEntry kTraceMethod, kTableMethod, kPhongMethod;
constinit const MethodEntry kTraceMethod{"trace"};
constinit const MethodEntry kTableMethod{"table"};
constinit const MethodEntry kPhongMethod{"phong"};

}  // namespace gem::gpu
