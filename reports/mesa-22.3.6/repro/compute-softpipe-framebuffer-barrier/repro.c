/* A compute shader's imageStore into a texture that is the colour attachment of the bound
 * framebuffer, read back by glReadPixels after glMemoryBarrier(GL_ALL_BARRIER_BITS).
 *
 * Written by hand (no shadowcheck code) for the compute-stage cases on egl:softpipe:es3, which
 * read the framebuffer's clear colour instead of the stored result.
 * Build and run: sh build.sh (softpipe; DRIVER=llvmpipe for comparison; ARGS=unbind to unbind
 * the framebuffer around the dispatch, as shadowcheck's worker does).
 *
 * The rule: ES 3.2 / GL 4.6, "Shader Memory Access Synchronization", MemoryBarrier,
 * FRAMEBUFFER_BARRIER_BIT: "Reads and writes via framebuffer object attachments after the
 * barrier will reflect data written by shaders prior to the barrier." glReadPixels reads the attachment after the barrier, so it must
 * see (0.25, 0.5, 0.75, 1).
 * Exits 1 when the pixel read back is not the stored value, 0 when it is, 2 on setup errors.
 */
#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl32.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void die(const char *what) {
    fprintf(stderr, "setup failed: %s (GL error 0x%04X)\n", what, glGetError());
    exit(2);
}

static const char *CS = "#version 310 es\n"
                        "precision highp float;\n"
                        "layout(local_size_x = 1) in;\n"
                        "layout(rgba32f, binding = 0) writeonly uniform highp image2D u_out;\n"
                        "void main() { imageStore(u_out, ivec2(2, 3), vec4(0.25, 0.5, 0.75, 1.0)); }\n";

int main(int argc, char **argv) {
    int unbind = argc > 1 && strcmp(argv[1], "unbind") == 0;
    EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, NULL, NULL)) die("eglInitialize (surfaceless)");
    if (!eglBindAPI(EGL_OPENGL_ES_API)) die("eglBindAPI");
    const EGLint attrs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 1, EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attrs);
    if (ctx == EGL_NO_CONTEXT) die("eglCreateContext (ES 3.1)");
    if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) die("eglMakeCurrent");
    printf("context:   %s | %s\n", glGetString(GL_RENDERER), glGetString(GL_VERSION));

    /* An immutable 8x8 RGBA32F texture (BindImageTexture needs one on ES), the framebuffer's
     * colour attachment, cleared to -1. */
    GLuint tex, fb;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, 8, 8);
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) die("framebuffer");
    glClearColor(-1, -1, -1, -1);
    glClear(GL_COLOR_BUFFER_BIT);

    GLuint sh = glCreateShader(GL_COMPUTE_SHADER);
    glShaderSource(sh, 1, &CS, NULL);
    glCompileShader(sh);
    GLint ok = 0;
    glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) die("compute shader compile");
    GLuint prog = glCreateProgram();
    glAttachShader(prog, sh);
    glLinkProgram(prog);
    glGetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok) die("program link");
    glUseProgram(prog);
    glBindImageTexture(0, tex, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);

    if (unbind) glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    if (unbind) glBindFramebuffer(GL_FRAMEBUFFER, fb);
    if (glGetError() != GL_NO_ERROR) die("dispatch");

    float px[4];
    glReadPixels(2, 3, 1, 1, GL_RGBA, GL_FLOAT, px);
    printf("framebuffer %s during the dispatch\n", unbind ? "unbound" : "bound");
    printf("read:      (%g, %g, %g, %g)\nexpected:  (0.25, 0.5, 0.75, 1)\n", px[0], px[1], px[2], px[3]);
    int same = px[0] == 0.25f && px[1] == 0.5f && px[2] == 0.75f && px[3] == 1.0f;
    printf("%s\n", same ? "PASS" : "FAIL: glReadPixels does not see the image store");
    return same ? 0 : 1;
}
