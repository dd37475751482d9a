/* Shadow textureGather on a cube-map-array texture: four LEQUAL comparisons against refZ.
 *
 * Written by hand (no shadowcheck code) for the gather Fails of egl:softpipe:es3 (issue 16).
 * Build and run: sh build.sh (softpipe; GALLIUM_DRIVER=llvmpipe for comparison).
 *
 * Texture: DEPTH_COMPONENT32F cube map array, 4x4, 2 cubes (12 layer-faces); texel k of the
 * 192 holds (k + 0.5) / 192, so every texel differs. COMPARE_REF_TO_TEXTURE, LEQUAL, NEAREST,
 * CLAMP_TO_EDGE. Lookup: cube 1, face +Z (layer-face 10), face coordinates (s, t) = (1.75/4, 2.25/4):
 * direction (-0.125, -0.125, 1), so u - 1/2 = 1.25, v - 1/2 = 1.75: the LINEAR footprint is
 * i0 = 1, i1 = 2, j0 = 1, j1 = 2 (GL 4.6 / ES 3.2 §8.14.2).
 * The rule: "A four-component vector is then assembled by taking a single component from the
 * swizzled texture source colors of the four texels, in the order τi0j1, τi1j1, τi1j0, and τi0j0"
 * (ES 3.2 §8.14.2); "each of the four texel lookups perform a depth comparison against the depth
 * reference value passed in (refZ)" (GLSL ES 3.20 §8.9.4).
 * Exits 1 when any result differs from the four comparisons, 0 when all agree, 2 on setup errors.
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
#define IMAGES 12
#define FACE_LAYER 10 /* cube 1, face +Z */

static float value(int k) { return (float)((k + 0.5) / (16.0 * IMAGES)); }

static const char *VS = "#version 310 es\n"
                        "in vec2 a_pos;\n"
                        "void main() { gl_Position = vec4(a_pos, 0.0, 1.0); }\n";
static const char *FS = "#version 310 es\n"
                        "#extension GL_OES_texture_cube_map_array : require\n"
                        "precision highp float;\n"
                        "uniform highp samplerCubeArrayShadow u_tex;\n"
                        "uniform vec4 u_p;\n"
                        "uniform float u_ref;\n"
                        "out vec4 o;\n"
                        "void main() { o = textureGather(u_tex, u_p, u_ref); }\n";

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
    GLuint color, fbo, vao, vbo, tex;
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

    static float texels[W * W * IMAGES];
    for (int k = 0; k < W * W * IMAGES; k++) texels[k] = value(k);
    glActiveTexture(GL_TEXTURE0);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_CUBE_MAP_ARRAY, tex);
    glTexImage3D(GL_TEXTURE_CUBE_MAP_ARRAY, 0, GL_DEPTH_COMPONENT32F, W, W, IMAGES, 0, GL_DEPTH_COMPONENT,
                 GL_FLOAT, texels);
    glTexParameteri(GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    check("texture");

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
    /* +Z face: s = (sc/|ma| + 1)/2 with sc = rx, t = (tc/|ma| + 1)/2 with tc = -ry (Table 8.19). */
    glUniform4f(glGetUniformLocation(p, "u_p"), -0.125f, -0.125f, 1.0f, 1.0f);
    glViewport(0, 0, 1, 1);

    /* The footprint texels (x, y) in the result order τi0j1, τi1j1, τi1j0, τi0j0. */
    static const int xy[4][2] = {{1, 2}, {2, 2}, {2, 1}, {1, 1}};
    const double refs[3] = {166.0 / 192.0, 168.0 / 192.0, 170.0 / 192.0};
    int bad = 0;
    for (int r = 0; r < 3; r++) {
        glUniform1f(glGetUniformLocation(p, "u_ref"), (float)refs[r]);
        glClearColor(-1.0f, -1.0f, -1.0f, -1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        GLfloat px[4];
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, px);
        check("draw / readback");
        float want[4];
        for (int c = 0; c < 4; c++) {
            float dt = value(FACE_LAYER * W * W + xy[c][1] * W + xy[c][0]);
            want[c] = (float)refs[r] <= dt ? 1.0f : 0.0f; /* LEQUAL: pass when Dref <= Dt */
        }
        int same = memcmp(want, px, sizeof want) == 0;
        bad |= !same;
        printf("refZ %.9g: expected (%g, %g, %g, %g), observed (%g, %g, %g, %g)%s\n", refs[r], want[0], want[1],
               want[2], want[3], px[0], px[1], px[2], px[3], same ? "" : "  <- differs");
    }
    printf("verdict:   %s\n", bad ? "FAIL" : "pass");
    return bad ? 1 : 0;
}
