// The thesis' baseline (fig. 8.17): a Phong-shaded stone, alpha-blended over what is behind
// it, no refraction. I = I_o (k_a E(n) + k_d sum I_l max(n.l, 0)) + sum I_l k_s (r.v)^h with
// E the environment cube along the normal (ambient), opacity 1 - alpha (alpha: the thesis'
// transparency, the share of the background that shows through each facet). Follows
// stone.glsl (the facet planes) and specular.glsl ((r.v)^h).

in vec3 v_position;
flat in uint v_facet;
out vec4 o_colour;

uniform samplerCube u_environment;
uniform mat3 u_frame_rotation;  // the stone's frame in the piece's, where the cube stands
uniform vec3 u_eye;             // eye position; a direction toward the eye when at infinity
uniform int u_eye_at_infinity;  // 1: orthographic camera
uniform vec4 u_light_position[MAX_LIGHTS];  // w = 1: point light (mm); w = 0: direction to it
uniform vec3 u_light_colour[MAX_LIGHTS];
uniform float u_k_s;
uniform float u_alpha;
uniform vec3 u_stone_colour;

// Ambient and diffuse shares of the stone colour: the thesis leaves them open; these keep a
// white stone under one unit light in a unit environment at most 1.
const float kAmbient = 0.3;
const float kDiffuse = 0.7;

void main() {
    vec3 n = facet_plane(int(v_facet)).xyz;
    if (!gl_FrontFacing) n = -n;  // a back facet is lit from inside the stone
    vec3 v = u_eye_at_infinity == 1 ? normalize(u_eye) : normalize(u_eye - v_position);
    vec3 diffuse = vec3(0.0);
    vec3 specular = vec3(0.0);
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vec3 l = toward_light(u_light_position[i], v_position);
        float n_l = dot(n, l);
        if (n_l <= 0.0) continue;
        diffuse += u_light_colour[i] * n_l;
        float r_v = max(dot(reflect(-l, n), v), 0.0);
        specular += u_light_colour[i] * (u_k_s * specular_power(r_v));
    }
    vec3 ambient = textureLod(u_environment, u_frame_rotation * n, 0.0).rgb;
    vec3 colour = u_stone_colour * (kAmbient * ambient + kDiffuse * diffuse) + specular;
    o_colour = vec4(colour, clamp(1.0 - u_alpha, 0.0, 1.0));
}
