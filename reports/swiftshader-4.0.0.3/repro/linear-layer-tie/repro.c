/* Standalone reproducer (no shadowcheck code): which array layer does a LINEAR shadow lookup of a
 * sampler2DArrayShadow use at layer coordinate r = 0.5?
 *
 * OpenGL ES 3.2 §8.14.2 (and GL 4.6 §8.14.2): for TEXTURE_MIN_FILTER/MAG_FILTER LINEAR the layer is
 *   l = clamp(floor(r + 1/2), 0, d - 1)            -> r = 0.5 selects layer 1
 * The round-to-nearest-even alternative of footnote 4 belongs to the NEAREST formula only
 * (clamp(RNE(r), 0, d - 1)), where layer 0 and layer 1 are both conforming at r = 0.5.
 *
 * The same holds for the mipmapped filters that filter LINEAR within a level (LINEAR_MIPMAP_*):
 * the third column minifies with textureGrad (lambda = 1, MAX_LEVEL 0).
 * Texture: 1x1x3 DEPTH_COMPONENT24, layer depths 0.2, 0.8, 0.4; compare LEQUAL, Dref = 0.6, so
 * layer 0 gives r = 0 and layer 1 gives r = 1. Build: sh build.sh; run: ./repro
 * This copy of ../../../mesa-22.3.6/repro/linear-layer-tie/ makes its context the EGL 1.4 way
 * (pbuffer) so that SwiftShader's own GLES and zink on SwiftShader Vulkan run it too.
 * Exit status: 1 if the LINEAR lookup at r = 0.5 returns layer 0 (outside the spec), 0 otherwise. */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>
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
static const char *FS = "#version 300 es\nprecision highp float; precision highp sampler2DArrayShadow;\n"
    "uniform sampler2DArrayShadow t; uniform float layer; uniform float dref; uniform float grad; out vec4 o;\n"
    "void main(){ o = vec4(textureGrad(t, vec4(0.5, 0.5, layer, dref), vec2(grad, 0.0), vec2(0.0, grad)), 0.0, 0.0, 1.0); }\n";

/* filter: the min and mag filter; for a mipmapped min filter the mag filter is LINEAR and the
 * gradients (2 texels per pixel: lambda = 1) make the lookup a minification; MAX_LEVEL 0, so level 0 is
 * filtered LINEAR within the level (LINEAR_MIPMAP_*). */
static float lookup(GLuint prog, GLenum filter, float layer) {
    int mip = filter == GL_LINEAR_MIPMAP_LINEAR || filter == GL_LINEAR_MIPMAP_NEAREST;
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, mip ? GL_LINEAR : filter);
    glUniform1f(glGetUniformLocation(prog, "grad"), mip ? 2.0f : 0.0f);
    glUniform1f(glGetUniformLocation(prog, "layer"), layer);
    glUniform1f(glGetUniformLocation(prog, "dref"), 0.6f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    unsigned char px[4];
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    return px[0] / 255.0f;
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

    /* Exact stored integers: d * (2^32 - 1) for UNSIGNED_INT data into DEPTH_COMPONENT24. */
    const GLuint depth[3] = {858993459u /* 0.2 */, 3435973836u /* 0.8 */, 1717986918u /* 0.4 */};
    GLuint tex;
    glGenTextures(1, &tex); glBindTexture(GL_TEXTURE_2D_ARRAY, tex);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT24, 1, 1, 3, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);

    GLuint prog = glCreateProgram();
    glAttachShader(prog, shader(GL_VERTEX_SHADER, VS));
    glAttachShader(prog, shader(GL_FRAGMENT_SHADER, FS));
    glLinkProgram(prog); glUseProgram(prog);
    glUniform1i(glGetUniformLocation(prog, "t"), 0);

    const float layers[] = {0.0f, 0.49f, 0.5f, 0.51f, 1.0f, 1.5f, 2.5f};
    printf("layer r | NEAREST: r (layer) | LINEAR: r (layer) | LINEAR_MIPMAP_LINEAR, minified: r (layer) | spec LINEAR layer floor(r+1/2)\n");
    int bad = 0;
    for (unsigned i = 0; i < sizeof layers / sizeof *layers; i++) {
        float l = layers[i];
        float n = lookup(prog, GL_NEAREST, l), li = lookup(prog, GL_LINEAR, l);
        float lml = lookup(prog, GL_LINEAR_MIPMAP_LINEAR, l);
        int spec = (int)(l + 0.5f); if (spec > 2) spec = 2;
        float want = spec == 1 ? 1.0f : 0.0f; /* layer 1 is the only one with 0.6 <= Dt */
        int off = (li > 0.5f) != (want > 0.5f), off_mip = (lml > 0.5f) != (want > 0.5f);
        printf("%7.2f | %4.1f (%s) | %4.1f (%s) | %4.1f (%s) | layer %d -> r = %.0f%s%s\n", l, n, n > 0.5f ? "1" : "0 or 2",
               li, li > 0.5f ? "1" : "0 or 2", lml, lml > 0.5f ? "1" : "0 or 2", spec, want,
               off ? "   <-- LINEAR differs from the spec" : "", off_mip ? "   <-- LINEAR_MIPMAP_LINEAR differs from the spec" : "");
        if (off || off_mip) bad = 1;
    }
    printf("glGetError: 0x%x\n", glGetError());
    return bad;
}
