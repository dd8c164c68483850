/* OpenGL of the raster plot device (plot_png): the OSMesa library is opened
 * with dlopen when the first PNG plot is made (udec_gl_load), not linked, so
 * a run that makes no PNG does not map it (nor libLLVM, which Mesa's
 * software rasteriser loads: about 45 MB resident, docs/performance.md).
 * Every OSMesa and GL entry point the device uses is called through a
 * pointer taken from that library. The state changes (page set-up, the
 * start of an item, the stencil passes) are one call from Fortran each;
 * the vertices stay in plot_png. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <GL/gl.h>

#ifndef UDEC_OSMESA_SONAME
#define UDEC_OSMESA_SONAME "libOSMesa.so.8"
#endif
#ifndef UDEC_OSMESA_PATH
#define UDEC_OSMESA_PATH "libOSMesa.so"
#endif

typedef void *(*create_ext_t)(GLenum, GLint, GLint, GLint, void *);
typedef GLboolean (*make_current_t)(void *, void *, GLenum, GLsizei, GLsizei);
typedef void (*destroy_t)(void *);

static void *library = NULL;
static create_ext_t p_create_ext;
static make_current_t p_make_current;
static destroy_t p_destroy;
static void (*p_viewport)(GLint, GLint, GLsizei, GLsizei);
static void (*p_matrix_mode)(GLenum);
static void (*p_load_identity)(void);
static void (*p_ortho)(GLdouble, GLdouble, GLdouble, GLdouble, GLdouble, GLdouble);
static void (*p_clear_color)(GLclampf, GLclampf, GLclampf, GLclampf);
static void (*p_clear_stencil)(GLint);
static void (*p_clear)(GLbitfield);
static void (*p_scissor)(GLint, GLint, GLsizei, GLsizei);
static void (*p_enable)(GLenum);
static void (*p_disable)(GLenum);
static void (*p_color3d)(GLdouble, GLdouble, GLdouble);
static void (*p_color_mask)(GLboolean, GLboolean, GLboolean, GLboolean);
static void (*p_stencil_func)(GLenum, GLint, GLuint);
static void (*p_stencil_op)(GLenum, GLenum, GLenum);
static void (*p_vertex2d)(GLdouble, GLdouble);
static void (*p_begin)(GLenum);
static void (*p_end)(void);
static void (*p_finish)(void);

static void copy_message(char *message, int message_len, const char *text)
{
    if (message_len > 0) snprintf(message, (size_t)message_len, "%s", text);
}

/* Open the OSMesa library once and take its entry points. Tried in order:
 * the file named by the environment variable UDEC_OSMESA_LIBRARY when set
 * (then only that), else the runtime name found when udec was built, then the
 * development link libOSMesa.so by name and by the path the build found.
 * Returns 0 when loaded; otherwise 1 with the reason in `message`. */
int udec_gl_load(char *message, int message_len)
{
    const char *names[4];
    int n = 0, i;
    const char *env = getenv("UDEC_OSMESA_LIBRARY");
    char text[1024];
    void *h = NULL;
    if (library) return 0;
    if (env && env[0]) {
        names[n++] = env;
    } else {
        names[n++] = UDEC_OSMESA_SONAME;
        names[n++] = "libOSMesa.so";
        names[n++] = UDEC_OSMESA_PATH;
    }
    for (i = 0; i < n && !h; i++) h = dlopen(names[i], RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        const char *why = dlerror();
        snprintf(text, sizeof text, "the OSMesa library could not be loaded (tried %s%s%s%s%s; "
                 "install Debian's libosmesa6, or set UDEC_OSMESA_LIBRARY to its file): %s",
                 names[0], n > 1 ? ", " : "", n > 1 ? names[1] : "", n > 2 ? ", " : "",
                 n > 2 ? names[2] : "", why ? why : "");
        copy_message(message, message_len, text);
        return 1;
    }
#define TAKE(ptr, name)                                                           \
    do {                                                                          \
        *(void **)(&ptr) = dlsym(h, name);                                        \
        if (!ptr) {                                                               \
            snprintf(text, sizeof text, "the OSMesa library has no entry point %s", \
                     name);                                                       \
            copy_message(message, message_len, text);                             \
            dlclose(h);                                                           \
            return 1;                                                             \
        }                                                                         \
    } while (0)
    TAKE(p_create_ext, "OSMesaCreateContextExt");
    TAKE(p_make_current, "OSMesaMakeCurrent");
    TAKE(p_destroy, "OSMesaDestroyContext");
    TAKE(p_viewport, "glViewport");
    TAKE(p_matrix_mode, "glMatrixMode");
    TAKE(p_load_identity, "glLoadIdentity");
    TAKE(p_ortho, "glOrtho");
    TAKE(p_clear_color, "glClearColor");
    TAKE(p_clear_stencil, "glClearStencil");
    TAKE(p_clear, "glClear");
    TAKE(p_scissor, "glScissor");
    TAKE(p_enable, "glEnable");
    TAKE(p_disable, "glDisable");
    TAKE(p_color3d, "glColor3d");
    TAKE(p_color_mask, "glColorMask");
    TAKE(p_stencil_func, "glStencilFunc");
    TAKE(p_stencil_op, "glStencilOp");
    TAKE(p_vertex2d, "glVertex2d");
    TAKE(p_begin, "glBegin");
    TAKE(p_end, "glEnd");
    TAKE(p_finish, "glFinish");
#undef TAKE
    library = h;
    return 0;
}

