/* Standalone reproducer (no shadowcheck code): mipmap level selection of cube-map lookups with
 * TEXTURE_CUBE_MAP_SEAMLESS disabled, as piglit's `tex-miplevel-selection GPU4texture() CubeShadow`,
 * `GPU4texture(bias) CubeShadow` and `GPU4textureGrad CubeShadow` draw them.
 *
 * State: compatibility context, TEXTURE_CUBE_MAP DEPTH_COMPONENT24 32x32 with 6 levels; on every
 * level L the -Y face holds (L + 1) / 10 and the other faces 0; MIN_FILTER NEAREST_MIPMAP_NEAREST,
 * MAG_FILTER NEAREST, TEXTURE_CUBE_MAP_SEAMLESS disabled (the default), then enabled.
 * Three units hold the same texture: `plain` (COMPARE_MODE NONE: the texel read names the level),
 * `lo` (COMPARE_REF_TO_TEXTURE, LESS, Dref = d - 0.05) and `hi` (GREATER, Dref = d + 0.05) with
 * d = (F + 1) / 10, so lo = hi = 1 exactly when level F is read (piglit multiplies them); lo = 1,
 * hi = 0 means a texel >= d + 0.05 (a higher level), lo = 0 one <= d - 0.05. The three lookups have
 * the same coordinates (and gradients), so the same lambda (GL 4.6 §8.14.1: rho is a function of
 * the coordinates' derivatives; compare state does not enter it).
 * Geometry (piglit's draw_quad): a 3x3 pixel quad with cube coordinates (2s - 1, -1, 2t - 1); the
 * probe is pixel (x + 1, y + 1), on the -Y face (sc = rx, tc = -rz, ma = ry: GL 4.6 §8.13 Table
 * 8.19, s = (sc/|ma| + 1) / 2, t likewise).
 * - implicit (texture()/shadowCube): s, t run from 0 to 3 * 2^F / 32 across the quad, so on -Y one
 *   pixel step changes u = 32 s by 2^F: lambda = F. For F = 4 the probe's 2x2 quad partner lies on
 *   +X (x + 1 even) and/or +Z (y + 1 even); F = 3 stays on -Y. How derivatives across a face edge
 *   enter rho is not said by GL 4.6 §8.14.1: these rows are reported, not judged (but the three
 *   lookups of one row must agree with each other).
 * - grad (textureGrad/shadowCubeGrad, piglit's derivatives): dPdx = (2 / (32 >> F), 0, 0),
 *   dPdy = (0, 0, 2 / (32 >> F)), s, t from 0 to 3/32 (every pixel on -Y): |du/dx| = |dv/dy| =
 *   2^F, the other two 0, so rho = 2^F (8.11), and an approximation f may lie in
 *   [max{mu, mv}, mu + mv] = [2^F, 2^(F+1)] (GL 4.6 §8.14.1): level F or F + 1 are both allowed.
 * - grad-x: the same with dPdy = 0: mu = 2^F, mv = mw = 0, so f = 2^F exactly, lambda = F and
 *   NEAREST_MIPMAP_NEAREST selects level F ("shall", GL 4.6 §8.14.1 conditions on f, §8.14.3).
 * Build and run: sh build.sh. Exit 1 if a grad-x row reads a level other than F (the rows the spec
 * decides); "<-- differs" marks every row that is not level F. */
#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SIZE 32
#define LEVELS 6

/* [implicit][version]: implicit lambda (texture / textureCube, shadowCube) or explicit gradients
 * (textureGrad / textureCubeGrad, shadowCubeGrad); GLSL 1.30, or 1.20 + EXT_gpu_shader4 where the
 * context is below GL 3.0 (zink on SwiftShader: GL 2.1), as piglit's GPU4 variants. */
