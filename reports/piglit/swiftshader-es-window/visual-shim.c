/* libEGL.so.1 shim that lets waffle's x11_egl (piglit's window system in run.sh) open windows on
 * SwiftShader 4.0's own EGL 1.4 (run.sh, implementation swiftshader-es). It is linked to
 * SwiftShader's libEGL.so, which supplies every EGL function the shim does not define (waffle
 * dlopens libEGL.so.1 and looks its functions up in it and its dependencies).
 * Three answers are changed, all about the X window only (probe.c shows why they are needed):
 * - EGL_NATIVE_VISUAL_ID: SwiftShader answers values that name no X visual (0x2, 0x7fffffff), and
 *   waffle creates its colormap and window with that visual (BadMatch). The shim answers the X
 *   screen's default visual (depth 24 under run.sh's Xvfb), into whose windows SwiftShader renders.
 * - eglChooseConfig: SwiftShader lists R5G6B5 and alpha-less configs first for waffle's request;
 *   the shim keeps the configs with 8-bit red, green, blue and alpha (a subset of the matching
 *   configs, in SwiftShader's order), so that the window has 8 bits per channel (piglit's probe
 *   tolerances follow the window's bits).
 * - eglCreateWindowSurface: waffle asks for EGL_RENDER_BUFFER EGL_SINGLE_BUFFER where piglit
 *   wants a single-buffered visual (most tests), and SwiftShader refuses it (EGL_BAD_MATCH,
 *   "rendering directly to front buffer not supported"). The shim asks for EGL_BACK_BUFFER; an ES
 *   context reads and draws the window's only colour buffer either way, and piglit's -auto runs
 *   read back before any swap.
 * Nothing about contexts, textures or sampling is touched. */
#define _GNU_SOURCE
#include <EGL/egl.h>
#include <X11/Xlib.h>
#include <dlfcn.h>
#include <stdlib.h>

typedef EGLBoolean (*attrib_fn)(EGLDisplay, EGLConfig, EGLint, EGLint *);
typedef EGLBoolean (*choose_fn)(EGLDisplay, const EGLint *, EGLConfig *, EGLint, EGLint *);

static attrib_fn real_attrib(void) {
    static attrib_fn f;
    if (!f)
        f = (attrib_fn)dlsym(RTLD_NEXT, "eglGetConfigAttrib");
    return f;
}

EGLBoolean eglGetConfigAttrib(EGLDisplay dpy, EGLConfig config, EGLint attribute, EGLint *value) {
    static long visual;
    attrib_fn real = real_attrib();
    if (!real)
        return EGL_FALSE;
    EGLBoolean ok = real(dpy, config, attribute, value);
    if (ok && attribute == EGL_NATIVE_VISUAL_ID) {
        if (!visual) {
            Display *x = XOpenDisplay(NULL);
            if (x) {
                visual = (long)XVisualIDFromVisual(DefaultVisual(x, DefaultScreen(x)));
                XCloseDisplay(x);
            }
        }
        if (visual)
            *value = (EGLint)visual;
    }
    return ok;
}

EGLSurface eglCreateWindowSurface(EGLDisplay dpy, EGLConfig config, EGLNativeWindowType win,
                                  const EGLint *attribs) {
    typedef EGLSurface (*create_fn)(EGLDisplay, EGLConfig, EGLNativeWindowType, const EGLint *);
    static create_fn real;
    if (!real)
        real = (create_fn)dlsym(RTLD_NEXT, "eglCreateWindowSurface");
    if (!real)
        return EGL_NO_SURFACE;
    EGLint copy[64];
    int n = 0;
    for (; attribs && attribs[n] != EGL_NONE && n < 62; n += 2) {
        copy[n] = attribs[n];
        copy[n + 1] = attribs[n] == EGL_RENDER_BUFFER ? EGL_BACK_BUFFER : attribs[n + 1];
    }
    copy[n] = EGL_NONE;
    return real(dpy, config, win, copy);
}

EGLBoolean eglChooseConfig(EGLDisplay dpy, const EGLint *attribs, EGLConfig *configs,
                           EGLint size, EGLint *num) {
    static choose_fn real;
    if (!real)
        real = (choose_fn)dlsym(RTLD_NEXT, "eglChooseConfig");
    attrib_fn get = real_attrib();
    if (!real || !get || !num)
        return EGL_FALSE;
    EGLint all = 0;
    if (!real(dpy, attribs, NULL, 0, &all))
        return EGL_FALSE;
    EGLConfig *list = calloc(all ? (size_t)all : 1, sizeof *list);
    if (!list)
        return EGL_FALSE;
    if (!real(dpy, attribs, list, all, &all)) {
        free(list);
        return EGL_FALSE;
    }
    EGLint kept = 0;
    for (EGLint i = 0; i < all; i++) {
        EGLint r = 0, g = 0, b = 0, a = 0;
        get(dpy, list[i], EGL_RED_SIZE, &r);
        get(dpy, list[i], EGL_GREEN_SIZE, &g);
        get(dpy, list[i], EGL_BLUE_SIZE, &b);
        get(dpy, list[i], EGL_ALPHA_SIZE, &a);
        if (r != 8 || g != 8 || b != 8 || a != 8)
            continue;
        if (configs && kept < size)
            configs[kept] = list[i];
        if (configs && kept >= size)
            break;
        kept++;
    }
    free(list);
    *num = kept;
    return EGL_TRUE;
}
