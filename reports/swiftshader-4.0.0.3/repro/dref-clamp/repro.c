/* Standalone reproducer (no shadowcheck code): is Dref clamped to [0, 1] before the depth
 * comparison of a fixed-point depth texture?
 *
 * GL 4.6 §8.23.1 / ES 3.2 §8.20.1: "If the texture's internal format indicates a fixed-point depth
 * texture, then Dt and Dref are clamped to the range [0, 1]; otherwise no clamping is performed."
 * Vulkan 1.3 §16.x "Depth Compare Operation" has the same rule for UNORM depth formats, so zink may
 * pass Dref unclamped and the Vulkan driver must clamp.
 *
 * One OpenGL ES 3.0 context on an EGL 1.4 pbuffer (works on Mesa and on SwiftShader's EGL 1.4), a
 * 1x1 DEPTH_COMPONENT24 / 16 texture, NEAREST, COMPARE_REF_TO_TEXTURE, a sampler2DShadow lookup
 * with Dref from a uniform, the result r read back from an RGBA8 renderbuffer (0 or 255).
 * libEGL is dlopen'ed from $REPRO_LIBEGL (default libEGL.so.1), GL entry points come from
 * eglGetProcAddress, so the same binary runs Mesa and SwiftShader's libraries.
 */
#include <EGL/egl.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>

typedef unsigned int GLenum, GLuint;
typedef int GLint, GLsizei;
typedef float GLfloat;
#define GL_TEXTURE_2D 0x0DE1
#define GL_DEPTH_COMPONENT 0x1902
#define GL_DEPTH_COMPONENT16 0x81A5
#define GL_DEPTH_COMPONENT24 0x81A6
#define GL_UNSIGNED_SHORT 0x1403
#define GL_UNSIGNED_INT 0x1405
#define GL_TEXTURE_MIN_FILTER 0x2801
#define GL_TEXTURE_MAG_FILTER 0x2800
#define GL_NEAREST 0x2600
#define GL_TEXTURE_COMPARE_MODE 0x884C
#define GL_TEXTURE_COMPARE_FUNC 0x884D
#define GL_COMPARE_REF_TO_TEXTURE 0x884E
#define GL_LESS 0x0201
#define GL_EQUAL 0x0202
#define GL_LEQUAL 0x0203
#define GL_GREATER 0x0204
#define GL_NOTEQUAL 0x0205
#define GL_GEQUAL 0x0206
#define GL_FRAMEBUFFER 0x8D40
#define GL_RENDERBUFFER 0x8D41
#define GL_RGBA8 0x8058
#define GL_COLOR_ATTACHMENT0 0x8CE0
#define GL_VERTEX_SHADER 0x8B31
#define GL_FRAGMENT_SHADER 0x8B30
#define GL_TRIANGLES 0x0004
#define GL_RGBA 0x1908
#define GL_UNSIGNED_BYTE 0x1401
#define GL_RENDERER 0x1F01
#define GL_VERSION 0x1F02
#define GL_COMPILE_STATUS 0x8B81
#define GL_LINK_STATUS 0x8B82

