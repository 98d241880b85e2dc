/*
 * gaussian.c — the lecture's JOGL "Rendering" example (Métodos para Rendering de Superfície)
 * as a C/GLUT program: a lit gaussian bump y = e^(-x²)·e^(-z²), one GL_TRIANGLE_STRIP of four
 * vertices per grid cell, seen through gluLookAt + glOrtho, lit by one positional white light.
 * The same scene in Rust is src/scenes/gaussian.rs (fixedgl's `gauss-flat-40`,
 * `gauss-smooth-40`, `gauss-smooth-400`).
 *
 * Keys (the JOGL example switches these in its source; here they are live):
 *   f  FLAT shading: one normal per cell (glShadeModel(GL_FLAT))
 *   s  SMOOTH (Gouraud) shading: one normal per vertex (glShadeModel(GL_SMOOTH))
 *   1  40 x 40 cells      2  400 x 400 cells (the lecture's finer mesh)
 *   q / Esc  quit
 *
 * Options, so that tests and scripts can run it without a person at the keyboard:
 *   --flat | --smooth       the shading to start with (default smooth)
 *   --cells N               N x N cells (default 40)
 *   --size WxH              window size (default 800x800, as the JOGL frame)
 *   --frames N              draw N frames, then stop
 *   --screenshot FILE.ppm   after the last frame, write what GL drew (glReadPixels) as a PPM
 *   --wait                  after the last frame, print "ready" and wait for a line (or end of
 *                           input) on stdin before exiting, so the window can be read back
 *                           from the X server (xwd) first
 *   --print-frames          after each frame, print "frame N WxH" (N counts from 1)
 *
 * Build: cc -O2 -o gaussian gaussian.c -lglut -lGL -lm   (or `make` in this folder)
 * Run on fixedgl: fixedgl run -- ./gaussian
 */
#include <GL/glut.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    float point[3];
    float normal[3];
} Cell;

static int cells = 40;
static GLenum shading = GL_SMOOTH;
static Cell *matrix; /* (cells + 2)^2 points, row i along z, column j along x */
static int matrix_cells = -1;
static int frames_wanted = -1; /* -1: run until quit */
static int frames_drawn = 0;
static const char *screenshot;
static int wait_at_end;
static int print_frames;
static int width = 800, height = 800;

static Cell *at(int i, int j) { return &matrix[i * (cells + 2) + j]; }

/* createMatrix(size): (size+2)^2 points over [-2, 2); the first and last rows and columns only
 * help to compute normals. */
static void create_matrix(void)
{
    int n = cells + 2;
    free(matrix);
    matrix = calloc((size_t)n * (size_t)n, sizeof(Cell));
    if (!matrix) {
        fprintf(stderr, "gaussian: out of memory\n");
        exit(1);
    }
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < n; j++) {
            float x = (4.0f * j) / ((float)cells + 2) - 2.0f;
            float z = (4.0f * i) / ((float)cells + 2) - 2.0f;
            float y = (float)(exp(-x * x) * exp(-z * z));
            Cell *c = at(i, j);
            c->point[0] = x;
            c->point[1] = y;
            c->point[2] = z;
        }
    }
    matrix_cells = cells;
}

static void sub(const float *a, const float *b, float *out)
{
    for (int k = 0; k < 3; k++)
        out[k] = a[k] - b[k];
}

/* calculateNormal: at V1 = m[i][j], with V2 = m[i][j+1] and V3 = m[i+1][j], the normal is
 * normalize((V2 - V1) x (V1 - V3)). On the last row and column the neighbours are taken on the
 * other side with the same orientation (the JOGL code leaves those unset; fixedgl's Rust port
 * makes the same choice). */
