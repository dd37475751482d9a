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
#ifdef COMPUTE_STAGE
    /* Immutable: the compute shader stores into it as an image (see COMPUTE_STAGE above). */
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, 16, 16);
#else
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 16, 16, 0, GL_RGBA, GL_FLOAT, NULL);
#endif
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

    return judge(px);
}