#define FNS(X) \
  X(const unsigned char *, glGetString, (GLenum)) \
  X(void, glGenTextures, (GLsizei, GLuint *)) X(void, glBindTexture, (GLenum, GLuint)) \
  X(void, glTexImage2D, (GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum, const void *)) \
  X(void, glTexParameteri, (GLenum, GLenum, GLint)) \
  X(void, glGenFramebuffers, (GLsizei, GLuint *)) X(void, glBindFramebuffer, (GLenum, GLuint)) \
  X(void, glGenRenderbuffers, (GLsizei, GLuint *)) X(void, glBindRenderbuffer, (GLenum, GLuint)) \
  X(void, glRenderbufferStorage, (GLenum, GLenum, GLsizei, GLsizei)) \
  X(void, glFramebufferRenderbuffer, (GLenum, GLenum, GLenum, GLuint)) \
  X(GLuint, glCreateShader, (GLenum)) X(void, glShaderSource, (GLuint, GLsizei, const char *const *, const GLint *)) \
  X(void, glCompileShader, (GLuint)) X(void, glGetShaderiv, (GLuint, GLenum, GLint *)) \
  X(GLuint, glCreateProgram, (void)) X(void, glAttachShader, (GLuint, GLuint)) \
  X(void, glLinkProgram, (GLuint)) X(void, glGetProgramiv, (GLuint, GLenum, GLint *)) \
  X(void, glUseProgram, (GLuint)) X(GLint, glGetUniformLocation, (GLuint, const char *)) \
  X(void, glUniform1f, (GLint, GLfloat)) X(void, glViewport, (GLint, GLint, GLsizei, GLsizei)) \
  X(void, glDrawArrays, (GLenum, GLint, GLsizei)) \
  X(void, glReadPixels, (GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void *)) \
  X(GLenum, glGetError, (void))
#define DECL(r, n, a) static r(*n) a;
FNS(DECL)

static const char *VS = "#version 300 es\nvoid main() { vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0); gl_Position = vec4(p, 0.0, 1.0); }\n";
static const char *FS = "#version 300 es\nprecision highp float; uniform highp sampler2DShadow s; uniform float dref; out vec4 o;\nvoid main() { o = vec4(texture(s, vec3(0.5, 0.5, dref))); }\n";

static GLuint shader(GLenum t, const char *src) {
  GLuint s = glCreateShader(t); GLint ok = 0;
  glShaderSource(s, 1, &src, NULL); glCompileShader(s); glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) { fprintf(stderr, "compile failed\n"); exit(1); }
  return s;
}

