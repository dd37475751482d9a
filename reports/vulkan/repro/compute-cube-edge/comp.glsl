#version 450
// The same lookup in the compute stage, by one invocation. Outside the fragment stage glslang
// compiles texture() to an explicit-LOD sample with Lod 0 (OpImageSampleDrefExplicitLod Lod 0;
// with -DNOCOMPARE, OpImageSampleExplicitLod Lod 0): the base level, magnification.
layout(local_size_x = 1) in;
#ifdef NOCOMPARE
layout(set = 0, binding = 0) uniform samplerCube u_tex;
#else
layout(set = 0, binding = 0) uniform samplerCubeShadow u_tex;
#endif
layout(set = 0, binding = 1, std430) buffer Out { vec4 o; };
layout(push_constant) uniform PC { vec4 u_p; };  // (direction.xyz, Dref)
void main() {
#ifdef NOCOMPARE
  o = vec4(texture(u_tex, u_p.xyz).r, 0.0, 0.0, 1.0);
#else
  o = vec4(texture(u_tex, u_p), 0.0, 0.0, 1.0);
#endif
}
