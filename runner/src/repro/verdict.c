/* The verdict of the observed RGBA against the expectation's constants (TEST, SPEC_VALUE, ACCEPTED,
 * STRICT, GATHER_*, LAYOUTS, ...), shared by the GL and the Vulkan reproducers: prints expected and
 * observed and returns the exit status (0 inside the accepted set, 1 outside). */
static int in_set(double v, const double set[][2], int n) {
    for (int i = 0; i < n; i++)
        if (v >= set[i][0] && v <= set[i][1]) return 1;
    return 0;
}

/* Does channel value v meet LAYOUT's rule for channel c under the given set (a gather value
 * 'A'..'D': under its own set of `gather`)? */
static int channel_ok(char c, double v, const double set[][2], int n, const struct set gather[4]) {
    switch (c) {
    case 'r': return in_set(v, set, n);
    case 'z': return v == 0.0 || in_set(v, set, n);
    case '0': return v == 0.0;
    case '1': return v == 1.0;
    case 'A': case 'B': case 'C': case 'D': return in_set(v, gather[c - 'A'].v, gather[c - 'A'].n);
    default: return 1;
    }
}

static int judge(const float px[4]) {
    const char *names = "rgba";
    /* Accepted when one reading of the layout accepts every channel (each tier on its own). */
    int strict_ok = 0, ok = 0;
    for (int k = 0; k < N_LAYOUTS; k++) {
        int a = 1, s = 1;
        for (int i = 0; i < 4; i++) {
            a &= channel_ok(LAYOUTS[k][i], px[i], ACCEPTED, N_ACCEPTED, GATHER_ACCEPTED);
            s &= channel_ok(LAYOUTS[k][i], px[i], STRICT, N_STRICT, GATHER_STRICT);
        }
        ok |= a;
        strict_ok |= s;
    }
    printf("test:      %s\n", TEST);
    printf("expected:  %s (spec value); accepted: r in %s (strict: %s)\n", SPEC_VALUE, ACCEPTED_TEXT, STRICT_TEXT);
    if (GATHER_ACCEPTED_TEXT)
        printf("gather:    values 0..3 accepted in %s (strict: %s)\n", GATHER_ACCEPTED_TEXT, GATHER_STRICT_TEXT);
    printf("layout:    (%c, %c, %c, %c)  ('r' the result, '0'/'1' exactly, 'z' r or 0, '-' unused, 'A'..'D' gather "
           "value 0..3)\n",
           LAYOUT[0], LAYOUT[1], LAYOUT[2], LAYOUT[3]);
    for (int k = 1; k < N_LAYOUTS; k++)
        printf("           (%c, %c, %c, %c)  also accepted: the other reading %s\n", LAYOUTS[k][0], LAYOUTS[k][1],
               LAYOUTS[k][2], LAYOUTS[k][3], READINGS[k]);
    printf("observed:  (%.9g, %.9g, %.9g, %.9g)\n", px[0], px[1], px[2], px[3]);
    for (int k = 0; k < N_LAYOUTS && !ok; k++)
        for (int i = 0; i < 4; i++)
            if (!channel_ok(LAYOUTS[k][i], px[i], ACCEPTED, N_ACCEPTED, GATHER_ACCEPTED))
                printf("           %c = %.9g is outside what channel '%c' allows (%s reading)\n", names[i], px[i],
                       LAYOUTS[k][i], READINGS[k]);
    printf("verdict:   %s\n", !ok ? "FAIL (outside the accepted set: a \"shall\" is violated)"
                          : strict_ok ? "pass" : "warn (inside the accepted set, outside the strict tier)");
    return ok ? 0 : 1;
}
