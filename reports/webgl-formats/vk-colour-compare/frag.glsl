#version 450
layout(set = 0, binding = 0) uniform sampler2D u_tex;
layout(push_constant) uniform PC { int u_base; };
layout(location = 0) flat in vec4 v_p;
layout(location = 1) flat in vec4 v_dx;
layout(location = 2) flat in vec4 v_dy;
layout(location = 3) flat in float v_x;
layout(location = 0) out vec4 o;
void main() {
  if (u_base < 0) discard;
  vec4 p = v_p;
  vec4 u_dx = v_dx;
  vec4 u_dy = v_dy;
  float u_x = v_x;
  o = textureLod(u_tex, p.xy, u_x);
}
