/* Standalone reproducer (no shadowcheck code), sampler-object variant (issue 16): is a sized depth texture with COMPARE_MODE NONE and a
 * LINEAR filter incomplete in OpenGL ES?
 *
 * ES 3.0.6 §3.8.13 / ES 3.2 §8.17 (texture completeness): a texture is not complete if "the
 * internal format of the texture is a depth or depth-stencil format, the value of
 * TEXTURE_COMPARE_MODE is NONE, and either the magnification filter is not NEAREST or the
 * minification filter is neither NEAREST nor NEAREST_MIPMAP_NEAREST". Sampling an incomplete
 * texture returns (0, 0, 0, 1) (ES 3.2 §11.1.3.5).
 *
 * Texture: 1x1 DEPTH_COMPONENT24, depth 0.6 (stored 0.6 * (2^32 - 1) as UNSIGNED_INT), a
 * sampler2D lookup, r written to an RGBA8 renderbuffer. NEAREST: r = 0.6 (153/255); LINEAR: r = 0.
 * EGL 1.4 pbuffer context (runs on Mesa with EGL_PLATFORM=surfaceless and on SwiftShader).
 * This variant sets the texture to COMPARE_REF_TO_TEXTURE / NEAREST and binds a sampler object with
 * COMPARE_MODE NONE and the filter under test: ES 3.2 8.17.1 takes the sampling state from the
 * sampler object, so the rule above applies to its state. */
#include <EGL/egl.h>
#include <GLES3/gl3.h>
#include <stdio.h>
#include <stdlib.h>

static GLuint shader(GLenum type, const char *src) {
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) { fprintf(stderr, "compile failed\n"); exit(2); }
    return s;
}

static const char *VS = "#version 300 es\nvoid main(){ vec2 p = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1)) * 4.0 - 1.0; gl_Position = vec4(p, 0.0, 1.0); }\n";
static const char *FS = "#version 300 es\nprecision highp float; uniform highp sampler2D t; out vec4 o;\nvoid main(){ o = texture(t, vec2(0.5, 0.5)); }\n";

int main(void) {
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

    GLuint rb, fbo, tex, prog = glCreateProgram();
    glGenRenderbuffers(1, &rb); glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1, 1);
    glGenFramebuffers(1, &fbo); glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    glViewport(0, 0, 1, 1);
    const GLuint depth = 2576980377u; /* 0.6 */
    glGenTextures(1, &tex); glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 1, 1, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &depth);
    /* The texture's own state compares (complete with any filter); a bound sampler object with
     * COMPARE_MODE NONE supplies the sampling state (ES 3.2 8.17.1), so 8.17's rule applies to it. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    GLuint so; glGenSamplers(1, &so);
    glSamplerParameteri(so, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glBindSampler(0, so);
    glAttachShader(prog, shader(GL_VERTEX_SHADER, VS));
    glAttachShader(prog, shader(GL_FRAGMENT_SHADER, FS));
    glLinkProgram(prog); glUseProgram(prog);
    int bad = 0;
    const GLenum filters[2] = {GL_NEAREST, GL_LINEAR};
    for (int i = 0; i < 2; i++) {
        glSamplerParameteri(so, GL_TEXTURE_MIN_FILTER, filters[i]);
        glSamplerParameteri(so, GL_TEXTURE_MAG_FILTER, filters[i]);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        unsigned char px[4];
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        int want_r = i == 0 ? 153 : 0, want_a = 255;
        int ok = abs(px[0] - want_r) <= 1 && px[3] == want_a;
        printf("%-7s: rgba = (%3d, %3d, %3d, %3d) / 255; spec (%s): (%d, -, -, %d)%s\n", i ? "LINEAR" : "NEAREST",
               px[0], px[1], px[2], px[3], i ? "incomplete" : "complete", want_r, want_a, ok ? "" : "   <-- differs");
        bad |= !ok;
    }
    printf("glGetError: 0x%x\n", glGetError());
    return bad;
}