static const char *fs[2][2] = {
    {"#version 130\n"
     "uniform samplerCube plain; uniform samplerCubeShadow lo, hi; uniform float d; uniform vec3 dx, dy;\n"
     "void main() { vec3 c = gl_TexCoord[0].xyz;\n"
     "  gl_FragColor = vec4(texture(plain, c).r, texture(lo, vec4(c, d - 0.05)), texture(hi, vec4(c, d + 0.05)), 1.0); }\n",
     "#version 120\n#extension GL_EXT_gpu_shader4 : require\n"
     "uniform samplerCube plain; uniform samplerCubeShadow lo, hi; uniform float d; uniform vec3 dx, dy;\n"
     "void main() { vec3 c = gl_TexCoord[0].xyz;\n"
     "  gl_FragColor = vec4(textureCube(plain, c).r, shadowCube(lo, vec4(c, d - 0.05)).r, shadowCube(hi, vec4(c, d + 0.05)).r, 1.0); }\n"},
    {"#version 130\n"
     "uniform samplerCube plain; uniform samplerCubeShadow lo, hi; uniform float d; uniform vec3 dx, dy;\n"
     "void main() { vec3 c = gl_TexCoord[0].xyz;\n"
     "  gl_FragColor = vec4(textureGrad(plain, c, dx, dy).r, textureGrad(lo, vec4(c, d - 0.05), dx, dy), textureGrad(hi, vec4(c, d + 0.05), dx, dy), 1.0); }\n",
     "#version 120\n#extension GL_EXT_gpu_shader4 : require\n"
     "uniform samplerCube plain; uniform samplerCubeShadow lo, hi; uniform float d; uniform vec3 dx, dy;\n"
     "void main() { vec3 c = gl_TexCoord[0].xyz;\n"
     "  gl_FragColor = vec4(textureCubeGrad(plain, c, dx, dy).r, shadowCubeGrad(lo, vec4(c, d - 0.05), dx, dy).r, shadowCubeGrad(hi, vec4(c, d + 0.05), dx, dy).r, 1.0); }\n"}};

static GLuint make_cube(GLenum mode, GLenum func) {
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_CUBE_MAP, t);
    float *buf = malloc(sizeof(float) * SIZE * SIZE);
    for (int l = 0, dim = SIZE; l < LEVELS; l++, dim /= 2)
        for (int f = 0; f < 6; f++) {
            float v = f == 3 ? (l + 1) / 10.0f : 0.0f; /* face 3 = NEGATIVE_Y */
            for (int i = 0; i < dim * dim; i++) buf[i] = v;
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, l, GL_DEPTH_COMPONENT24, dim, dim, 0,
                         GL_DEPTH_COMPONENT, GL_FLOAT, buf);
        }
    free(buf);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, LEVELS - 1);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_COMPARE_MODE, mode);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_COMPARE_FUNC, func);
    return t;
}

/* piglit's draw_quad: s, t from 0 to 3 * 2^F / 32 for implicit lambda (scaled so that the -Y
 * face's derivatives give lambda = F), 0 to 3 / 32 for explicit gradients (lambda from dx, dy). */
static void quad(int x, int y, int F, int grad) {
    float s1 = 3.0f * (grad ? 1 : 1 << F) / SIZE;
    float x0 = -1, z0 = -1, x1 = 2 * s1 - 1, z1 = 2 * s1 - 1;
    glBegin(GL_QUADS);
    glTexCoord3f(x0, -1, z0); glVertex2f(x, y);
    glTexCoord3f(x1, -1, z0); glVertex2f(x + 3, y);
    glTexCoord3f(x1, -1, z1); glVertex2f(x + 3, y + 3);
    glTexCoord3f(x0, -1, z1); glVertex2f(x, y + 3);
    glEnd();
}

