// What shows where the stone is not: the environment seen along each camera ray (through
// the virtual cube's centre, as the camera orbits it). A solid colour is a clear
// (background_pass.cpp).
in vec2 v_ndc;
out vec4 o_colour;

uniform samplerCube u_environment;

void main() {
    vec3 origin;
    vec3 direction;
    camera_ray(v_ndc, origin, direction);
    o_colour = vec4(textureLod(u_environment, direction, 0.0).rgb, 1.0);
}