static void calculate_normal(void)
{
    int n = cells + 2;
    for (int i = 1; i < n; i++) {
        for (int j = 1; j < n; j++) {
            int j2 = j + 1 < n ? j + 1 : j - 1, flip_x = j + 1 >= n;
            int i3 = i + 1 < n ? i + 1 : i - 1, flip_z = i + 1 >= n;
            float v1[3], v2[3], v3[3], a[3], b[3], p[3];
            memcpy(v1, at(i, j)->point, sizeof v1);
            memcpy(v2, at(i, j2)->point, sizeof v2);
            memcpy(v3, at(i3, j)->point, sizeof v3);
            sub(v2, v1, a);
            sub(v1, v3, b);
            for (int k = 0; k < 3; k++) {
                if (flip_x)
                    a[k] = -a[k];
                if (flip_z)
                    b[k] = -b[k];
            }
            p[0] = a[1] * b[2] - a[2] * b[1];
            p[1] = a[2] * b[0] - a[0] * b[2];
            p[2] = a[0] * b[1] - b[0] * a[1];
            float norm = sqrtf(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            if (norm != 0.0f)
                for (int k = 0; k < 3; k++)
                    p[k] /= norm;
            memcpy(at(i, j)->normal, p, sizeof p);
        }
    }
}

/* lighting: LIGHT0 at (1, 1.5, -0.5), positional, black ambient, white diffuse and specular. */
static void lighting(void)
{
    GLfloat position[] = {1.0f, 1.5f, -0.5f, 1.0f};
    GLfloat white[] = {1.0f, 1.0f, 1.0f, 1.0f};
    GLfloat black[] = {0.0f, 0.0f, 0.0f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glLightfv(GL_LIGHT0, GL_AMBIENT, black);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
}

/* init: white background, depth test, the camera, the projection, the light. */
static void init(void)
{
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(1.5, 0.75, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-2.5, 2.5, -2.5, 2.5, -4.5, 4.5);
    lighting();
}

static void write_ppm(const char *path)
{
    int w = glutGet(GLUT_WINDOW_WIDTH), h = glutGet(GLUT_WINDOW_HEIGHT);
    unsigned char *pixels = malloc((size_t)w * (size_t)h * 3);
    FILE *f = fopen(path, "wb");
    if (!pixels || !f) {
        fprintf(stderr, "gaussian: cannot write %s\n", path);
        exit(1);
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, pixels);
    fprintf(f, "P6\n%d %d\n255\n", w, h);
    for (int row = h - 1; row >= 0; row--) /* GL's bottom row is the image's last */
        fwrite(pixels + (size_t)row * (size_t)w * 3, 1, (size_t)w * 3, f);
    fclose(f);
    free(pixels);
}

static void display(void)
{
    GLfloat diffuse[] = {0.5f, 0.5f, 0.8f, 1.0f};
    GLfloat specular[] = {1.0f, 1.0f, 1.0f, 1.0f};
    GLfloat shininess = 100.0f;

    if (matrix_cells != cells) {
        create_matrix();
        calculate_normal();
    }
    glShadeModel(shading);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT, GL_SHININESS, shininess);

    for (int i = 1; i <= cells; i++) {
        for (int j = 1; j <= cells; j++) {
            Cell *corners[4] = {at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i, j + 1)};
            if (shading == GL_FLAT)
                glNormal3f(at(i, j)->normal[0], at(i, j)->normal[1], at(i, j)->normal[2]);
            glBegin(GL_TRIANGLE_STRIP);
            for (int k = 0; k < 4; k++) {
                if (shading != GL_FLAT)
                    glNormal3f(corners[k]->normal[0], corners[k]->normal[1], corners[k]->normal[2]);
                glVertex3f(corners[k]->point[0], corners[k]->point[1], corners[k]->point[2]);
            }
            glEnd();
        }
    }
    glFlush();

    frames_drawn++;
    int last = frames_wanted >= 0 && frames_drawn >= frames_wanted;
    if (last && screenshot)
        write_ppm(screenshot); /* the back buffer, before the swap leaves it undefined */
    glutSwapBuffers();
    if (print_frames) {
        glFinish();
        printf("frame %d %dx%d\n", frames_drawn, glutGet(GLUT_WINDOW_WIDTH), glutGet(GLUT_WINDOW_HEIGHT));
        fflush(stdout);
    }
    if (last) {
        glFinish();
        if (wait_at_end) {
            char line[16];
            printf("ready\n");
            fflush(stdout);
            if (!fgets(line, sizeof line, stdin)) { /* end of input: go on */
            }
        }
        exit(0);
    }
}

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    switch (key) {
    case 'f': case 'F': shading = GL_FLAT; break;
    case 's': case 'S': shading = GL_SMOOTH; break;
    case '1': cells = 40; break;
    case '2': cells = 400; break;
    case 'q': case 'Q': case 27: exit(0);
    default: return;
    }
    printf("%s shading, %dx%d cells\n", shading == GL_FLAT ? "FLAT" : "SMOOTH", cells, cells);
    glutPostRedisplay();
}

static void idle(void)
{
    if (frames_wanted >= 0)
        glutPostRedisplay();
}

static void usage(void)
{
    fprintf(stderr, "usage: gaussian [--flat|--smooth] [--cells N] [--size WxH] [--frames N] "
                    "[--screenshot FILE.ppm] [--wait] [--print-frames]\n");
    exit(2);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--flat")) shading = GL_FLAT;
        else if (!strcmp(a, "--smooth")) shading = GL_SMOOTH;
        else if (!strcmp(a, "--wait")) wait_at_end = 1;
        else if (!strcmp(a, "--print-frames")) print_frames = 1;
        else if (!strcmp(a, "--cells") && v) { cells = atoi(v); i++; }
        else if (!strcmp(a, "--frames") && v) { frames_wanted = atoi(v); i++; }
        else if (!strcmp(a, "--screenshot") && v) { screenshot = v; i++; }
        else if (!strcmp(a, "--size") && v) {
            if (sscanf(v, "%dx%d", &width, &height) != 2) usage();
            i++;
        } else usage();
    }
    if (cells < 1 || cells > 2000 || width < 1 || height < 1) usage();
    if (screenshot && frames_wanted < 0) frames_wanted = 1;

    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(width, height);
    glutInitWindowPosition(0, 0);
    glutCreateWindow("gaussian");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
