/* Shader 6 source */
#version 400 core
#extension GL_EXT_texture_shadow_lod : require
uniform samplerCubeShadow u_tex;
uniform vec4 u_p;
uniform float u_x;
uniform vec4 u_dx;
uniform vec4 u_dy;
uniform vec2 u_c;
out vec4 o;
void main() {
  vec4 p = u_p;
  o = vec4(textureLod(u_tex, p, u_x), 0.0, 0.0, 1.0);
}

/* Compile status: ok */
/* Log Info: */
