/*
 * osmesa_demo.c — a headless OpenGL 1.x program written for Mesa's off-screen API (OSMesa):
 * renders a lit scene (a smooth red sphere, a gold torus, a flat-shaded blue cube on a tiled
 * floor, two lights) into a buffer it owns and writes it as a PPM. No display, no window.
 *
 * It uses nothing but OSMesa and GL 1.1 (no GLU: on a glvnd system libGLU dispatches through
 * libOpenGL.so.0, which does not reach an OSMesa context), so the same binary runs on Mesa's
 * libOSMesa.so.8 (Mesa <= 25.0) and on fixedgl's:
 *
 *   cc -O2 -o osmesa_demo osmesa_demo.c -lOSMesa -lm
 *   ./osmesa_demo out.ppm                    # Mesa's OSMesa
 *   fixedgl run -- ./osmesa_demo out.ppm     # fixedgl
 *
 * Usage: osmesa_demo [OUT.ppm] [--size WxH]   (default osmesa_demo.ppm, 400x300)
 */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static void material(const GLfloat *ambient_diffuse, const GLfloat *specular, GLfloat shininess)
{
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, ambient_diffuse);
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT, GL_SHININESS, shininess);
}

/* A sphere of radius r as quad strips, one normal per vertex. */
static void sphere(float r, int slices, int stacks)
{
    for (int i = 0; i < stacks; i++) {
        float t0 = (float)M_PI * i / stacks - (float)M_PI / 2;
        float t1 = (float)M_PI * (i + 1) / stacks - (float)M_PI / 2;
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= slices; j++) {
            float p = 2 * (float)M_PI * j / slices;
            float x0 = cosf(t0) * cosf(p), y0 = sinf(t0), z0 = cosf(t0) * sinf(p);
            float x1 = cosf(t1) * cosf(p), y1 = sinf(t1), z1 = cosf(t1) * sinf(p);
            glNormal3f(x1, y1, z1);
            glVertex3f(r * x1, r * y1, r * z1);
            glNormal3f(x0, y0, z0);
            glVertex3f(r * x0, r * y0, r * z0);
        }
        glEnd();
    }
}

/* A torus around the y axis: tube radius r, ring radius R. */
static void torus(float r, float R, int sides, int rings)
{
    for (int i = 0; i < rings; i++) {
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= sides; j++) {
            for (int k = 1; k >= 0; k--) {
                float s = 2 * (float)M_PI * (i + k) / rings;
                float t = 2 * (float)M_PI * j / sides;
                float nx = cosf(t) * cosf(s), ny = sinf(t), nz = cosf(t) * sinf(s);
                glNormal3f(nx, ny, nz);
                glVertex3f((R + r * cosf(t)) * cosf(s), r * sinf(t), (R + r * cosf(t)) * sinf(s));
            }
        }
        glEnd();
    }
}

/* A unit cube, one normal per face (flat). */
static void cube(void)
{
    static const GLfloat n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const int f[6][4] = {{1, 5, 7, 3}, {4, 0, 2, 6}, {2, 3, 7, 6}, {4, 5, 1, 0}, {0, 1, 3, 2}, {5, 4, 6, 7}};
    glBegin(GL_QUADS);
    for (int i = 0; i < 6; i++) {
        glNormal3fv(n[i]);
        for (int k = 0; k < 4; k++) {
            int v = f[i][k];
            glVertex3f(v & 1 ? 0.5f : -0.5f, v & 2 ? 0.5f : -0.5f, v & 4 ? -0.5f : 0.5f);
        }
    }
    glEnd();
}

/* The floor: 10 x 10 tiles in two colours, each split into 4 x 4 quads so that the light's
 * falloff shows across it. */
static void floor_tiles(void)
{
    static const GLfloat light[] = {0.75f, 0.75f, 0.7f, 1}, dark[] = {0.3f, 0.35f, 0.3f, 1};
    static const GLfloat none[] = {0, 0, 0, 1};
    glNormal3f(0, 1, 0);
    for (int i = 0; i < 10; i++) {
        for (int j = 0; j < 10; j++) {
            material((i + j) % 2 ? light : dark, none, 0);
            glBegin(GL_QUADS);
            for (int a = 0; a < 4; a++) {
                for (int b = 0; b < 4; b++) {
                    float x0 = -5 + i + a / 4.0f, z0 = -5 + j + b / 4.0f, d = 0.25f;
                    glVertex3f(x0, 0, z0);
                    glVertex3f(x0, 0, z0 + d);
                    glVertex3f(x0 + d, 0, z0 + d);
                    glVertex3f(x0 + d, 0, z0);
                }
            }
            glEnd();
        }
    }
}

