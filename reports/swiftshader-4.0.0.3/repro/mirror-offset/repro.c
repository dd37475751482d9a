/* Standalone reproducer (no shadowcheck code): which texel does a NEAREST lookup with a texel offset
 * read under TEXTURE_WRAP_S/T = MIRRORED_REPEAT?
 *
 * OpenGL ES 3.2 §8.14.2 (and GL 4.6 §8.14.2, equation (8.10)): the offset is added to the texel
 * coordinates before the wrap: u = w_s * s + δu, i = wrap(floor(u)), and Table 8.20 gives
 *   MIRRORED_REPEAT: (size - 1) - mirror((coord mod (2 * size)) - size),
 *   mirror(a) = a if a >= 0, else -(1 + a).
 * So on a 4x4 texture, from texel (1, 2) with offset (-8, 7): x = -7 -> 1, y = 9 -> 1: texel (1, 1);
 * with offset (7, -8): x = 8 -> 0, y = -6 -> 2: texel (0, 2). The program prints every offset.
 *
 * Texture: 4x4 DEPTH_COMPONENT24, texel (x, y) holds depth (4y + x + 0.5) / 16, read with a
 * non-shadow sampler2D (COMPARE_MODE NONE) so that the value read names the texel (a shadow
 * lookup addresses texels the same way, §8.14.2 before §8.23.1). Build: sh build.sh.
 * Exit status: 1 if any offset reads another texel than the spec's, 0 otherwise. */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>
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

static const char *VS = "#version 300 es\nvoid main(){ vec2 p = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1)) * 4.0 - 1.0; gl_Position = vec4(p, 0.0, 1.0); }\n";
/* One program per offset: textureOffset takes a constant expression. */
static GLuint program(int dx, int dy) {
    char fs[512];
    snprintf(fs, sizeof fs, "#version 300 es\nprecision highp float;\n"
        "uniform highp sampler2D t; out vec4 o;\n"
        "void main(){ o = vec4(textureOffset(t, vec2(1.5 / 4.0, 2.5 / 4.0), ivec2(%d, %d)).r, 0.0, 0.0, 1.0); }\n", dx, dy);
    GLuint p = glCreateProgram();
    glAttachShader(p, shader(GL_VERTEX_SHADER, VS));
    glAttachShader(p, shader(GL_FRAGMENT_SHADER, fs));
    glLinkProgram(p);
    return p;
}

static int mirror_index(int coord, int size) {
    int m = ((coord % (2 * size)) + 2 * size) % (2 * size) - size;
    int a = m >= 0 ? m : -(1 + m);
    return (size - 1) - a;
}

int main(void) {
    /* EGL 1.4: default display, a pbuffer config, a 16x16 pbuffer (SwiftShader has no surfaceless
     * platform and no config-less contexts; Mesa runs this with EGL_PLATFORM=surfaceless). */
    EGLDisplay dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (!eglInitialize(dpy, NULL, NULL)) { fprintf(stderr, "eglInitialize failed\n"); return 2; }
    const EGLint cfg_attr[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, 0x40 /* ES3 */, EGL_NONE};
    EGLConfig cfg; EGLint n = 0;
    if (!eglChooseConfig(dpy, cfg_attr, &cfg, 1, &n) || n < 1) { fprintf(stderr, "no config\n"); return 2; }
    const EGLint pb_attr[] = {EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE};
    EGLSurface pb = eglCreatePbufferSurface(dpy, cfg, pb_attr);
    eglBindAPI(EGL_OPENGL_ES_API);
    const EGLint ctx_attr[] = {EGL_CONTEXT_CLIENT_VERSION, 3, EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, ctx_attr);
    if (pb == EGL_NO_SURFACE || ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, pb, pb, ctx)) { fprintf(stderr, "context failed\n"); return 2; }
    printf("GL_RENDERER: %s\nGL_VERSION: %s\n", glGetString(GL_RENDERER), glGetString(GL_VERSION));

    GLuint rb, fbo;
    glGenRenderbuffers(1, &rb); glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1, 1);
    glGenFramebuffers(1, &fbo); glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    glViewport(0, 0, 1, 1);

    GLint omin = 0, omax = 0;
    glGetIntegerv(GL_MIN_PROGRAM_TEXEL_OFFSET, &omin);
    glGetIntegerv(GL_MAX_PROGRAM_TEXEL_OFFSET, &omax);
    printf("MIN/MAX_PROGRAM_TEXEL_OFFSET: %d %d\n", omin, omax);


    GLuint depth[16];
    for (int k = 0; k < 16; k++) depth[k] = (GLuint)(((k + 0.5) / 16.0) * 4294967295.0);
    GLuint tex;
    glGenTextures(1, &tex); glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 4, 4, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);

    const int offs[][2] = {{1, 0}, {0, 1}, {-1, -1}, {2, -1}, {-2, 1}, {3, 2}, {-4, -3}, {-8, 7}, {7, -8}};
    printf("offset | texel read (x,y) | spec texel (x,y)\n");
    int bad = 0;
    for (unsigned i = 0; i < sizeof offs / sizeof *offs; i++) {
        GLuint p = program(offs[i][0], offs[i][1]);
        glUseProgram(p);
        glUniform1i(glGetUniformLocation(p, "t"), 0);
        glClear(GL_COLOR_BUFFER_BIT);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        unsigned char px[4];
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        int k = (int)floor(px[0] / 255.0 * 16.0);
        int sx = mirror_index(1 + offs[i][0], 4), sy = mirror_index(2 + offs[i][1], 4);
        int differs = k != 4 * sy + sx;
        printf("%3d,%3d | (%d,%d) | (%d,%d)%s\n", offs[i][0], offs[i][1], k % 4, k / 4, sx, sy,
               differs ? "   <-- differs from Table 8.20" : "");
        bad |= differs;
    }
    printf("glGetError: 0x%x\n", glGetError());
    return bad;
}