int main(void) {
    PFNEGLGETPLATFORMDISPLAYEXTPROC getdpy = (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    EGLDisplay dpy = getdpy(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (!eglInitialize(dpy, NULL, NULL)) { fprintf(stderr, "eglInitialize failed\n"); return 2; }
    eglBindAPI(EGL_OPENGL_API);
    const EGLint attr[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attr);
    if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) { fprintf(stderr, "context failed\n"); return 2; }
    const char *ver = (const char *)glGetString(GL_VERSION);
    printf("GL_RENDERER: %s\nGL_VERSION: %s\n", glGetString(GL_RENDERER), ver);

    GLuint rb, fbo;
    glGenRenderbuffers(1, &rb); glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 16, 16);
    glGenFramebuffers(1, &fbo); glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) { fprintf(stderr, "fbo incomplete\n"); return 2; }
    glViewport(0, 0, 16, 16);
    glMatrixMode(GL_PROJECTION); glLoadIdentity(); glOrtho(0, 16, 0, 16, -1, 1);
    glMatrixMode(GL_MODELVIEW); glLoadIdentity();

    GLuint progs[2];
    for (int g = 0; g < 2; g++) {
        const char *src = fs[g][ver[0] >= '3' ? 0 : 1];
        GLuint sh = glCreateShader(GL_FRAGMENT_SHADER);
        glShaderSource(sh, 1, &src, NULL); glCompileShader(sh);
        GLint ok; glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
        if (!ok) { char log[2048]; glGetShaderInfoLog(sh, sizeof log, NULL, log); fprintf(stderr, "compile: %s\n", log); return 2; }
        GLuint prog = glCreateProgram(); glAttachShader(prog, sh); glLinkProgram(prog);
        glGetProgramiv(prog, GL_LINK_STATUS, &ok);
        if (!ok) { fprintf(stderr, "link failed\n"); return 2; }
        glUseProgram(prog);
        glUniform1i(glGetUniformLocation(prog, "plain"), 0);
        glUniform1i(glGetUniformLocation(prog, "lo"), 1);
        glUniform1i(glGetUniformLocation(prog, "hi"), 2);
        progs[g] = prog;
    }

    glActiveTexture(GL_TEXTURE0); make_cube(GL_NONE, GL_LEQUAL);
    glActiveTexture(GL_TEXTURE1); make_cube(GL_COMPARE_REF_TO_TEXTURE, GL_LESS);
    glActiveTexture(GL_TEXTURE2); make_cube(GL_COMPARE_REF_TO_TEXTURE, GL_GREATER);

    int bad = 0;
    printf("lookup    seamless  F  quad(x,y)  partner-x      partner-y      plain (level)  lo hi  expected\n");
    /* grad 0: implicit; 1: piglit's gradients along x (dx) and z (dy); 2: dx only, dy = 0 */
    for (int grad = 0; grad < 3; grad++) {
        GLuint prog = progs[grad ? 1 : 0];
        glUseProgram(prog);
        for (int seamless = 0; seamless < 2; seamless++) {
            if (seamless) glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS); else glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
            for (int F = grad ? 0 : 3; F <= 4; F++)
                for (int q = 0; q < 4; q++) {
                    int x = (q & 1) ? 3 : 0, y = (q & 2) ? 3 : 0;
                    /* piglit's explicit cube derivatives: 2 / (32 >> F) along x (dx) and z (dy) */
                    float deriv = 2.0f / (SIZE >> F);
                    glUniform3f(glGetUniformLocation(prog, "dx"), deriv, 0, 0);
                    glUniform3f(glGetUniformLocation(prog, "dy"), 0, 0, grad == 2 ? 0 : deriv);
                    glUniform1f(glGetUniformLocation(prog, "d"), (F + 1) / 10.0f);
                    glClearColor(0.5f, 0.5f, 0.5f, 0.5f); glClear(GL_COLOR_BUFFER_BIT);
                    quad(x, y, F, grad);
                    unsigned char px[4];
                    glReadPixels(x + 1, y + 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
                    float plain = px[0] / 255.0f;
                    int level = (int)(plain * 10 + 0.5f) - 1;
                    int lo = px[1] > 127, hi = px[2] > 127, shadow = lo && hi;
                    int wrong = level != F || !shadow;
                    if (grad == 2)
                        bad |= wrong;
                    /* the partner pixel centre's cube coordinate: x + 0.5 (before) or x + 2.5 (after) */
                    float step = 2.0f * (grad ? 1 : 1 << F) / SIZE;
                    float px_ = ((x + 1) % 2) ? -1 + 0.5f * step : -1 + 2.5f * step;
                    float pz_ = ((y + 1) % 2) ? -1 + 0.5f * step : -1 + 2.5f * step;
                    printf("%-8s  %-8s  %d  (%d,%d)      %-14s %-14s %.3f (%d)      %d  %d   level %d, 1 1%s\n",
                           grad == 2 ? "grad-x" : grad ? "grad" : "implicit", seamless ? "on" : "off", F, x, y,
                           px_ > 1 ? "+X face" : "-Y face", pz_ > 1 ? "+Z face" : "-Y face",
                           plain, level, lo, hi, F, wrong ? "   <-- differs" : "");
                }
        }
    }
    return bad ? 1 : 0;
}