static void draw(int w, int h)
{
    static const GLfloat sun_dir[] = {-0.4f, 1.0f, 0.6f, 0.0f};
    static const GLfloat sun[] = {0.8f, 0.8f, 0.75f, 1};
    static const GLfloat lamp_pos[] = {2.0f, 1.5f, 2.0f, 1.0f};
    static const GLfloat lamp[] = {0.9f, 0.6f, 0.3f, 1};
    static const GLfloat ambient[] = {0.15f, 0.15f, 0.18f, 1};
    static const GLfloat red[] = {0.8f, 0.1f, 0.1f, 1}, white[] = {1, 1, 1, 1};
    static const GLfloat gold[] = {0.75f, 0.6f, 0.23f, 1}, gold_spec[] = {0.63f, 0.56f, 0.37f, 1};
    static const GLfloat blue[] = {0.2f, 0.3f, 0.8f, 1}, grey[] = {0.3f, 0.3f, 0.3f, 1};

    glViewport(0, 0, w, h);
    glClearColor(0.1f, 0.12f, 0.18f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_NORMALIZE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    float aspect = (float)w / (float)h;
    glFrustum(-0.5 * aspect, 0.5 * aspect, -0.5, 0.5, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, -1.2f, -7);
    glRotatef(20, 1, 0, 0);
    glRotatef(-25, 0, 1, 0);

    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glLightfv(GL_LIGHT0, GL_POSITION, sun_dir);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, sun);
    glLightfv(GL_LIGHT0, GL_SPECULAR, sun);
    glLightfv(GL_LIGHT1, GL_POSITION, lamp_pos);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, lamp);
    glLightfv(GL_LIGHT1, GL_SPECULAR, lamp);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);

    glShadeModel(GL_SMOOTH);
    floor_tiles();

    glPushMatrix();
    glTranslatef(-1.2f, 1.0f, 0.3f);
    material(red, white, 60);
    sphere(1.0f, 40, 20);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(1.4f, 0.45f, -0.6f);
    glRotatef(30, 1, 0, 0);
    material(gold, gold_spec, 51.2f);
    torus(0.25f, 0.8f, 24, 48);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(0.9f, 0.5f, 1.6f);
    glRotatef(35, 0, 1, 0);
    glShadeModel(GL_FLAT);
    material(blue, grey, 20);
    cube();
    glPopMatrix();

    glFinish();
}

int main(int argc, char **argv)
{
    const char *out = "osmesa_demo.ppm";
    int w = 400, h = 300;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--size") && i + 1 < argc) {
            if (sscanf(argv[++i], "%dx%d", &w, &h) != 2 || w < 1 || h < 1) {
                fprintf(stderr, "osmesa_demo: --size WxH\n");
                return 2;
            }
        } else {
            out = argv[i];
        }
    }

    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx) {
        fprintf(stderr, "osmesa_demo: OSMesaCreateContextExt failed\n");
        return 1;
    }
    unsigned char *buffer = malloc((size_t)w * (size_t)h * 4);
    if (!buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, w, h)) {
        fprintf(stderr, "osmesa_demo: OSMesaMakeCurrent failed\n");
        return 1;
    }
    /* Row 0 of the buffer at the top, as an image file wants it. */
    OSMesaPixelStore(OSMESA_Y_UP, 0);
    printf("GL_RENDERER: %s\nGL_VERSION: %s\n", (const char *)glGetString(GL_RENDERER),
           (const char *)glGetString(GL_VERSION));

    draw(w, h);

    GLint bw = 0, bh = 0;
    OSMesaGetIntegerv(OSMESA_WIDTH, &bw);
    OSMesaGetIntegerv(OSMESA_HEIGHT, &bh);
    if (bw != w || bh != h) {
        fprintf(stderr, "osmesa_demo: the buffer is %dx%d, not %dx%d\n", bw, bh, w, h);
        return 1;
    }
    FILE *f = fopen(out, "wb");
    if (!f) {
        fprintf(stderr, "osmesa_demo: cannot write %s\n", out);
        return 1;
    }
    fprintf(f, "P6\n%d %d\n255\n", w, h);
    for (size_t i = 0; i < (size_t)w * (size_t)h; i++)
        fwrite(buffer + 4 * i, 1, 3, f);
    fclose(f);
    printf("wrote %s (%dx%d)\n", out, w, h);

    OSMesaDestroyContext(ctx);
    free(buffer);
    return 0;
}
