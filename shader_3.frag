/* Shader 3 source */
#version 400 core
uniform samplerCube u_tex;
uniform vec4 u_p;
uniform float u_x;
uniform vec4 u_dx;
uniform vec4 u_dy;
uniform vec2 u_c;
out vec4 o;
void main() {
  vec4 p = u_p;
  o = vec4(textureLod(u_tex, p.xyz, u_x));
}

/* Compile status: ok */
/* Log Info: */
