/* Two GLX contexts sharing objects (glXCreateContext's shareList), on two threads: the main
 * thread's context makes a texture and a display list and stays current; a second thread makes
 * the second context (created with the first as shareList) current on the same window, binds
 * the texture, calls the list and reads the picture back with glReadPixels. Written for Mesa;
 * run on fixedgl by capi/tests/share.rs under Xvfb, which compares the two pictures.
 *
 * Usage: share_glx OUT.ppm */
#include <GL/glx.h>
#include <GL/gl.h>
#include <X11/Xlib.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>

#define W 128
#define H 96

static Display *dpy;
static Window win;
static GLXContext a, b;
static GLuint tex, list;
static unsigned char pixels[W * H * 4];
static int failed;

static void *draw_in_b(void *arg)
{
    (void)arg;
    if (!glXMakeCurrent(dpy, win, b)) {
        fprintf(stderr, "cannot make B current\n");
        failed = 1;
        return NULL;
    }
    if (!glIsTexture(tex) || !glIsList(list)) {
        fprintf(stderr, "B does not see A's texture %u or list %u\n", tex, list);
        failed = 1;
    }
    glViewport(0, 0, W, H);
    glClearColor(0.1f, 0.1f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, tex);
    glRotatef(-15, 0, 0, 1);
    glCallList(list);
    glScalef(0.5f, 0.5f, 1);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glListBase(list - 1);
    GLubyte one = 1;
    glCallLists(1, GL_UNSIGNED_BYTE, &one);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    if (glGetError() != GL_NO_ERROR) {
        fprintf(stderr, "GL error in B\n");
        failed = 1;
    }
    glXSwapBuffers(dpy, win);
    glXMakeCurrent(dpy, None, NULL);
    return NULL;
}

int main(int argc, char **argv)
{
    const char *out = argc > 1 ? argv[1] : "share_glx.ppm";
    XInitThreads();
    dpy = XOpenDisplay(NULL);
    if (!dpy) {
        fprintf(stderr, "no display\n");
        return 1;
    }
    int attribs[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 8, GLX_DEPTH_SIZE, 16, None};
    XVisualInfo *vi = glXChooseVisual(dpy, DefaultScreen(dpy), attribs);
    if (!vi) {
        fprintf(stderr, "no visual\n");
        return 1;
    }
    Window root = RootWindow(dpy, vi->screen);
    XSetWindowAttributes swa;
    swa.colormap = XCreateColormap(dpy, root, vi->visual, AllocNone);
    swa.border_pixel = 0;
    swa.event_mask = StructureNotifyMask;
    win = XCreateWindow(dpy, root, 0, 0, W, H, 0, vi->depth, InputOutput, vi->visual,
                        CWColormap | CWBorderPixel | CWEventMask, &swa);
    XStoreName(dpy, win, "share_glx");
    XMapWindow(dpy, win);
    for (;;) {
        XEvent e;
        XNextEvent(dpy, &e);
        if (e.type == MapNotify)
            break;
    }
    a = glXCreateContext(dpy, vi, NULL, True);
    if (!a || !glXMakeCurrent(dpy, win, a)) {
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
            p[0] = on ? 40 : 200;
            p[1] = on ? 200 : 60;
            p[2] = on ? 30 : 90;
            p[3] = 255;
        }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    list = glGenLists(1);
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
    b = glXCreateContext(dpy, vi, a, True);
    if (!b) {
        fprintf(stderr, "no context B\n");
        return 1;
    }

    /* B draws on another thread while A stays current here. */
    pthread_t t;
    pthread_create(&t, NULL, draw_in_b, NULL);
    pthread_join(t, NULL);
    if (failed)
        return 1;

    FILE *f = fopen(out, "wb");
    if (!f)
        return 1;
    fprintf(f, "P6\n%d %d\n255\n", W, H);
    for (int y = H - 1; y >= 0; y--)
        for (int x = 0; x < W; x++)
            fwrite(pixels + (y * W + x) * 4, 1, 3, f);
    fclose(f);
    glXMakeCurrent(dpy, None, NULL);
    glXDestroyContext(dpy, b);
    glXDestroyContext(dpy, a);
    XDestroyWindow(dpy, win);
    XCloseDisplay(dpy);
    return 0;
}
