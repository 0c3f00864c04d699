// How the G-buffer's RGBA8 albedo target holds linear albedo: as its square root, a gamma of 2 that
// keeps dark shades apart in 8 bits as sRGB would. Encoding sRGB exactly on write and read costs a
// CPU rasterizer a polynomial per channel and pixel; this is one square root and one product.

vec3 encodeAlbedo(vec3 linear) { return sqrt(clamp(linear, 0.0, 1.0)); }

vec3 decodeAlbedo(vec3 stored) { return stored * stored; }
