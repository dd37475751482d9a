/* Shader 2 source */
#version 400 core
in vec2 a_pos;
void main() { gl_Position = vec4(a_pos, 0.0, 1.0); }

/* Compile status: ok */
/* Log Info: */
