/* Standalone reproducer (no shadowcheck code): the DEPTH_TEXTURE_MODE layout seen through the
 * fixed-function texture environment, read two ways.
 *
 * GL 2.1 §3.8.14 / GL 4.6 compatibility §8.23.1 and Table 16.1: a depth texture value r (the
 * texel Dt when TEXTURE_COMPARE_MODE is NONE, the comparison result with COMPARE_R_TO_TEXTURE)
 * becomes the texture source colour (Rs, Gs, Bs, As) by DEPTH_TEXTURE_MODE:
 *   LUMINANCE (r, r, r, 1), INTENSITY (r, r, r, r), ALPHA (0, 0, 0, r), RED (r, 0, 0, 1).
 * GL 2.1 Table 3.22, TEXTURE_ENV_MODE REPLACE: an ALPHA texture gives Cv = Cf (the fragment
 * colour), a LUMINANCE/RED one Av = Af, so REPLACE with a (0,0,0,1) fragment shows only part of
 * the layout. GL 2.1 §3.8.13, COMBINE with COMBINE_RGB = COMBINE_ALPHA = REPLACE, SOURCE0 =
 * TEXTURE, OPERAND0 = SRC_COLOR / SRC_ALPHA gives (Cv, Av) = (Cs, As): the whole layout.
 *
 * Texture: 1x1 DEPTH_COMPONENT24 holding 0.4 (uploaded as UNSIGNED_INT 0x66666666), NEAREST,
 * TEXTURE_2D. Modes ALPHA, LUMINANCE, INTENSITY, RED; compare NONE (r = 0.4) and LEQUAL with
 * R = 0.3 (r = 1) and R = 0.5 (r = 0). Build and run: sh build.sh. Exit 1 if any COMBINE result differs from the
 * layout (REPLACE rows are printed for comparison; they are what shadowcheck's ff path reads). */
#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int bad = 0;

static void draw(float r) {
    glBegin(GL_QUADS);
    glTexCoord4f(0.5f, 0.5f, r, 1.0f); glVertex2f(-1, -1);
    glTexCoord4f(0.5f, 0.5f, r, 1.0f); glVertex2f(1, -1);
    glTexCoord4f(0.5f, 0.5f, r, 1.0f); glVertex2f(1, 1);
    glTexCoord4f(0.5f, 0.5f, r, 1.0f); glVertex2f(-1, 1);
    glEnd();
}

static void layout(GLenum mode, float r, float out[4]) {
    switch (mode) {
    case GL_ALPHA: out[0] = out[1] = out[2] = 0; out[3] = r; break;
    case GL_LUMINANCE: out[0] = out[1] = out[2] = r; out[3] = 1; break;
    case GL_INTENSITY: out[0] = out[1] = out[2] = out[3] = r; break;
    default: out[0] = r; out[1] = out[2] = 0; out[3] = 1; break; /* RED */
    }
}

static const char *name(GLenum m) {
    return m == GL_ALPHA ? "ALPHA" : m == GL_LUMINANCE ? "LUMINANCE" : m == GL_INTENSITY ? "INTENSITY" : "RED";
}

int main(void) {
    PFNEGLGETPLATFORMDISPLAYEXTPROC getdpy = (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    EGLDisplay dpy = getdpy(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (!eglInitialize(dpy, NULL, NULL)) { fprintf(stderr, "eglInitialize failed\n"); return 2; }
    eglBindAPI(EGL_OPENGL_API);
    const EGLint attr[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attr);
    if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) { fprintf(stderr, "context failed\n"); return 2; }
    printf("GL_RENDERER: %s\nGL_VERSION: %s\n", glGetString(GL_RENDERER), glGetString(GL_VERSION));

    GLuint rb, fbo;
    glGenRenderbuffers(1, &rb); glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, 1, 1);
    glGenFramebuffers(1, &fbo); glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    glViewport(0, 0, 1, 1);

    const GLuint depth = 0x66666666u; /* 0.4 */
    GLuint tex;
    glGenTextures(1, &tex); glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 1, 1, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &depth);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glColor4f(0, 0, 0, 1);

    const GLenum modes[] = {GL_ALPHA, GL_LUMINANCE, GL_INTENSITY, GL_RED};
    printf("%-10s %-8s %-8s got (r g b a)                    layout (Cs, As)\n", "mode", "compare", "env");
    for (int cmp = 0; cmp < 3; cmp++) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, cmp ? GL_COMPARE_R_TO_TEXTURE : GL_NONE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        float R = cmp == 2 ? 0.5f : 0.3f;             /* the reference: texture coordinate r */
        float r = cmp == 0 ? 0.4f : cmp == 1 ? 1.0f : 0.0f;
        for (unsigned m = 0; m < 4; m++) {
            glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, modes[m]);
            for (int env = 0; env < 2; env++) {
                if (env == 0) {
                    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
                } else {
                    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
                    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_REPLACE);
                    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_REPLACE);
                    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE);
                    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_TEXTURE);
                    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_SRC_COLOR);
                    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_ALPHA);
                }
                glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
                glClear(GL_COLOR_BUFFER_BIT);
                draw(R);
                float px[4], want[4];
                glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, px);
                layout(modes[m], r, want);
                int ok = 1;
                if (env == 0) { /* REPLACE: ALPHA keeps Cf = (0,0,0); LUMINANCE/RED keep Af = 1 */
                    if (modes[m] == GL_ALPHA) want[0] = want[1] = want[2] = 0;
                }
                for (int i = 0; i < 4; i++) if (px[i] < want[i] - 0.001f || px[i] > want[i] + 0.001f) ok = 0;
                printf("%-10s %-8s %-8s (%.4f %.4f %.4f %.4f)   want (%.1f %.1f %.1f %.1f)%s\n", name(modes[m]),
                       cmp == 0 ? "NONE" : cmp == 1 ? "R=0.3" : "R=0.5", env ? "COMBINE" : "REPLACE", px[0], px[1], px[2], px[3],
                       want[0], want[1], want[2], want[3], ok ? "" : "   <-- differs from the spec");
                if (!ok && env == 1) bad = 1;
            }
        }
    }
    printf("glGetError: 0x%x\n", glGetError());
    return bad;
}
