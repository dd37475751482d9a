#version 450
// The lookup in the fragment stage. The coordinate is a push constant, so its derivatives are 0:
// lambda = -inf, which selects magnification at the base level (level 0), like Lod 0 in comp.glsl.
// Built twice: as is (samplerCubeShadow, OpImageSampleDrefImplicitLod) and with -DNOCOMPARE
// (samplerCube, OpImageSampleImplicitLod: the filtered depth itself, for diagnosis).
#ifdef NOCOMPARE
layout(set = 0, binding = 0) uniform samplerCube u_tex;
#else
layout(set = 0, binding = 0) uniform samplerCubeShadow u_tex;
#endif
layout(push_constant) uniform PC { vec4 u_p; };  // (direction.xyz, Dref)
layout(location = 0) out vec4 o;
void main() {
#ifdef NOCOMPARE
  o = vec4(texture(u_tex, u_p.xyz).r, 0.0, 0.0, 1.0);
#else
  o = vec4(texture(u_tex, u_p), 0.0, 0.0, 1.0);
#endif
}
