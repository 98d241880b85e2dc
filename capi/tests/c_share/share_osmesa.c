/* Two OSMesa contexts sharing objects (OSMesaCreateContextExt's sharelist): the first makes a
 * texture and a display list, the second (made with the first as sharelist) binds the texture
 * and calls the list, in its own buffer. Written for Mesa; run on fixedgl by the test
 * capi/tests/share.rs, which compares the two pictures.
 *
 * Usage: share_osmesa OUT.ppm */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 128
#define H 96

int main(int argc, char **argv)
{
    const char *out = argc > 1 ? argv[1] : "share_osmesa.ppm";
    static unsigned char buf1[W * H * 4], buf2[W * H * 4];
    OSMesaContext a = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!a || !OSMesaMakeCurrent(a, buf1, GL_UNSIGNED_BYTE, W, H)) {
        fprintf(stderr, "no context A\n");
        return 1;
    }
    printf("GL_RENDERER: %s\n", (const char *)glGetString(GL_RENDERER));

    /* A: a checkerboard texture and a list drawing a textured quad. */
    unsigned char img[16 * 16 * 4];
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            unsigned char *p = img + (y * 16 + x) * 4;
            int on = ((x / 4) + (y / 4)) & 1;
            p[0] = on ? 230 : 20;
            p[1] = on ? 40 : 90;
            p[2] = on ? 20 : 220;
            p[3] = 255;
        }
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(-0.8f, -0.7f);
    glTexCoord2f(1, 0); glVertex2f(0.7f, -0.8f);
    glTexCoord2f(1, 1); glVertex2f(0.8f, 0.7f);
    glTexCoord2f(0, 1); glVertex2f(-0.7f, 0.8f);
    glEnd();
    glEndList();
    glFinish();

    /* B shares A's objects. */
    OSMesaContext b = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, a);
    if (!b || !OSMesaMakeCurrent(b, buf2, GL_UNSIGNED_BYTE, W, H)) {
        fprintf(stderr, "no context B\n");
        return 1;
    }
    if (!glIsTexture(tex) || !glIsList(list)) {
        fprintf(stderr, "B does not see A's texture %u or list %u\n", tex, list);
        return 1;
    }
    GLint bound = -1;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    if (bound != 0) {
        fprintf(stderr, "B's binding is %d, not its own 0\n", bound);
        return 1;
    }
    glClearColor(0.1f, 0.1f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, tex);
    glRotatef(20, 0, 0, 1);
    glCallList(list);
    glScalef(0.4f, 0.4f, 1);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glCallList(list);
    glFinish();
    if (glGetError() != GL_NO_ERROR) {
        fprintf(stderr, "GL error in B\n");
        return 1;
    }

    /* A deletes the list: B no longer has it. */
    OSMesaMakeCurrent(a, buf1, GL_UNSIGNED_BYTE, W, H);
    glDeleteLists(list, 1);
    OSMesaMakeCurrent(b, buf2, GL_UNSIGNED_BYTE, W, H);
    if (glIsList(list)) {
        fprintf(stderr, "B still sees the list A deleted\n");
        return 1;
    }

    FILE *f = fopen(out, "wb");
    if (!f)
        return 1;
    fprintf(f, "P6\n%d %d\n255\n", W, H);
    for (int y = H - 1; y >= 0; y--)
        for (int x = 0; x < W; x++)
            fwrite(buf2 + (y * W + x) * 4, 1, 3, f);
    fclose(f);
    OSMesaDestroyContext(b);
    OSMesaDestroyContext(a);
    return 0;
}
