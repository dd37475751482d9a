/* Shader 5 source */
#version 400 core
#extension GL_EXT_texture_shadow_lod : require
in vec2 a_pos;
void main() { gl_Position = vec4(a_pos, 0.0, 1.0); }

/* Compile status: ok */
/* Log Info: */
