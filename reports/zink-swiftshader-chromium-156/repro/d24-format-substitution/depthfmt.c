/* Which depth format Mesa picked for each GL depth internal format: GL_TEXTURE_DEPTH_SIZE and
 * GL_TEXTURE_DEPTH_TYPE of level 0 (GL 4.6 §8.11.3 / Table 23.x texture level state). EGL
 * surfaceless, desktop GL core context; plain C, no shadowcheck code. */
#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
int main(void) {
    EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (!eglInitialize(dpy, NULL, NULL)) return 2;
    eglBindAPI(EGL_OPENGL_API);
    const EGLint attrs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attrs);
    if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) return 2;
    printf("GL_RENDERER: %s\n", glGetString(GL_RENDERER));
    const struct { GLenum f; const char *n; } fs[] = {{GL_DEPTH_COMPONENT16, "DEPTH_COMPONENT16"}, {GL_DEPTH_COMPONENT24, "DEPTH_COMPONENT24"}, {GL_DEPTH_COMPONENT32, "DEPTH_COMPONENT32"}, {GL_DEPTH_COMPONENT32F, "DEPTH_COMPONENT32F"}, {GL_DEPTH24_STENCIL8, "DEPTH24_STENCIL8"}};
    for (unsigned i = 0; i < sizeof fs / sizeof fs[0]; i++) {
        GLuint t; glGenTextures(1, &t); glBindTexture(GL_TEXTURE_2D, t);
        GLenum fmt = fs[i].f == GL_DEPTH24_STENCIL8 ? GL_DEPTH_STENCIL : GL_DEPTH_COMPONENT;
        GLenum ty = fs[i].f == GL_DEPTH24_STENCIL8 ? GL_UNSIGNED_INT_24_8 : GL_FLOAT;
        glTexImage2D(GL_TEXTURE_2D, 0, fs[i].f, 4, 4, 0, fmt, ty, NULL);
        GLint size = 0, type = 0;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &size);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_TYPE, &type);
        printf("%-20s DEPTH_SIZE %2d  DEPTH_TYPE %s  (GL error 0x%x)\n", fs[i].n, size,
               type == GL_UNSIGNED_NORMALIZED ? "UNSIGNED_NORMALIZED" : type == GL_FLOAT ? "FLOAT" : "other", glGetError());
    }
    return 0;
}
