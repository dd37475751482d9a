/* Shadow textureGather with a texture swizzle and a bound sampler object (the `interact` covering
 * array, gather x swizzle x sampler object).
 *
 * Written by hand (no shadowcheck code) for the Fails of egl:softpipe:es3
 * `gles32/{2d,cube}/d24/linear/lequal/interact/gather*+swizzle=gbar+sampler_object@es300`.
 * Build and run: sh build.sh (softpipe; DRIVER=llvmpipe for comparison).
 *
 * Texture: DEPTH_COMPONENT32F 2D, 4x4, texel (x, y) holds (4y + x + 0.5) / 16; texture state
 * COMPARE_REF_TO_TEXTURE, LEQUAL, LINEAR, CLAMP_TO_EDGE. Lookup: textureGather(sampler2DShadow,
 * (1.75/4, 2.25/4), refZ 0.5): footprint i0 = j0 = 1 (GL 4.6 / ES 3.2 §8.14.2), texels in result
 * order tau_i0j1, tau_i1j1, tau_i1j0, tau_i0j0 = 9.5/16, 10.5/16, 6.5/16, 5.5/16.
 * Five runs: swizzle identity or (GREEN, BLUE, ALPHA, RED); no sampler object or one bound whose
 * TEXTURE_COMPARE_FUNC is GEQUAL (otherwise the texture's state); and the swizzle with the
 * texture's own function GEQUAL, no sampler object.
 * The rules: "If a sampler object and a texture object are simultaneously bound to the same
 * texture unit, then the sampling state for that unit is taken from the sampler object" (ES 3.2
 * §8.17.1 / GL 4.6 §8.17.1); "A four-component vector is then assembled by taking a single
 * component from the swizzled texture source colors of the four texels" (§8.14.2: with
 * TEXTURE_SWIZZLE_R = GREEN that is 0 for each texel's (Rt, 0, 0, 1)); GLSL ES 3.20 §8.9.4 puts
 * the comparisons "in the appropriate component", so the unswizzled comparisons under the
 * effective function are accepted too (shadowcheck's contradiction `gather-swizzle`).
 * Exits 1 when a run matches neither reading, 0 when all do, 2 on setup errors.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl32.h>
#include <GLES2/gl2ext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void die(const char *what) {
    fprintf(stderr, "setup failed: %s\n", what);
    exit(2);
}

static void check(const char *what) {
    GLenum e = glGetError();
    if (e != GL_NO_ERROR) {
        fprintf(stderr, "setup failed: %s raised GL error 0x%04X\n", what, e);
        exit(2);
    }
}

/* The context, as shadowcheck's worker creates it (gl/src/context.rs). */
static void make_context(void) {
    EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, NULL, NULL)) die("eglInitialize (surfaceless)");
    if (!eglBindAPI(EGL_OPENGL_ES_API)) die("eglBindAPI");
    static const int versions[][2] = {{3, 2}, {3, 1}, {3, 0}};
    for (unsigned i = 0; i < sizeof versions / sizeof versions[0]; i++) {
        const EGLint attrs[] = {EGL_CONTEXT_MAJOR_VERSION, versions[i][0], EGL_CONTEXT_MINOR_VERSION, versions[i][1], EGL_NONE};
        EGLContext ctx = eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attrs);
        if (ctx == EGL_NO_CONTEXT) continue;
        if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) die("eglMakeCurrent (no surface)");
        printf("context:   asked for %d.%d\n", versions[i][0], versions[i][1]);
        return;
    }
    die("eglCreateContext: no version of this context kind");
}

#define W 4

static float value(int x, int y) { return (float)((4 * y + x + 0.5) / 16.0); }

static const char *VS = "#version 310 es\n"
                        "in vec2 a_pos;\n"
                        "void main() { gl_Position = vec4(a_pos, 0.0, 1.0); }\n";
static const char *FS = "#version 310 es\n"
                        "precision highp float;\n"
                        "uniform highp sampler2DShadow u_tex;\n"
                        "out vec4 o;\n"
                        "void main() { o = textureGather(u_tex, vec2(1.75 / 4.0, 2.25 / 4.0), 0.5); }\n";

