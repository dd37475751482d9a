static int in_set(double v, const double set[][2], int n) {
    for (int i = 0; i < n; i++)
        if (v >= set[i][0] && v <= set[i][1]) return 1;
    return 0;
}

/* Does channel value v meet LAYOUT's rule for channel c under the given set? */
static int channel_ok(char c, double v, const double set[][2], int n) {
    switch (c) {
    case 'r': return in_set(v, set, n);
    case 'z': return v == 0.0 || in_set(v, set, n);
    case '0': return v == 0.0;
    case '1': return v == 1.0;
    default: return 1;
    }
}

int main(void) {
    make_context();
    const char *glsl_text = (const char *)glGetString(GL_SHADING_LANGUAGE_VERSION);
    printf("GL_RENDERER: %s\nGL_VERSION: %s\nGL_SHADING_LANGUAGE_VERSION: %s\n", glGetString(GL_RENDERER),
           glGetString(GL_VERSION), glsl_text ? glsl_text : "(none)");
    int major = 0, minor = 0;
    if (glsl_text) {
        const char *d = glsl_text;
        while (*d && (*d < '0' || *d > '9')) d++;
        sscanf(d, "%d.%d", &major, &minor);
    }
    int glsl = major * 100 + minor;

    /* An RGBA32F colour buffer (results are not quantized), cleared to -1, which no lookup returns. */
    GLuint color, fbo, vao, vbo;
    glGenTextures(1, &color);
    glBindTexture(GL_TEXTURE_2D, color);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 16, 16, 0, GL_RGBA, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) die("RGBA32F framebuffer incomplete");
    glBindTexture(GL_TEXTURE_2D, 0);
    static const GLfloat tri[6] = {-1.0f, -1.0f, 3.0f, -1.0f, -1.0f, 3.0f};
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof tri, tri, GL_STATIC_DRAW);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 8, 0);
    glEnableVertexAttribArray(0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glDisable(GL_DITHER);
    glClearColor(-1.0f, -1.0f, -1.0f, -1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    check("framebuffer setup");

    make_texture();
    glViewport(0, 0, 1, 1);
    draw(glsl);
    GLfloat px[4];
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, px);
    check("glReadPixels");

    const char *names = "rgba";
    /* Accepted when one reading of the layout accepts every channel (each tier on its own). */
    int strict_ok = 0, ok = 0;
    for (int k = 0; k < N_LAYOUTS; k++) {
        int a = 1, s = 1;
        for (int i = 0; i < 4; i++) {
            a &= channel_ok(LAYOUTS[k][i], px[i], ACCEPTED, N_ACCEPTED);
            s &= channel_ok(LAYOUTS[k][i], px[i], STRICT, N_STRICT);
        }
        ok |= a;
        strict_ok |= s;
    }
    printf("test:      %s\n", TEST);
    printf("expected:  %s (spec value); accepted: r in %s (strict: %s)\n", SPEC_VALUE, ACCEPTED_TEXT, STRICT_TEXT);
    printf("layout:    (%c, %c, %c, %c)  ('r' the result, '0'/'1' exactly, 'z' r or 0, '-' unused)\n", LAYOUT[0],
           LAYOUT[1], LAYOUT[2], LAYOUT[3]);
    for (int k = 1; k < N_LAYOUTS; k++)
        printf("           (%c, %c, %c, %c)  also accepted: the other reading %s\n", LAYOUTS[k][0], LAYOUTS[k][1],
               LAYOUTS[k][2], LAYOUTS[k][3], READINGS[k]);
    printf("observed:  (%.9g, %.9g, %.9g, %.9g)\n", px[0], px[1], px[2], px[3]);
    for (int k = 0; k < N_LAYOUTS && !ok; k++)
        for (int i = 0; i < 4; i++)
            if (!channel_ok(LAYOUTS[k][i], px[i], ACCEPTED, N_ACCEPTED))
                printf("           %c = %.9g is outside what channel '%c' allows (%s reading)\n", names[i], px[i],
                       LAYOUTS[k][i], READINGS[k]);
    printf("verdict:   %s\n", !ok ? "FAIL (outside the accepted set: a \"shall\" is violated)"
                          : strict_ok ? "pass" : "warn (inside the accepted set, outside the strict tier)");
    return ok ? 0 : 1;
}