/* 1 when the OSMesa library is loaded in this process (tests). */
int udec_gl_loaded(void) { return library != NULL; }

/* The OSMesa calls of plot_png and plot_backends (udec_gl_load first). */
void *udec_osmesa_create(int format, int depth, int stencil, int accum)
{
    return p_create_ext((GLenum)format, depth, stencil, accum, NULL);
}

int udec_osmesa_make_current(void *ctx, void *buffer, int type, int width, int height)
{
    return p_make_current(ctx, buffer, (GLenum)type, width, height) ? 1 : 0;
}

void udec_osmesa_destroy(void *ctx) { p_destroy(ctx); }

void udec_gl_vertex2d(double x, double y) { p_vertex2d(x, y); }
void udec_gl_begin(int mode) { p_begin((GLenum)mode); }
void udec_gl_end(void) { p_end(); }
void udec_gl_finish(void) { p_finish(); }

/* A pw x ph pixel viewport showing page units 0..page_w by 0..page_h,
 * cleared to white with an empty stencil, and the scissor box (sx, sy,
 * sw, sh pixels) that clipped items are drawn through. */
void udec_gl_page(int pw, int ph, double page_w, double page_h,
                  int sx, int sy, int sw, int sh)
{
    p_viewport(0, 0, pw, ph);
    p_matrix_mode(GL_PROJECTION);
    p_load_identity();
    p_ortho(0.0, page_w, 0.0, page_h, -1.0, 1.0);
    p_matrix_mode(GL_MODELVIEW);
    p_load_identity();
    p_clear_color(1.0f, 1.0f, 1.0f, 1.0f);
    p_clear_stencil(0);
    p_clear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    p_scissor(sx, sy, sw, sh);
}

/* Start an item: clipped to the scissor box or not, in colour (r, g, b). */
void udec_gl_item(int clip, double r, double g, double b)
{
    if (clip)
        p_enable(GL_SCISSOR_TEST);
    else
        p_disable(GL_SCISSOR_TEST);
    p_color3d(r, g, b);
}

/* The passes of a fill (any simple polygon, by stencil parity). Pass 1: the
 * triangles drawn next only invert the stencil (a pixel covered an odd
 * number of times is inside). Pass 2: they paint the marked pixels and
 * clear the stencil behind them. Pass 0: the fill is done. */
void udec_gl_stencil(int pass)
{
    if (pass == 1) {
        p_enable(GL_STENCIL_TEST);
        p_color_mask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        p_stencil_func(GL_ALWAYS, 0, 1);
        p_stencil_op(GL_KEEP, GL_KEEP, GL_INVERT);
    } else if (pass == 2) {
        p_color_mask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        p_stencil_func(GL_EQUAL, 1, 1);
        p_stencil_op(GL_ZERO, GL_ZERO, GL_ZERO);
    } else {
        p_disable(GL_STENCIL_TEST);
    }
}