static GLuint shader(GLenum type, const char *src) {
    GLuint sh = glCreateShader(type);
    glShaderSource(sh, 1, &src, NULL);
    glCompileShader(sh);
    GLint ok = 0;
    glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048];
        glGetShaderInfoLog(sh, sizeof log, NULL, log);
        fprintf(stderr, "shader compile failed: %s\n", log);
        exit(2);
    }
    return sh;
}

int main(void) {
    make_context();
    printf("GL_RENDERER: %s\nGL_VERSION: %s\n", glGetString(GL_RENDERER), glGetString(GL_VERSION));
    GLuint color, fbo, vao, vbo, tex, smp;
    static const GLfloat tri[6] = {-1.0f, -1.0f, 3.0f, -1.0f, -1.0f, 3.0f};
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof tri, tri, GL_STATIC_DRAW);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 8, 0);
    glEnableVertexAttribArray(0);
    glGenTextures(1, &color);
    glBindTexture(GL_TEXTURE_2D, color);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 1, 1, 0, GL_RGBA, GL_FLOAT, NULL);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) die("RGBA32F framebuffer");
    check("framebuffer setup");

    static float texels[W * W];
    for (int y = 0; y < W; y++)
        for (int x = 0; x < W; x++) texels[y * W + x] = value(x, y);
    glActiveTexture(GL_TEXTURE0);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, W, W, 0, GL_DEPTH_COMPONENT, GL_FLOAT, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    /* The sampler object: the texture's state but GEQUAL. */
    glGenSamplers(1, &smp);
    glSamplerParameteri(smp, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(smp, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(smp, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(smp, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(smp, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(smp, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
    check("texture and sampler");

    GLuint p = glCreateProgram();
    glAttachShader(p, shader(GL_VERTEX_SHADER, VS));
    glAttachShader(p, shader(GL_FRAGMENT_SHADER, FS));
    glBindAttribLocation(p, 0, "a_pos");
    glLinkProgram(p);
    GLint linked = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &linked);
    if (!linked) die("program link");
    glUseProgram(p);
    glUniform1i(glGetUniformLocation(p, "u_tex"), 0);
    glViewport(0, 0, 1, 1);

    static const int xy[4][2] = {{1, 2}, {2, 2}, {2, 1}, {1, 1}};
    const float ref = 0.5f;
    int bad = 0;
    for (int run = 0; run < 5; run++) {
        /* Runs 0-3: swizzle x sampler object; run 4: swizzle, no sampler object, the texture's own
         * function GEQUAL (is it the sampler object or the function?). */
        int swz = run == 4 || (run & 1), so = run == 2 || run == 3, texgeq = run == 4;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, texgeq ? GL_GEQUAL : GL_LEQUAL);
        GLint sw[4] = {GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA};
        if (swz) { sw[0] = GL_GREEN; sw[1] = GL_BLUE; sw[2] = GL_ALPHA; sw[3] = GL_RED; }
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_R, sw[0]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_G, sw[1]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_B, sw[2]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_A, sw[3]);
        glBindSampler(0, so ? smp : 0);
        glClearColor(-1.0f, -1.0f, -1.0f, -1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        GLfloat px[4];
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, px);
        check("draw / readback");
        float cmp[4], post[4];
        for (int c = 0; c < 4; c++) {
            float dt = value(xy[c][0], xy[c][1]);
            cmp[c] = (so || texgeq ? ref >= dt : ref <= dt) ? 1.0f : 0.0f;
            post[c] = swz ? 0.0f : cmp[c]; /* post-swizzle R of (Rt, 0, 0, 1) */
        }
        int ok = memcmp(post, px, sizeof px) == 0 || memcmp(cmp, px, sizeof px) == 0;
        bad |= !ok;
        printf("swizzle %-4s sampler object %-18s: expected (%g, %g, %g, %g) [or unswizzled (%g, %g, %g, %g)], "
               "observed (%g, %g, %g, %g)%s\n",
               swz ? "gbar" : "rgba", so ? "GEQUAL" : texgeq ? "none (tex GEQUAL)" : "none", post[0], post[1], post[2], post[3], cmp[0], cmp[1],
               cmp[2], cmp[3], px[0], px[1], px[2], px[3], ok ? "" : "  <- neither");
    }
    printf("verdict:   %s\n", bad ? "FAIL" : "pass");
    return bad ? 1 : 0;
}
