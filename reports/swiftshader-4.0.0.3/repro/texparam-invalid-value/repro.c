/* Standalone reproducer (no shadowcheck code): which error does TexParameteri raise for a value of
 * TEXTURE_COMPARE_MODE / TEXTURE_COMPARE_FUNC that is not among the legal ones, and is the state
 * left unchanged?
 *
 * ES 3.2 §8.10 Errors (ES 3.0 §3.8.7 alike): "An INVALID_ENUM error is generated if the type of the
 * parameter specified by pname is enum, and the value(s) specified by param or params are not among
 * the legal values shown in table 8.19." §2.3.1: the command that generates the error "is ignored
 * so that it has no effect on GL state".
 *
 * One OpenGL ES 3.0 context on an EGL 1.4 pbuffer; libEGL dlopen'ed from $REPRO_LIBEGL (default
 * libEGL.so.1), GL entry points from eglGetProcAddress, so one binary runs Mesa and SwiftShader.
 */
#include <EGL/egl.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>

typedef unsigned int GLenum, GLuint;
typedef int GLint, GLsizei;
#define GL_TEXTURE_2D 0x0DE1
#define GL_TEXTURE_COMPARE_MODE 0x884C
#define GL_TEXTURE_COMPARE_FUNC 0x884D
#define GL_RENDERER 0x1F01
#define GL_VERSION 0x1F02

static const unsigned char *(*glGetString)(GLenum);
static void (*glGenTextures)(GLsizei, GLuint *);
static void (*glBindTexture)(GLenum, GLuint);
static void (*glTexParameteri)(GLenum, GLenum, GLint);
static void (*glGetTexParameteriv)(GLenum, GLenum, GLint *);
static GLenum (*glGetError)(void);

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
#define LOAD(n) *(void **)&n = (void *)p_eglGetProcAddress(#n);
  LOAD(glGetString) LOAD(glGenTextures) LOAD(glBindTexture) LOAD(glTexParameteri)
  LOAD(glGetTexParameteriv) LOAD(glGetError)
  printf("GL_RENDERER = %s\nGL_VERSION  = %s\n", glGetString(GL_RENDERER), glGetString(GL_VERSION));

  struct { const char *pname_name; GLenum pname; GLint value; GLint initial; } t[] = {
      {"TEXTURE_COMPARE_MODE", GL_TEXTURE_COMPARE_MODE, 0x0203 /* LEQUAL */, 0 /* NONE */},
      {"TEXTURE_COMPARE_MODE", GL_TEXTURE_COMPARE_MODE, 0x1234, 0},
      {"TEXTURE_COMPARE_FUNC", GL_TEXTURE_COMPARE_FUNC, 0x884E /* COMPARE_REF_TO_TEXTURE */, 0x0203},
      {"TEXTURE_COMPARE_FUNC", GL_TEXTURE_COMPARE_FUNC, 0x1234, 0x0203},
  };
  int bad = 0;
  for (unsigned i = 0; i < sizeof t / sizeof t[0]; i++) {
    GLuint tex; GLint got = -1;
    while (glGetError() != 0) {}
    glGenTextures(1, &tex); glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, t[i].pname, t[i].value);
    GLenum e = glGetError();
    glGetTexParameteriv(GL_TEXTURE_2D, t[i].pname, &got);
    int ok = e == 0x0500 && got == t[i].initial;
    bad += !ok;
    printf("TexParameteri(%s, 0x%04X): error 0x%04X (expected 0x0500 INVALID_ENUM), value read back 0x%04X (expected 0x%04X) %s\n",
           t[i].pname_name, t[i].value, e, got, t[i].initial, ok ? "ok" : "WRONG");
  }
  printf("%s\n", bad ? "RESULT: differs from ES 3.2 §8.10" : "RESULT: as ES 3.2 §8.10");
  return 0;
}
