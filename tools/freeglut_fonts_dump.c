/* Dumps the GL calls the system's freeglut issues for every glyph of its fonts, as the input of
 * tools/gen_glut_fonts.py (which writes src/glut/bitmap_fonts.rs and src/glut/stroke_fonts.rs).
 *
 * The program defines the few GL entry points GLUT's text functions call (glBitmap, glBegin,
 * glVertex2f, glEnd, glTranslatef and the pixel-store calls around glBitmap); being in the
 * executable, they take precedence over libGL's for libglut's calls, so each glyph arrives here
 * exactly as freeglut would hand it to the driver. No GL context is made (glutInit only opens
 * the X display, which freeglut needs before its text functions run: use Xvfb or xvfb-run).
 *
 *     cc -O2 -rdynamic -o /tmp/fgdump tools/freeglut_fonts_dump.c -lglut
 *     xvfb-run -a /tmp/fgdump > /tmp/freeglut_fonts.txt
 *     python3 tools/gen_glut_fonts.py /tmp/freeglut_fonts.txt src/glut
 *
 * Output lines:
 *   BF <font> <glutBitmapHeight> <the font's name>
 *   B <font> <code> <width> <height> <xorig> <yorig> <xmove> <ymove> <hex bytes | ->
 *   SF <font> <glutStrokeHeight as %a> <the font's name>
 *   S <font> <code> <glutStrokeWidthf as %a>   (then the glyph's calls:)
 *   L <x as %a> <y as %a> ...                  one GL_LINE_STRIP Begin/End
 *   T <x as %a> <y as %a> <z as %a>            glTranslatef
 *   E                                          end of the glyph's calls
 * Any other GL call, or a Begin of another mode, stops the program with a message. */
#include <GL/freeglut.h>
#include <stdio.h>
#include <stdlib.h>

static int in_strip;

static void fail(const char *what) {
    fprintf(stderr, "freeglut_fonts_dump: unexpected call: %s\n", what);
    exit(1);
}

void glBitmap(GLsizei w, GLsizei h, GLfloat xorig, GLfloat yorig, GLfloat xmove, GLfloat ymove,
              const GLubyte *bits) {
    int i, n = (w + 7) / 8 * h;
    printf(" %d %d %a %a %a %a ", w, h, xorig, yorig, xmove, ymove);
    if (!bits || n == 0)
        putchar('-');
    for (i = 0; bits && i < n; i++)
        printf("%02x", bits[i]);
    putchar('\n');
}

void glPushClientAttrib(GLbitfield mask) {
    if (mask != GL_CLIENT_PIXEL_STORE_BIT)
        fail("glPushClientAttrib");
}
void glPopClientAttrib(void) {}
void glPixelStorei(GLenum pname, GLint param) {
    (void)pname;
    (void)param;
}
void glPixelStoref(GLenum pname, GLfloat param) {
    (void)pname;
    (void)param;
    fail("glPixelStoref");
}
void glGetIntegerv(GLenum pname, GLint *v) {
    (void)pname;
    (void)v;
    fail("glGetIntegerv");
}

void glBegin(GLenum mode) {
    if (mode != GL_LINE_STRIP || in_strip)
        fail("glBegin");
    in_strip = 1;
    printf("L");
}
void glVertex2f(GLfloat x, GLfloat y) {
    if (!in_strip)
        fail("glVertex2f");
    printf(" %a %a", x, y);
}
void glEnd(void) {
    if (!in_strip)
        fail("glEnd");
    in_strip = 0;
    printf("\n");
}
void glTranslatef(GLfloat x, GLfloat y, GLfloat z) { printf("T %a %a %a\n", x, y, z); }

/* freeglut's font structures start with the font's name (SFG_Font, SFG_StrokeFont in
 * fg_internal.h); only that first member is read here. */
struct named {
    const char *name;
};
extern struct named fgFontFixed8x13, fgFontFixed9x15, fgFontTimesRoman10, fgFontTimesRoman24,
    fgFontHelvetica10, fgFontHelvetica12, fgFontHelvetica18, fgStrokeRoman, fgStrokeMonoRoman;

int main(int argc, char **argv) {
    const struct named *const names[9] = {
        &fgFontFixed8x13,   &fgFontFixed9x15,   &fgFontTimesRoman10, &fgFontTimesRoman24,
        &fgFontHelvetica10, &fgFontHelvetica12, &fgFontHelvetica18,  &fgStrokeRoman,
        &fgStrokeMonoRoman,
    };
    void *const bitmap[7] = {
        GLUT_BITMAP_8_BY_13,        GLUT_BITMAP_9_BY_15,      GLUT_BITMAP_TIMES_ROMAN_10,
        GLUT_BITMAP_TIMES_ROMAN_24, GLUT_BITMAP_HELVETICA_10, GLUT_BITMAP_HELVETICA_12,
        GLUT_BITMAP_HELVETICA_18,
    };
    void *const stroke[2] = {GLUT_STROKE_ROMAN, GLUT_STROKE_MONO_ROMAN};
    int i, c;
    glutInit(&argc, argv);
    for (i = 0; i < 7; i++) {
        printf("BF %d %d %s\n", i, glutBitmapHeight(bitmap[i]), names[i]->name);
        for (c = 1; c < 256; c++) {
            printf("B %d %d", i, c);
            glutBitmapCharacter(bitmap[i], c);
        }
    }
    for (i = 0; i < 2; i++) {
        printf("SF %d %a %s\n", i, glutStrokeHeight(stroke[i]), names[7 + i]->name);
        for (c = 0; c < 256; c++) {
            printf("S %d %d %a\n", i, c, glutStrokeWidthf(stroke[i], c));
            glutStrokeCharacter(stroke[i], c);
            printf("E\n");
        }
    }
    return 0;
}
