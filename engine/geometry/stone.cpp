#include "geometry/stone.hpp"

namespace gem {

const char* to_string(FacetKind kind) {
    switch (kind) {
        case FacetKind::table:
            return "table";
        case FacetKind::crown:
            return "crown";
        case FacetKind::girdle:
            return "girdle";
        case FacetKind::pavilion:
            return "pavilion";
        case FacetKind::culet:
            return "culet";
        case FacetKind::other:
            return "other";
    }
    return "other";
}

}  // namespace gem
