// Long arrays of float4 records in RGBA32F textures kTexWidth texels wide
// (texel_array.hpp), read with texelFetch: record i's texel.
const int kTexWidth = 1024;  // texel_array.hpp: kTextureWidth

ivec2 texel_of(int i) { return ivec2(i % kTexWidth, i / kTexWidth); }
