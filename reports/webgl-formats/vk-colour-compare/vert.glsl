#version 450
layout(location = 0) in vec2 a_pos;
layout(location = 1) in vec4 a_p;
layout(location = 2) in vec4 a_dx;
layout(location = 3) in vec4 a_dy;
layout(location = 4) in vec3 a_x;
layout(push_constant) uniform PC { int u_base; };
layout(location = 0) flat out vec4 v_p;
layout(location = 1) flat out vec4 v_dx;
layout(location = 2) flat out vec4 v_dy;
layout(location = 3) flat out float v_x;
void main() {
  int s = u_base + int(a_x.y);
  ivec2 corner = 2 * ivec2(s % 1, s / 1) + 2 * ivec2(a_pos);
  gl_Position = vec4(vec2(corner) / 1.0 - 1.0, 0.0, 1.0);
  v_p = a_p;
  v_dx = a_dx;
  v_dy = a_dy;
  v_x = a_x.x;
}
