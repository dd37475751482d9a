/* Standalone reproducer (no shadowcheck code) for two compatibility-profile results on Mesa:
 *
 * (A) Fixed-function 1D shadow lookup: ARB_shadow §3.8.13.1 / GL 4.6 compatibility §8.23.1 compare
 *     R, the texture coordinate r, with Dt. Texture: 4x1 DEPTH_COMPONENT24 holding 0.2 0.4 0.6 0.8,
 *     NEAREST, COMPARE_R_TO_TEXTURE; texcoord (s, t, r, q) = (0.375, 0, 0.5, 1) hits texel 1 (0.4).
 *     LEQUAL: 0.5 <= 0.4 is false -> 0; GEQUAL -> 1. Comparing against t = 0 instead gives 1 and 0.
 * (B) GLSL 1.20 shadow2D with DEPTH_TEXTURE_MODE: GL 4.6 compatibility Table 16.1 gives LUMINANCE
 *     (r,r,r,1), INTENSITY (r,r,r,r), ALPHA (0,0,0,r). Texture 1x1 depth 0.8, LEQUAL, R = 0.9 -> r = 0,
 *     so LUMINANCE must return alpha 1 and ALPHA must return (0,0,0,0); R = 0.5 -> r = 1, ALPHA (0,0,0,1).
 * Build: sh build.sh. Exit status 1 if any result differs from the spec's. */
#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>

static int bad = 0;

static void check(const char *what, const unsigned char *px, const float want[4]) {
    int ok = 1;
    for (int i = 0; i < 4; i++)
        if (abs(px[i] - (int)(want[i] * 255.0f + 0.5f)) > 1) ok = 0;
    printf("%-48s got (%.2f %.2f %.2f %.2f) want (%.0f %.0f %.0f %.0f)%s\n", what, px[0] / 255.0, px[1] / 255.0,
           px[2] / 255.0, px[3] / 255.0, want[0], want[1], want[2], want[3], ok ? "" : "   <-- differs from the spec");
    if (!ok) bad = 1;
}

static void quad(float s, float t, float r) {
    glBegin(GL_QUADS);
    glTexCoord4f(s, t, r, 1.0f); glVertex2f(-1, -1);
    glTexCoord4f(s, t, r, 1.0f); glVertex2f(1, -1);
    glTexCoord4f(s, t, r, 1.0f); glVertex2f(1, 1);
    glTexCoord4f(s, t, r, 1.0f); glVertex2f(-1, 1);
    glEnd();
}

static GLuint program(const char *fs_src) {
    const char *vs_src = "#version 120\nvoid main(){ gl_TexCoord[0] = gl_MultiTexCoord0; gl_Position = gl_Vertex; }\n";
    GLuint vs = glCreateShader(GL_VERTEX_SHADER), fs = glCreateShader(GL_FRAGMENT_SHADER), p = glCreateProgram();
    glShaderSource(vs, 1, &vs_src, NULL); glCompileShader(vs);
    glShaderSource(fs, 1, &fs_src, NULL); glCompileShader(fs);
    GLint ok = 0; glGetShaderiv(fs, GL_COMPILE_STATUS, &ok);
    if (!ok) { char log[1024]; glGetShaderInfoLog(fs, sizeof log, NULL, log); fprintf(stderr, "%s\n", log); exit(2); }
    glAttachShader(p, vs); glAttachShader(p, fs); glLinkProgram(p);
    return p;
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
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1, 1);
    glGenFramebuffers(1, &fbo); glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    glViewport(0, 0, 1, 1);
    unsigned char px[4];

    /* (A) fixed function, 1D */
    const GLuint d1[4] = {858993459u, 1717986918u, 2576980377u, 3435973836u}; /* 0.2 0.4 0.6 0.8 */
    GLuint t1; glGenTextures(1, &t1); glBindTexture(GL_TEXTURE_1D, t1);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_DEPTH_COMPONENT24, 4, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, d1);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_1D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_1D);
    const float one[4] = {1, 1, 1, 1}, zero_l[4] = {0, 0, 0, 1};
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    quad(0.375f, 0.0f, 0.5f); glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    check("(A) ff 1D LEQUAL, R=0.5 vs Dt=0.4", px, zero_l);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
    quad(0.375f, 0.0f, 0.5f); glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    check("(A) ff 1D GEQUAL, R=0.5 vs Dt=0.4", px, one);
    glDisable(GL_TEXTURE_1D);

    /* (B) GLSL 1.20 shadow2D and DEPTH_TEXTURE_MODE */
    const GLuint d2[1] = {3435973836u}; /* 0.8 */
    GLuint t2; glGenTextures(1, &t2); glBindTexture(GL_TEXTURE_2D, t2);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 1, 1, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, d2);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    GLuint p = program("#version 120\nuniform sampler2DShadow t;\nvoid main(){ gl_FragColor = shadow2D(t, gl_TexCoord[0].stp); }\n");
    glUseProgram(p); glUniform1i(glGetUniformLocation(p, "t"), 0);
    const struct { GLenum mode; const char *name; float r; float want[4]; } cases[] = {
        {GL_LUMINANCE, "(B) shadow2D LUMINANCE, r = 0", 0.9f, {0, 0, 0, 1}},
        {GL_INTENSITY, "(B) shadow2D INTENSITY, r = 0", 0.9f, {0, 0, 0, 0}},
        {GL_ALPHA, "(B) shadow2D ALPHA, r = 1", 0.5f, {0, 0, 0, 1}},
        {GL_LUMINANCE, "(B) shadow2D LUMINANCE, r = 1", 0.5f, {1, 1, 1, 1}},
    };
    for (unsigned i = 0; i < sizeof cases / sizeof *cases; i++) {
        glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, cases[i].mode);
        quad(0.5f, 0.5f, cases[i].r);
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        check(cases[i].name, px, cases[i].want);
    }
    printf("glGetError: 0x%x\n", glGetError());
    return bad;
}
