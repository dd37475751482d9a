/* Why piglit (waffle 1.7, platform x11_egl) cannot open a window on SwiftShader 4.0's own EGL 1.4.
 * waffle's x11_egl window takes the visual from eglGetConfigAttrib(EGL_NATIVE_VISUAL_ID) and
 * creates an X colormap and window with it. This program does the same steps with no waffle and
 * no piglit, asks for a single-buffered window surface as waffle does for most piglit tests, and
 * then renders through a back-buffered X window of the screen's default visual instead.
 * Build and run: sh build.sh (needs Xvfb; loads SwiftShader's libEGL.so / libGLESv2.so). */
#include <EGL/egl.h>
#include <GLES2/gl2.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdio.h>
#include <stdlib.h>

static int x_error;
static int on_x_error(Display *d, XErrorEvent *e) {
    (void)d;
    x_error = e->error_code;
    return 0;
}

int main(void) {
    Display *x = XOpenDisplay(NULL);
    if (!x) { printf("XOpenDisplay failed\n"); return 2; }
    XSetErrorHandler(on_x_error);
    EGLDisplay dpy = eglGetDisplay((EGLNativeDisplayType)x);
    EGLint maj = 0, min = 0;
    if (!eglInitialize(dpy, &maj, &min)) { printf("eglInitialize failed 0x%x\n", eglGetError()); return 2; }
    printf("EGL_VERSION     %s\n", eglQueryString(dpy, EGL_VERSION));
    printf("EGL_VENDOR      %s\n", eglQueryString(dpy, EGL_VENDOR));
    printf("EGL_CLIENT_APIS %s\n", eglQueryString(dpy, EGL_CLIENT_APIS));
    printf("EGL_EXTENSIONS  %s\n", eglQueryString(dpy, EGL_EXTENSIONS));
    printf("client extensions (EGL_NO_DISPLAY): %s\n", eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS));
    printf("eglGetProcAddress(eglGetPlatformDisplay) %p, (eglGetPlatformDisplayEXT) %p\n",
           (void *)eglGetProcAddress("eglGetPlatformDisplay"),
           (void *)eglGetProcAddress("eglGetPlatformDisplayEXT"));
    printf("X default visual 0x%lx depth %d\n",
           XVisualIDFromVisual(DefaultVisual(x, DefaultScreen(x))), DefaultDepth(x, DefaultScreen(x)));

    /* The config waffle asks for in piglit's GLES tests: RGBA8, window surface, ES2 renderable. */
    EGLint attrs[] = {EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                      EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT,
                      EGL_NONE};
    EGLConfig cfgs[64];
    EGLint n = 0;
    eglChooseConfig(dpy, attrs, cfgs, 64, &n);
    printf("eglChooseConfig(RGBA8, WINDOW_BIT, ES2): %d configs\n", n);
    int bad = 0;
    for (int i = 0; i < n; i++) {
        EGLint id, vid, vtype, depth, r, a;
        eglGetConfigAttrib(dpy, cfgs[i], EGL_CONFIG_ID, &id);
        eglGetConfigAttrib(dpy, cfgs[i], EGL_NATIVE_VISUAL_ID, &vid);
        eglGetConfigAttrib(dpy, cfgs[i], EGL_NATIVE_VISUAL_TYPE, &vtype);
        eglGetConfigAttrib(dpy, cfgs[i], EGL_DEPTH_SIZE, &depth);
        eglGetConfigAttrib(dpy, cfgs[i], EGL_RED_SIZE, &r);
        eglGetConfigAttrib(dpy, cfgs[i], EGL_ALPHA_SIZE, &a);
        XVisualInfo tmpl = {.visualid = (VisualID)(unsigned)vid};
        int nv = 0;
        XVisualInfo *vi = XGetVisualInfo(x, VisualIDMask, &tmpl, &nv);
        printf("  config %d: R%d A%d depth %d EGL_NATIVE_VISUAL_ID 0x%x EGL_NATIVE_VISUAL_TYPE 0x%x: "
               "X visual %s\n", id, r, a, depth, vid, vtype, nv ? "exists" : "does not exist");
        if (vi) XFree(vi);
        if (!nv) bad++;
    }
    if (n == 0) return 2;

    /* waffle's step: a colormap for the config's native visual. */
    EGLint vid;
    eglGetConfigAttrib(dpy, cfgs[0], EGL_NATIVE_VISUAL_ID, &vid);
    XVisualInfo tmpl = {.visualid = (VisualID)(unsigned)vid};
    int nv = 0;
    XVisualInfo *vi = XGetVisualInfo(x, VisualIDMask, &tmpl, &nv);
    if (!vi) {
        printf("waffle's path: no X visual 0x%x, so a colormap for it is BadMatch (error 0x8; "
               "piglit: \"xcb_create_colormap() failed on visual_id=... with error=0x8\")\n", vid);
    }

    /* waffle's window surface for a single-buffered piglit visual: EGL_RENDER_BUFFER SINGLE. */
    Window w1 = XCreateSimpleWindow(x, DefaultRootWindow(x), 0, 0, 64, 64, 0, 0, 0);
    XSync(x, False);
    EGLint single[] = {EGL_RENDER_BUFFER, EGL_SINGLE_BUFFER, EGL_NONE};
    EGLSurface s1 = eglCreateWindowSurface(dpy, cfgs[0], (EGLNativeWindowType)w1, single);
    printf("default-visual window, EGL_RENDER_BUFFER EGL_SINGLE_BUFFER: surface %s, error 0x%x%s\n",
           s1 == EGL_NO_SURFACE ? "none" : "created", eglGetError(),
           s1 == EGL_NO_SURFACE ? " (0x3009 = EGL_BAD_MATCH)" : "");

    /* The same config through a window of the default visual: does SwiftShader render into X? */
    Window w = XCreateSimpleWindow(x, DefaultRootWindow(x), 0, 0, 64, 64, 0, 0, 0);
    XSync(x, False);
    EGLSurface s = eglCreateWindowSurface(dpy, cfgs[0], (EGLNativeWindowType)w, NULL);
    EGLint cattrs[] = {EGL_CONTEXT_CLIENT_VERSION, 3, EGL_NONE};
    EGLContext c = eglCreateContext(dpy, cfgs[0], EGL_NO_CONTEXT, cattrs);
    if (s == EGL_NO_SURFACE || c == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, s, s, c)) {
        printf("default-visual window: surface %p context %p error 0x%x\n", s, c, eglGetError());
        return 1;
    }
    glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    unsigned char px[4] = {0};
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    printf("default-visual window: GL_RENDERER %s, GL_VERSION %s, clear read back %u %u %u %u\n",
           glGetString(GL_RENDERER), glGetString(GL_VERSION), px[0], px[1], px[2], px[3]);
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglTerminate(dpy);
    printf("%d of %d configs name an X visual that does not exist\n", bad, n);
    return bad ? 1 : 0;
}
