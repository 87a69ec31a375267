#pragma once
// What gltf_document.cpp (the document) and gltf_material.cpp (its materials) share inside
// import/: tinygltf's declarations, included with the options gltf_document.cpp compiles it
// with, and the reading of its loosely typed values, each falling back where a key is absent
// or of another type. The rest of the project sees glTF through gltf_document.hpp only.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <cmath>
#include <string>

#include <glm/glm.hpp>

#include "import/gltf_document.hpp"

namespace gem::import {

inline double number(const tinygltf::Value& object, const char* key, double fallback) {
    if (!object.IsObject() || !object.Has(key)) return fallback;
    const tinygltf::Value& v = object.Get(key);
    return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

inline glm::dvec3 colour(const tinygltf::Value& object, const char* key, glm::dvec3 fallback) {
    if (!object.IsObject() || !object.Has(key)) return fallback;
    const tinygltf::Value& v = object.Get(key);
    if (!v.IsArray() || v.ArrayLen() < 3) return fallback;
    glm::dvec3 c;
    for (int i = 0; i < 3; ++i) {
        if (!v.Get(i).IsNumber()) return fallback;
        c[i] = v.Get(i).GetNumberAsDouble();
    }
    return c;
}

inline bool all_finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

inline std::string text(const tinygltf::Value& object, const char* key,
                        const std::string& fallback) {
    if (!object.IsObject() || !object.Has(key)) return fallback;
    const tinygltf::Value& v = object.Get(key);
    return v.IsString() ? v.Get<std::string>() : fallback;
}

// A material's factors and the extensions read (gltf_material.cpp).
GltfMaterial material_of(const tinygltf::Material& m);

}  // namespace gem::import
