// What shows where the stone is not: the environment seen along each camera ray (through
// the virtual cube's centre, as the camera orbits it), or a solid colour.
in vec2 v_ndc;
out vec4 o_colour;

uniform samplerCube u_environment;
uniform int u_use_environment;
uniform vec3 u_background_colour;

void main() {
    if (u_use_environment == 0) {
        o_colour = vec4(u_background_colour, 1.0);
        return;
    }
    vec3 origin;
    vec3 direction;
    camera_ray(v_ndc, origin, direction);
    o_colour = vec4(textureLod(u_environment, direction, 0.0).rgb, 1.0);
}
