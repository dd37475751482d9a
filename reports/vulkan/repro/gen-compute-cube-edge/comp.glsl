#version 450
layout(local_size_x = 1, local_size_y = 1, local_size_z = 1) in;
layout(set = 0, binding = 0) uniform samplerCubeShadow u_tex;
layout(set = 0, binding = 1, rgba32f) writeonly uniform image2D u_out;
layout(push_constant) uniform PC { vec4 u_p; float u_x; ivec2 u_at; };
void main() {
  vec4 p = u_p;
  vec4 r = vec4(0.0);
  r = vec4(texture(u_tex, p), 0.0, 0.0, 1.0);
  imageStore(u_out, u_at, r);
}