int main(void) {
  const char *lib = getenv("REPRO_LIBEGL") ? getenv("REPRO_LIBEGL") : "libEGL.so.1";
  void *h = dlopen(lib, RTLD_NOW | RTLD_GLOBAL);
  if (!h) { fprintf(stderr, "dlopen %s: %s\n", lib, dlerror()); return 1; }
#define E(n) __typeof__(&n) p_##n = (__typeof__(&n))dlsym(h, #n);
  E(eglGetDisplay) E(eglInitialize) E(eglChooseConfig) E(eglCreatePbufferSurface) E(eglBindAPI)
  E(eglCreateContext) E(eglMakeCurrent) E(eglGetProcAddress) E(eglGetError)
  EGLDisplay d = p_eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (!p_eglInitialize(d, NULL, NULL)) { fprintf(stderr, "eglInitialize 0x%x\n", p_eglGetError()); return 1; }
  EGLint ca[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, 0x40 /* ES3 */, EGL_NONE};
  EGLConfig cfg; EGLint n = 0;
  if (!p_eglChooseConfig(d, ca, &cfg, 1, &n) || n < 1) { fprintf(stderr, "no config\n"); return 1; }
  EGLint pa[] = {EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE};
  EGLSurface surf = p_eglCreatePbufferSurface(d, cfg, pa);
  p_eglBindAPI(EGL_OPENGL_ES_API);
  EGLint xa[] = {EGL_CONTEXT_CLIENT_VERSION, 3, EGL_NONE};
  EGLContext c = p_eglCreateContext(d, cfg, EGL_NO_CONTEXT, xa);
  if (!surf || !c || !p_eglMakeCurrent(d, surf, surf, c)) { fprintf(stderr, "context 0x%x\n", p_eglGetError()); return 1; }
#define LOAD(r, n, a) n = (r(*) a)p_eglGetProcAddress(#n);
  FNS(LOAD)
  printf("GL_RENDERER = %s\nGL_VERSION  = %s\n", glGetString(GL_RENDERER), glGetString(GL_VERSION));

  GLuint fb, rb, prog = glCreateProgram(), tex;
  glGenFramebuffers(1, &fb); glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glGenRenderbuffers(1, &rb); glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1, 1);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  glAttachShader(prog, shader(GL_VERTEX_SHADER, VS)); glAttachShader(prog, shader(GL_FRAGMENT_SHADER, FS));
  glLinkProgram(prog); glUseProgram(prog); glViewport(0, 0, 1, 1);
  glGenTextures(1, &tex); glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);

  /* Expected r: Table 8.23 on the clamped Dref (clamp(-0.1) = 0, clamp(1.1) = 1). */
  struct { const char *fmt; GLenum ifmt, type; unsigned texel; float dt; const char *func_name; GLenum func; float dref; int expect; } t[] = {
      {"D24", GL_DEPTH_COMPONENT24, GL_UNSIGNED_INT, 0x00000000u, 0.0f, "LESS", GL_LESS, -0.1f, 0},
      {"D24", GL_DEPTH_COMPONENT24, GL_UNSIGNED_INT, 0x00000000u, 0.0f, "EQUAL", GL_EQUAL, -0.1f, 1},
      {"D24", GL_DEPTH_COMPONENT24, GL_UNSIGNED_INT, 0x00000000u, 0.0f, "GEQUAL", GL_GEQUAL, -0.1f, 1},
      {"D24", GL_DEPTH_COMPONENT24, GL_UNSIGNED_INT, 0xFFFFFFFFu, 1.0f, "EQUAL", GL_EQUAL, 1.1f, 1},
      {"D24", GL_DEPTH_COMPONENT24, GL_UNSIGNED_INT, 0xFFFFFFFFu, 1.0f, "LEQUAL", GL_LEQUAL, 1.1f, 1},
      {"D24", GL_DEPTH_COMPONENT24, GL_UNSIGNED_INT, 0xFFFFFFFFu, 1.0f, "GREATER", GL_GREATER, 1.1f, 0},
      {"D16", GL_DEPTH_COMPONENT16, GL_UNSIGNED_SHORT, 0xFFFFu, 1.0f, "NOTEQUAL", GL_NOTEQUAL, 1.1f, 0},
      /* In range: no clamping involved (controls). */
      {"D24", GL_DEPTH_COMPONENT24, GL_UNSIGNED_INT, 0x00000000u, 0.0f, "LESS", GL_LESS, 0.0f, 0},
      {"D24", GL_DEPTH_COMPONENT24, GL_UNSIGNED_INT, 0xFFFFFFFFu, 1.0f, "EQUAL", GL_EQUAL, 1.0f, 1},
      {"D16", GL_DEPTH_COMPONENT16, GL_UNSIGNED_SHORT, 0x0000u, 0.0f, "LESS", GL_LESS, 0.0f, 0},
  };
  int bad = 0;
  for (unsigned i = 0; i < sizeof t / sizeof t[0]; i++) {
    unsigned short s16 = (unsigned short)t[i].texel;
    glTexImage2D(GL_TEXTURE_2D, 0, t[i].ifmt, 1, 1, 0, GL_DEPTH_COMPONENT, t[i].type,
                 t[i].type == GL_UNSIGNED_SHORT ? (const void *)&s16 : (const void *)&t[i].texel);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, t[i].func);
    glUniform1f(glGetUniformLocation(prog, "dref"), t[i].dref);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    unsigned char px[4] = {7, 7, 7, 7};
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    int r = px[0] == 255 ? 1 : px[0] == 0 ? 0 : -1;
    printf("%s Dt=%.0f %-8s Dref=%5.2f: r=%d (spec: %d)%s\n", t[i].fmt, t[i].dt, t[i].func_name, t[i].dref, r,
           t[i].expect, r == t[i].expect ? "" : "  <-- differs");
    bad += r != t[i].expect;
  }
  GLenum e = glGetError();
  if (e) printf("GL error 0x%x\n", e);
  printf("%d of %zu differ from the spec\n", bad, sizeof t / sizeof t[0]);
  return 0;
}
