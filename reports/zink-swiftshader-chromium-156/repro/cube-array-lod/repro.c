/* Standalone reproducer (no shadowcheck code): which mipmap level does a cube-map-array shadow
 * lookup with implicit derivatives use, against a cube-map shadow lookup with the same coordinates?
 *
 * GL 4.6 §8.14.1 (8.7)-(8.9): λ = log2 ρ, ρ from the derivatives of the face coordinates u = s·w,
 * v = t·w (§8.13: s, t from the major axis). NEAREST_MIPMAP_NEAREST picks level ⌈λ + 1/2⌉ − 1
 * (§8.14.3). Here each 8x8 face is covered by a 4x4 viewport with the direction (1, y, z),
 * y and z going linearly from −1 to 1 across the viewport: u and v change by 8/4 = 2 texels per pixel,
 * ρ = 2, λ = 1: level 1 for every pixel of the 4x4 block.
 * Levels hold Dt = 0.2 (level 0), 0.8 (level 1), 0.4 (level 2) in every face and layer; with LEQUAL
 * and Dref = 0.5 the result is 1 only where level 1 was sampled.
 * GLSL 4.30 (4.40 and later trip zink-on-SwiftShader's missing transform feedback: "invalid xfb_buffer").
 * Desktop GL 4.6 (else 4.5) core context on EGL (surfaceless Mesa; MESA_GL_VERSION_OVERRIDE where the driver
 * offers less), rendered into an RGBA8 renderbuffer, read back with glReadPixels.
 */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <stdio.h>
#include <stdlib.h>

typedef unsigned int GLenum, GLuint; typedef int GLint, GLsizei; typedef float GLfloat;
#define FNS(X) \
  X(const unsigned char *, glGetString, (GLenum)) X(void, glGenTextures, (GLsizei, GLuint *)) \
  X(void, glBindTexture, (GLenum, GLuint)) X(void, glActiveTexture, (GLenum)) \
  X(void, glTexImage3D, (GLenum, GLint, GLint, GLsizei, GLsizei, GLsizei, GLint, GLenum, GLenum, const void *)) \
  X(void, glTexImage2D, (GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum, const void *)) \
  X(void, glTexParameteri, (GLenum, GLenum, GLint)) X(void, glGenFramebuffers, (GLsizei, GLuint *)) \
  X(void, glBindFramebuffer, (GLenum, GLuint)) X(void, glGenRenderbuffers, (GLsizei, GLuint *)) \
  X(void, glBindRenderbuffer, (GLenum, GLuint)) X(void, glRenderbufferStorage, (GLenum, GLenum, GLsizei, GLsizei)) \
  X(void, glFramebufferRenderbuffer, (GLenum, GLenum, GLenum, GLuint)) X(GLuint, glCreateShader, (GLenum)) \
  X(void, glShaderSource, (GLuint, GLsizei, const char *const *, const GLint *)) X(void, glCompileShader, (GLuint)) \
  X(void, glGetShaderiv, (GLuint, GLenum, GLint *)) X(void, glGetShaderInfoLog, (GLuint, GLsizei, GLsizei *, char *)) \
  X(GLuint, glCreateProgram, (void)) X(void, glAttachShader, (GLuint, GLuint)) X(void, glLinkProgram, (GLuint)) \
  X(void, glUseProgram, (GLuint)) X(GLint, glGetUniformLocation, (GLuint, const char *)) X(void, glUniform1i, (GLint, GLint)) \
  X(void, glViewport, (GLint, GLint, GLsizei, GLsizei)) X(void, glDrawArrays, (GLenum, GLint, GLsizei)) \
  X(void, glGenVertexArrays, (GLsizei, GLuint *)) X(void, glBindVertexArray, (GLuint)) \
  X(void, glReadPixels, (GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void *)) X(GLenum, glGetError, (void))
#define DECL(r, n, a) static r(*n) a;
FNS(DECL)

static const char *VS = "#version 430 core\nout vec2 p;\nvoid main() { vec2 q = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0); p = q; gl_Position = vec4(q, 0.0, 1.0); }\n";
/* p in [-1, 1] across the 4x4 viewport (pixel centres at ±0.25, ±0.75): direction (1, -p.y, -p.x)
 * hits face +X with s = (-z/|x| + 1)/2 = (p.x + 1)/2, t = (-y/|x| + 1)/2 = (p.y + 1)/2. */
