/* The independent check of fixedgl's GLUT bitmap fonts: draws every glyph of every GLUT bitmap
 * font with the system's real freeglut (on Mesa, under Xvfb) and writes what it drew, glyph by
 * glyph, to the file named by argv[1]:
 *
 *   H <font> <glutBitmapHeight>
 *   C <font> <code> <glutBitmapWidth> <raster x advance> <W*H '0'/'1' pixels, rows bottom-up>
 *   S <font> <W*H pixels of glutBitmapString(font, STRING)>
 *   SH <stroke font> <glutStrokeHeight (float bits, hex)>
 *   SC <stroke font> <code> <glutStrokeWidth> <glutStrokeWidthf (float bits, hex)>
 *      <modelview x translation after the glyph (float bits, hex)> <W*H pixels>
 *   SL <stroke font> <glutStrokeLength(STRING)> <glutStrokeLengthf(STRING) (float bits, hex)>
 *   SS <stroke font> <SW*SH pixels of glutStrokeString(font, STRING)>
 *
 * Each glyph is drawn alone at raster position (4.5, 8.5) of a W x H window under a pixel
 * ortho projection, and read back with glReadPixels (a pixel is '1' where red > 127). Each
 * stroke glyph (codes 1..=255) is drawn alone under glTranslatef(STX, STY, 0) and
 * glScalef(SCALE, SCALE, 1); the stroke string at (4.5, 40.5) under glScalef(SSCALE, SSCALE, 1). */
#include <GL/freeglut.h>
#include <stdio.h>
#include <string.h>

#define W 48
#define H 40
#define SW 256
#define SH 64
#define STRING "Hello GLUT\nline two 0123"
#define STX 4.25f
#define STY 10.25f
#define SCALE 0.25f
#define SSCALE 0.125f

static void *const fonts[7] = {
    GLUT_BITMAP_8_BY_13,       GLUT_BITMAP_9_BY_15,      GLUT_BITMAP_TIMES_ROMAN_10,
    GLUT_BITMAP_TIMES_ROMAN_24, GLUT_BITMAP_HELVETICA_10, GLUT_BITMAP_HELVETICA_12,
    GLUT_BITMAP_HELVETICA_18,
};

static void *const strokes[2] = {GLUT_STROKE_ROMAN, GLUT_STROKE_MONO_ROMAN};

static unsigned char px[SW * SH * 4];

/* A float's bits, for exact comparison. */
static unsigned bits(GLfloat v) {
    unsigned u;
    memcpy(&u, &v, sizeof u);
    return u;
}

static void dump(FILE *f, int w, int h) {
    int i;
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, px);
    for (i = 0; i < w * h; i++)
        fputc(px[4 * i] > 127 ? '1' : '0', f);
    fputc('\n', f);
}

int main(int argc, char **argv) {
    FILE *f;
    int i, c;
    GLfloat pos[4];
    if (argc < 2)
        return 2;
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGBA);
    glutInitWindowSize(SW, SH);
    glutCreateWindow("freeglut glyphs");
    f = fopen(argv[1], "w");
    if (!f)
        return 3;
    glViewport(0, 0, SW, SH);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, SW, 0, SH, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 1);
    glColor3f(1, 1, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (i = 0; i < 7; i++) {
        fprintf(f, "H %d %d\n", i, glutBitmapHeight(fonts[i]));
        for (c = 1; c < 256; c++) {
            glClear(GL_COLOR_BUFFER_BIT);
            glRasterPos2f(4.5f, 8.5f);
            glutBitmapCharacter(fonts[i], c);
            glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
            glFinish();
            fprintf(f, "C %d %d %d %g ", i, c, glutBitmapWidth(fonts[i], c), pos[0] - 4.5f);
            dump(f, W, H);
        }
        glClear(GL_COLOR_BUFFER_BIT);
        glRasterPos2f(4.5f, 40.5f);
        glutBitmapString(fonts[i], (const unsigned char *)STRING);
        glFinish();
        fprintf(f, "S %d ", i);
        dump(f, SW, SH);
    }
    for (i = 0; i < 2; i++) {
        fprintf(f, "SH %d %08x\n", i, bits(glutStrokeHeight(strokes[i])));
        for (c = 1; c < 256; c++) {
            GLfloat m[16];
            glClear(GL_COLOR_BUFFER_BIT);
            glLoadIdentity();
            glTranslatef(STX, STY, 0);
            glScalef(SCALE, SCALE, 1);
            glutStrokeCharacter(strokes[i], c);
            glGetFloatv(GL_MODELVIEW_MATRIX, m);
            glFinish();
            fprintf(f, "SC %d %d %d %08x %08x ", i, c, glutStrokeWidth(strokes[i], c),
                    bits(glutStrokeWidthf(strokes[i], c)), bits(m[12]));
            dump(f, W, H);
        }
        fprintf(f, "SL %d %d %08x\n", i,
                glutStrokeLength(strokes[i], (const unsigned char *)STRING),
                bits(glutStrokeLengthf(strokes[i], (const unsigned char *)STRING)));
        glClear(GL_COLOR_BUFFER_BIT);
        glLoadIdentity();
        glTranslatef(4.5f, 40.5f, 0);
        glScalef(SSCALE, SSCALE, 1);
        glutStrokeString(strokes[i], (const unsigned char *)STRING);
        glFinish();
        fprintf(f, "SS %d ", i);
        dump(f, SW, SH);
        glLoadIdentity();
    }
    fclose(f);
    return 0;
}
