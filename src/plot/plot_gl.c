/* OpenGL state changes of the raster plot device (plot_png), one call from
 * Fortran each: the page set-up, the start of an item (clipping, colour)
 * and the passes of a stencil fill. The vertices stay in plot_png. */
#include <GL/gl.h>

/* A pw x ph pixel viewport showing page units 0..page_w by 0..page_h,
 * cleared to white with an empty stencil, and the scissor box (sx, sy,
 * sw, sh pixels) that clipped items are drawn through. */
void udec_gl_page(int pw, int ph, double page_w, double page_h,
                  int sx, int sy, int sw, int sh)
{
    glViewport(0, 0, pw, ph);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, page_w, 0.0, page_h, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glScissor(sx, sy, sw, sh);
}

/* Start an item: clipped to the scissor box or not, in colour (r, g, b). */
void udec_gl_item(int clip, double r, double g, double b)
{
    if (clip)
        glEnable(GL_SCISSOR_TEST);
    else
        glDisable(GL_SCISSOR_TEST);
    glColor3d(r, g, b);
}

/* The passes of a fill (any simple polygon, by stencil parity). Pass 1: the
 * triangles drawn next only invert the stencil (a pixel covered an odd
 * number of times is inside). Pass 2: they paint the marked pixels and
 * clear the stencil behind them. Pass 0: the fill is done. */
void udec_gl_stencil(int pass)
{
    if (pass == 1) {
        glEnable(GL_STENCIL_TEST);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glStencilFunc(GL_ALWAYS, 0, 1);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
    } else if (pass == 2) {
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glStencilFunc(GL_EQUAL, 1, 1);
        glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO);
    } else {
        glDisable(GL_STENCIL_TEST);
    }
}