static const char *FS_ARRAY = "#version 430 core\nin vec2 p; uniform samplerCubeArrayShadow s; out vec4 o;\nvoid main() { o = vec4(texture(s, vec4(1.0, -p.y, -p.x, 1.0), 0.5)); }\n";
static const char *FS_CUBE = "#version 430 core\nin vec2 p; uniform samplerCubeShadow s; out vec4 o;\nvoid main() { o = vec4(texture(s, vec4(1.0, -p.y, -p.x, 0.5))); }\n";

static GLuint shader(GLenum t, const char *src) {
  GLuint s = glCreateShader(t); GLint ok = 0; char log[1024];
  glShaderSource(s, 1, &src, NULL); glCompileShader(s); glGetShaderiv(s, 0x8B81, &ok);
  if (!ok) { glGetShaderInfoLog(s, sizeof log, NULL, log); fprintf(stderr, "compile: %s\n", log); exit(1); }
  return s;
}

static void run(const char *what, const char *fs, GLenum target) {
  GLuint prog = glCreateProgram(), tex;
  glAttachShader(prog, shader(0x8B31, VS)); glAttachShader(prog, shader(0x8B30, fs));
  glLinkProgram(prog); glUseProgram(prog);
  glGenTextures(1, &tex); glBindTexture(target, tex);
  const unsigned short dt[3] = {13107, 52428, 26214}; /* 0.2, 0.8, 0.4 as unorm16 */
  static unsigned short buf[8 * 8 * 12];
  for (int l = 0; l < 3; l++) {
    int w = 8 >> l;
    for (int i = 0; i < w * w * 12; i++) buf[i] = dt[l];
    if (target == 0x9009) /* CUBE_MAP_ARRAY: 2 cubes = 12 layer-faces */
      glTexImage3D(target, l, 0x81A5 /* DEPTH_COMPONENT16 */, w, w, 12, 0, 0x1902, 0x1403, buf);
    else
      for (int f = 0; f < 6; f++) glTexImage2D(0x8515 + f, l, 0x81A5, w, w, 0, 0x1902, 0x1403, buf);
  }
  glTexParameteri(target, 0x813D /* MAX_LEVEL */, 2);
  glTexParameteri(target, 0x2801, 0x2700 /* NEAREST_MIPMAP_NEAREST */);
  glTexParameteri(target, 0x2800, 0x2600 /* NEAREST */);
  glTexParameteri(target, 0x884C, 0x884E /* COMPARE_REF_TO_TEXTURE */);
  glTexParameteri(target, 0x884D, 0x0203 /* LEQUAL */);
  glDrawArrays(0x0004, 0, 3);
  unsigned char px[4 * 4 * 4];
  glReadPixels(0, 0, 4, 4, 0x1908, 0x1401, px);
  int ones = 0;
  for (int i = 0; i < 16; i++) ones += px[4 * i] == 255;
  printf("%-28s r per pixel (row by row):", what);
  for (int i = 0; i < 16; i++) printf("%s%d", i % 4 ? "" : " ", px[4 * i] == 255);
  printf("  -> %d of 16 sampled level 1 (spec: 16)\n", ones);
  GLenum e = glGetError();
  if (e) printf("GL error 0x%x\n", e);
}

int main(void) {
  EGLDisplay d = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  if (!eglInitialize(d, NULL, NULL)) { fprintf(stderr, "eglInitialize failed\n"); return 1; }
  eglBindAPI(EGL_OPENGL_API);
  EGLContext c = EGL_NO_CONTEXT;
  for (int minor = 6; minor >= 5 && !c; minor--) {
    EGLint a[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, minor, EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    c = eglCreateContext(d, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, a);
  }
  if (!c || !eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, c)) { fprintf(stderr, "no GL 4.5/4.6 core context\n"); return 1; }
#define LOAD(r, n, a) n = (r(*) a)eglGetProcAddress(#n);
  FNS(LOAD)
  printf("GL_RENDERER = %s\nGL_VERSION  = %s\n", glGetString(0x1F01), glGetString(0x1F02));
  GLuint fb, rb, vao;
  glGenVertexArrays(1, &vao); glBindVertexArray(vao);
  glGenFramebuffers(1, &fb); glBindFramebuffer(0x8D40, fb);
  glGenRenderbuffers(1, &rb); glBindRenderbuffer(0x8D41, rb);
  glRenderbufferStorage(0x8D41, 0x8058, 4, 4);
  glFramebufferRenderbuffer(0x8D40, 0x8CE0, 0x8D41, rb);
  glViewport(0, 0, 4, 4);
  run("samplerCubeShadow", FS_CUBE, 0x8513);
  run("samplerCubeArrayShadow", FS_ARRAY, 0x9009);
  return 0;
}
