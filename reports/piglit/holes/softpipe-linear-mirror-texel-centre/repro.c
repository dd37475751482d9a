/* Standalone reproducer (no shadowcheck code): LINEAR filtering with MIRRORED_REPEAT at a texel
 * centre inside a mirrored repetition of the texture.
 *
 * GL 4.6 §8.14.2 (ES 3.2 §8.14.2), LINEAR: u = s * w_t, i0 = wrap(floor(u - 1/2)),
 * i1 = wrap(floor(u - 1/2) + 1), alpha = frac(u - 1/2), result = (1 - alpha) * T[i0] + alpha * T[i1];
 * MIRRORED_REPEAT (ES 3.2 Table 8.21): wrap(i) = (size - 1) - mirror((i mod (2 * size)) - size),
 * mirror(a) = a if a >= 0, else -(1 + a).
 * At s = -0.25 on a texture 2 texels wide: u - 1/2 = -1, so alpha = 0, i0 = wrap(-1) = 0: the
 * result is texel 0 alone.
 *
 * Part A: 2x2 DEPTH_COMPONENT24 holding 0.2 0.4 / 0.6 0.8 (row 0: 0.2, 0.4), LINEAR, mirrored
 * repeat, (s, t) = (-0.25, 0.25): COMPARE_MODE NONE must read 0.2 (texel (0,0)); with LEQUAL and
 * Dref = 0.3 the only texel with weight is (0,0), 0.3 <= 0.2 is false, so r = 0 (a texel of weight 0
 * may pass, which the spec's "implementation-dependent" filtered r makes a should-level matter).
 * Part B: piglit's `texwrap` NPOT case: a 9x9 DEPTH_COMPONENT24 texture whose column x holds
 * (x + 1) / 16, sampled (NONE) at the centre of every texel column i in [-21, 29]; prints each
 * column where the texel read differs from wrap(i). Also NEAREST, which must agree.
 * Build and run: sh build.sh. Exit status 1 if part A's NONE read or any part B column differs. */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static GLuint shader(GLenum type, const char *src) {
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) { char log[1024]; glGetShaderInfoLog(s, sizeof log, NULL, log); fprintf(stderr, "%s\n", log); exit(2); }
    return s;
}

static GLuint program(const char *fs) {
    static const char *vs = "#version 330 core\nvoid main(){ vec2 p = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1)) * 4.0 - 1.0; gl_Position = vec4(p, 0.0, 1.0); }\n";
    GLuint p = glCreateProgram();
    glAttachShader(p, shader(GL_VERTEX_SHADER, vs));
    glAttachShader(p, shader(GL_FRAGMENT_SHADER, fs));
    glLinkProgram(p);
    return p;
}

static float lookup(GLuint prog, float s, float t, float dref) {
    glUseProgram(prog);
    glUniform1i(glGetUniformLocation(prog, "tex"), 0);
    glUniform3f(glGetUniformLocation(prog, "p"), s, t, dref);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    float px[4];
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, px);
    return px[0];
}

static int wrap(int i, int size) {
    int m = ((i % (2 * size)) + 2 * size) % (2 * size) - size;
    int mir = m >= 0 ? m : -(1 + m);
    return (size - 1) - mir;
}

static void filters(GLenum f) {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, f);
}

int main(void) {
    PFNEGLGETPLATFORMDISPLAYEXTPROC getdpy = (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    EGLDisplay dpy = getdpy(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (!eglInitialize(dpy, NULL, NULL)) { fprintf(stderr, "eglInitialize failed\n"); return 2; }
    eglBindAPI(EGL_OPENGL_API);
    const EGLint attr[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                           EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attr);
    if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) { fprintf(stderr, "context failed\n"); return 2; }
    printf("GL_RENDERER: %s\nGL_VERSION: %s\n", glGetString(GL_RENDERER), glGetString(GL_VERSION));

    GLuint vao, rb, fbo;
    glGenVertexArrays(1, &vao); glBindVertexArray(vao);
    glGenRenderbuffers(1, &rb); glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, 1, 1);
    glGenFramebuffers(1, &fbo); glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    glViewport(0, 0, 1, 1);

    GLuint read = program("#version 330 core\nuniform sampler2D tex; uniform vec3 p; out vec4 o;\n"
                          "void main(){ o = vec4(texture(tex, p.xy).r, 0.0, 0.0, 1.0); }\n");
    GLuint cmp = program("#version 330 core\nuniform sampler2DShadow tex; uniform vec3 p; out vec4 o;\n"
                         "void main(){ o = vec4(texture(tex, p), 0.0, 0.0, 1.0); }\n");
    int bad = 0;

    /* Part A: exact stored integers, d * (2^32 - 1) for UNSIGNED_INT data. */
    const GLuint a[4] = {858993459u /* 0.2 */, 1717986918u /* 0.4 */, 2576980377u /* 0.6 */, 3435973836u /* 0.8 */};
    GLuint tex;
    glGenTextures(1, &tex); glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 2, 2, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, a);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    printf("Part A: 2x2 D24 (0.2 0.4 / 0.6 0.8), MIRRORED_REPEAT\n");
    const float ss[] = {-0.25f, 1.75f, -0.375f, 0.25f};
    for (unsigned k = 0; k < sizeof ss / sizeof *ss; k++) {
        for (int f = 0; f < 2; f++) {
            filters(f ? GL_LINEAR : GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
            float d = lookup(read, ss[k], 0.25f, 0.0f);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
            float r = lookup(cmp, ss[k], 0.25f, 0.3f);
            /* spec: u - 1/2 = 2s - 1/2; s = -0.25, 1.75: texel 0 alone; s = -0.375: 0.75 * texel 0 + 0.25 * texel 1 */
            float want = (ss[k] == -0.375f && f) ? 0.75f * 0.2f + 0.25f * 0.4f : 0.2f;
            int ok = fabsf(d - want) < 1e-4f;
            printf("  %-7s s = %+.3f t = 0.25: NONE reads %.6f (spec %.6f)%s | LEQUAL Dref 0.3: r = %.4f\n",
                   f ? "LINEAR" : "NEAREST", ss[k], d, want, ok ? "" : "   <-- differs from the spec", r);
            if (!ok) bad = 1;
        }
    }

    /* Part B: piglit texwrap's NPOT size. */
    enum { W = 9 };
    GLuint b[W * W];
    for (int y = 0; y < W; y++)
        for (int x = 0; x < W; x++) b[y * W + x] = (GLuint)((double)(x + 1) / 16.0 * 4294967295.0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, W, W, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, b);
    for (int f = 0; f < 2; f++) {
        filters(f ? GL_LINEAR : GL_NEAREST);
        int n = 0;
        printf("Part B: 9x9 D24, column x holds (x+1)/16, %s, s at texel centres (i + 0.5) / 9, t = 4.5 / 9\n", f ? "LINEAR" : "NEAREST");
        for (int i = -21; i < 30; i++) {
            float s = (i + 0.5f) / W;
            float d = lookup(read, s, 4.5f / W, 0.0f);
            int got = (int)lroundf(d * 16.0f) - 1, want = wrap(i, W);
            if (got != want) {
                printf("  column %3d (s = %+.6f, repetition %d): reads texel %d (%.6f), spec texel %d\n", i, s,
                       (int)floorf(s), got, d, want);
                n++;
            }
        }
        printf("  %d of 51 columns differ\n", n);
        if (n) bad = 1;
    }
    printf("glGetError: 0x%x\n", glGetError());
    return bad;
}
